"""Parameter studies and validation figures of the gyro bearing (Jiang et al. 2014): the studies run through the sweep
machinery (:func:`hsbearing.workflows.sweeps.run_sweep`), so they live apart from the model
(:mod:`hsbearing.systems.gyro.model`), which the sweeps call.

``python -m hsbearing.workflows.study.gyro [OUT_DIR] [-j N]`` writes the validation tables and figures.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hsbearing.errors import CaseError, SolverError
from hsbearing.systems.gyro.model import (
    GRAVITY,
    override,
    plot_run,
    simulate,
    start_ensemble,
    summary,
)

__all__ = ["study", "validation", "study_figures"]


def study(case, key: str, values, *, duration=None, out_dir=None, jobs: int = 1, **kw):
    """Run ``case`` for each value of one case key (e.g. ``cage.thickness`` or ``pocket_clearance``).

    ``key="pocket_clearance"`` means the seed's A = k - D_w/2 (not a case key) and varies
    ``cage.pocket_depth = D_w/2 + A``.  Returns ``{value: Dataset}`` in the order of ``values``.

    The points go through the sweep machinery (:func:`hsbearing.workflows.sweeps.run_sweep`): ``jobs``
    worker processes (1 = in this process), one archive per point in ``out_dir`` (None: a
    temporary directory, deleted on return) and resume when ``out_dir`` already holds them.  The
    point cases are built exactly as :func:`override` builds them (same TOML text), so a point's
    (chaotic) trajectory is the same as a direct :func:`simulate` of ``override(case, key=value)``.
    Simulation keywords (``**kw``: gravity, settle, ...) cannot be passed through a sweep point;
    with any of them the points run in this process, one after the other.
    A point that fails numerically raises :class:`SolverError` with its partial Dataset.
    """
    import tempfile
    from contextlib import nullcontext

    from hsbearing.results import open_run
    from hsbearing.workflows.sweeps import run_sweep

    values = list(values)
    if key == "pocket_clearance":
        vary_key = "cage.pocket_depth"
        # k written as a short decimal ("0.67 mm", as on the command line and in the case file): a value
        # 1e-16 away would start a different chaotic trajectory
        items = [f"{round((case.bearing.ball_diameter / 2 + float(A)) * 1e3, 9)!r} mm" for A in values]
    else:
        vary_key, items = key, values
    if kw:
        out = {}
        for v, item in zip(values, items):
            out[v] = simulate(override(case, **{vary_key: item}), duration=duration, **kw)
        return out
    with (tempfile.TemporaryDirectory(prefix="gyro-study-") if out_dir is None else nullcontext(out_dir)) as d:
        sw = run_sweep(case, {vary_key: items}, jobs=jobs, out_dir=d, duration=duration, progress=False)
        out = {}
        for v, status, err, arch in zip(values, sw["status"].values, sw["error"].values, sw["archive"].values):
            if status == "invalid":
                raise CaseError(case.source, vary_key, f"value {v!r}: {err}")
            ds = open_run(Path(d) / arch) if arch else None
            if status != "ok":
                raise SolverError(f"gyro study {vary_key} = {v!r}: {status}: {err}", partial=ds)
            out[v] = ds
    return out


def validation(out_dir="docs/figures", *, osc_duration: float = 20.3, study_duration: float = 20.3,
               ensemble: int = 5, gravity_check: bool = True, jobs: int = 1):
    """Recompute the Jiang et al. 2014 comparison (Table 2 cells, s and A studies) and draw docs/figures/gyro_*.png.

    ``python -m hsbearing.workflows.study.gyro [OUT_DIR] [--jobs N]``; prints the Markdown rows used in
    docs/validation/gyro.md.  Takes about half an hour on one core.  The s and A studies run through
    the sweep machinery (:func:`study`) with ``jobs`` worker processes.
    """
    import csv

    from hsbearing.case import load_case

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    base = load_case("jiang2014_gyro")
    ref = {}
    data = Path(__file__).resolve().parents[3] / "tests" / "data" / "jiang2014_friction_moments.csv"
    if data.exists():
        with open(data) as fh:
            for r in csv.DictReader(line for line in fh if not line.startswith("#")):
                ref[(float(r["load_N"]), float(r["speed_r_per_min"]))] = r
    rows = []
    keep = {}
    u = 1e6
    for n in (2, 5):
        for F in (1, 2, 3):
            c = override(base, **{"operating.axial_load": f"{F} N", "operating.outer_speed": f"{n} rpm"})
            d_o = simulate(override(c, **{"operating.mode": "oscillation"}), duration=osc_duration)
            keep[(F, n)] = d_o
            wm = d_o.window_max_moment.values * u
            ens = start_ensemble(c, ensemble) * u if ensemble else np.array([wm[0]])
            r = ref.get((float(F), float(n)), {})
            rows.append((F, n, float(d_o.rfmc) * u, r.get("RFMC_uNm", "?"), wm[0], ens.mean(), ens.std(), r.get("SFMC_uNm", "?"),
                         wm[1:].mean(), wm[1:].std(), wm[1:].size, r.get("SFMO_uNm", "?")))
            print(f"cell {F} N {n} r/min: window maxima {np.round(wm, 2)}; start ensemble {np.round(ens, 2)}; "
                  f"steps {d_o.attrs['solver_steps']}, wall {d_o.attrs['solver_wall_time']:.1f} s", flush=True)
    print("| load [N] | n_o [r/min] | RFMC ours | RFMC paper | SFMC ours (settled start) | SFMC ours, ensemble mean +/- sd "
          "| SFMC paper | SFMO ours, mean +/- sd (windows) | SFMO paper |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print("| {} | {} | {:.2f} | {} | {:.2f} | {:.2f} +/- {:.2f} | {} | {:.2f} +/- {:.2f} ({}) | {} |".format(*r))
    if gravity_check:
        for n in (2, 5):
            c = override(base, **{"operating.outer_speed": f"{n} rpm"})
            d_g = simulate(c, duration=0.3, gravity=GRAVITY)
            d_0 = simulate(c, duration=2.0, settle=False)
            print(f"1 N, {n} r/min: SFMC with cage gravity in the dynamics (0.3 s) = {float(d_g.sfmc)*u:.3f} uN m "
                  f"(steps {d_g.attrs['solver_steps']}); SFMC from an exactly centred cage = {float(d_0.sfmc)*u:.3f} uN m", flush=True)
    plot_run(keep[(1, 5)], out / "gyro_run_1N_5rpm_oscillation.png")
    plot_run(keep[(1, 2)], out / "gyro_run_1N_2rpm_oscillation.png")
    study_figures(out, study_duration=study_duration, jobs=jobs)
    return rows


def study_figures(out_dir="docs/figures", *, study_duration: float = 20.3, jobs: int = 1,
                  which=("thickness", "clearance")):
    """The s and A studies of [J] Figs. 10-11 (oscillation, 1 N, +/-5 and +/-2 r/min) through :func:`study`;
    draws ``gyro_thickness.png`` / ``gyro_clearance.png`` (M histories and SFMO +/- standard error) and
    prints one line per point."""
    from matplotlib.figure import Figure

    from hsbearing.case import load_case
    from hsbearing.plotting import save_figure

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    base = load_case("jiang2014_gyro")
    u = 1e6
    plans = {
        "thickness": ("cage.thickness", ["0.15 mm", "0.20 mm", "0.25 mm", "0.30 mm"], "s", "gyro_thickness.png"),
        "clearance": ("pocket_clearance", [0.01e-3, 0.02e-3, 0.03e-3, 0.04e-3, 0.05e-3], "A", "gyro_clearance.png"),
    }
    for key, values, label, fname in (plans[w] for w in which):
        fig = Figure(figsize=(9, 8), layout="constrained")
        axs = fig.subplots(3, 1)
        curves = {}
        for ax, n in zip(axs[:2], (5, 2)):
            c = override(base, **{"operating.mode": "oscillation", "operating.outer_speed": f"{n} rpm"})
            res = study(c, key, values, duration=study_duration, jobs=jobs)
            xs, ms, ses = [], [], []
            for v, ds in res.items():
                lab = v if isinstance(v, str) else f"{v*1e3:.2f} mm"
                sm = summary(ds)
                ax.plot(ds.time.values, ds.friction_moment_total.values * u, lw=0.6, label=f"{label} = {lab}")
                print(f"study {key} = {lab}, n = {n} r/min: SFMC {sm['sfmc']*u:.2f}, SFMO {sm['sfmo']*u:.2f} "
                      f"+/- {sm['sfmo_stderr']*u:.2f} (standard error, {sm['reversal_windows']} windows) uN m", flush=True)
                xs.append(float(lab.split()[0]))
                ms.append(sm["sfmo"] * u)
                ses.append(sm["sfmo_stderr"] * u)
            curves[n] = (xs, ms, ses)
            ax.set_ylabel(r"M [$\mu$N m]")
            ax.set_title(f"1 N, +/-{n} r/min: total friction moment M (peak-hold)", fontsize=9)
            ax.legend(fontsize=7, ncol=5)
        axs[1].set_xlabel("time [s]")
        for n, (xs, ms, ses) in curves.items():
            axs[2].errorbar(xs, ms, yerr=ses, marker="o", capsize=3, label=f"+/-{n} r/min")
        axs[2].set_xlabel(f"{label} [mm]")
        axs[2].set_ylabel(r"SFMO [$\mu$N m]" + "\n(mean +/- standard error)")
        axs[2].legend(fontsize=8)
        save_figure(fig, out / fname)


if __name__ == "__main__":  # pragma: no cover
    import argparse

    _ap = argparse.ArgumentParser(description="Jiang et al. 2014 validation tables and docs/figures/gyro_*.png")
    _ap.add_argument("out_dir", nargs="?", default="docs/figures")
    _ap.add_argument("-j", "--jobs", type=int, default=1, help="worker processes for the s and A studies")
    _a = _ap.parse_args()
    validation(_a.out_dir, jobs=_a.jobs)
