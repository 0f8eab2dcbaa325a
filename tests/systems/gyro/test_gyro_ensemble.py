"""The gyro start ensemble as an output (issue 7 follow-up): ``simulation.start_positions`` = N > 1.

SFMC of one start from rest depends by 30-140 % on where the cage sits in its circumferential play
(docs/validation/gyro.md, "SFMC and SFMO"): a run with N > 1 adds N constant-rate starts with the cage
turned uniformly over -1/2..+1/2 of the play and archives ``sfmc_ensemble`` (dim ``start_offset``),
``sfmc_ensemble_mean`` and ``sfmc_ensemble_sd``.  These are plumbing and consistency tests with short starts
(oscillation_period 0.3 s, N = 3); the ensemble against Table 2 of Jiang et al. 2014 is documented in gyro.md.
"""

import math

import numpy as np
import pytest

import hsbearing
from hsbearing import cli
from hsbearing.case import CaseError
from hsbearing.errors import SolverError
from hsbearing.results import open_run, write_netcdf
from hsbearing.systems.gyro import model as gyro

T = 0.3  # short starts: one "oscillation_period" of 0.3 s each (the impacts of a start are over by then)


def _case(**kw):
    return hsbearing.load_case("jiang2014_gyro", **{"operating.oscillation_period": f"{T} s", **kw})


@pytest.fixture(scope="module")
def plain():
    """The plain default start (start_positions = 1, the default)."""
    return gyro.simulate(_case(), duration=T)


@pytest.fixture(scope="module")
def ens3():
    return gyro.simulate(_case(**{"simulation.start_positions": "3"}), duration=T)


def test_default_has_no_ensemble(plain):
    assert _case().simulation.start_positions == 1
    assert "start_offset" not in plain.dims and "start_offset" not in plain.coords
    assert not [v for v in plain.data_vars if "ensemble" in v]
    assert not [a for a in plain.attrs if a.startswith("start_ensemble")]
    assert "sfmc_ensemble_mean" not in gyro.summary(plain)
    assert gyro.ensemble_lines(plain) == []


def test_explicit_one_is_the_default_bit_for_bit(plain):
    ds = gyro.simulate(_case(**{"simulation.start_positions": "1"}), duration=T)
    assert float(ds["sfmc"]) == float(plain["sfmc"])
    assert np.array_equal(ds["friction_moment_total"].values, plain["friction_moment_total"].values)
    assert set(ds.data_vars) == set(plain.data_vars)


def test_start_offsets():
    assert gyro.start_offsets(1).tolist() == [0.0]
    assert gyro.start_offsets(3).tolist() == [-0.5, 0.0, 0.5]
    assert gyro.start_offsets(5).tolist() == [-0.5, -0.25, 0.0, 0.25, 0.5]  # the offsets of the gyro.md table
    for n in (7, 9, 11, 13, 101):  # odd n: exactly 0.0 in the middle, symmetric, uniform, ends at +/-1/2
        f = gyro.start_offsets(n)
        assert f[n // 2] == 0.0 and f[0] == -0.5 and f[-1] == 0.5
        assert np.allclose(f, -f[::-1], rtol=0, atol=1e-15) and np.allclose(np.diff(f), 1 / (n - 1))
    assert gyro.start_offsets(4).tolist() == pytest.approx([-0.5, -1 / 6, 1 / 6, 0.5])
    with pytest.raises(ValueError):
        gyro.start_offsets(0)


def test_circumferential_play_angle():
    """Play along the orbit sqrt(nabla^2 - (nabla - A)^2) = 0.04 mm for Table 1 (gyro.md, "Ribbon pocket")."""
    c = _case()
    D, Dp, k, dm = c.bearing.ball_diameter, c.cage.pocket_diameter, c.cage.pocket_depth, c.bearing.pitch_diameter
    nabla, A = (Dp - D) / 2, k - D / 2
    play = gyro.circumferential_play_angle(D, Dp, k, dm)
    assert play * dm / 2 == pytest.approx(math.sqrt(nabla**2 - (nabla - A) ** 2), rel=1e-12)
    assert play * dm / 2 == pytest.approx(0.04e-3, rel=1e-9)


def test_ensemble_variables_units_and_statistics(ens3, plain):
    ds = ens3
    assert ds.sizes["start_offset"] == 3
    assert ds["start_offset"].values.tolist() == [-0.5, 0.0, 0.5]
    assert ds["start_offset"].attrs["units"] == "1"
    assert ds["sfmc_ensemble"].dims == ("start_offset",)
    for name in ("sfmc_ensemble", "sfmc_ensemble_mean", "sfmc_ensemble_sd"):
        assert ds[name].attrs["units"] == "N m" and ds[name].attrs["long_name"]
    for name in ("sfmc_ensemble_mean", "sfmc_ensemble_sd"):
        assert ds[name].ndim == 0
    vals = ds["sfmc_ensemble"].values
    assert np.all(np.isfinite(vals)) and np.all(vals > float(ds["rfmc"]))  # every start adds a cage impact to RFMC
    assert float(ds["sfmc_ensemble_mean"]) == pytest.approx(vals.mean(), rel=1e-14)
    assert float(ds["sfmc_ensemble_sd"]) == pytest.approx(np.std(vals, ddof=1), rel=1e-14)
    # the members differ (the start is ill-conditioned: gyro.md measures 30-140 % between offsets)
    assert float(ds["sfmc_ensemble_sd"]) > 0.02 * float(ds["sfmc_ensemble_mean"])
    # offset 0 is the default start, bit for bit: the same as a plain run (start_positions = 1) ...
    assert float(ds["sfmc_ensemble"].sel(start_offset=0.0)) == pytest.approx(float(plain["sfmc"]), rel=1e-12)
    # ... and sfmc keeps meaning the run's own default start, with the same time series as the plain run
    assert float(ds["sfmc"]) == pytest.approx(float(plain["sfmc"]), rel=1e-12)
    assert np.array_equal(ds["friction_moment_total"].values, plain["friction_moment_total"].values)
    c = _case()
    assert ds.attrs["start_ensemble_play_rad"] == pytest.approx(
        gyro.circumferential_play_angle(c.bearing.ball_diameter, c.cage.pocket_diameter, c.cage.pocket_depth,
                                        c.bearing.pitch_diameter), rel=1e-15)
    assert ds.attrs["start_ensemble_duration_s"] == pytest.approx(T)


def test_members_are_start_ensemble(ens3):
    """The archived members are gyro.start_ensemble's values (the function the validation table uses)."""
    vals = gyro.start_ensemble(_case(), 3)
    assert np.allclose(ens3["sfmc_ensemble"].values, vals, rtol=1e-12, atol=0)


def test_oscillation_run_members_are_constant_starts(ens3):
    """For an oscillation run the members are still constant-rate starts of one oscillation_period (brief: "constant
    mode"), equal to those of the constant-mode case; the run's own sfmc is window 0 of the oscillation run."""
    ds = gyro.simulate(_case(**{"simulation.start_positions": "3", "operating.mode": "oscillation"}), duration=2.1 * T)
    assert "sfmo" in ds and ds.sizes["window"] == 2
    assert np.allclose(ds["sfmc_ensemble"].values, ens3["sfmc_ensemble"].values, rtol=1e-12, atol=0)
    assert gyro.summary(ds)["sfmc_ensemble_mean"] == float(ds["sfmc_ensemble_mean"])


def test_archive_round_trip_and_summary(ens3, tmp_path):
    p = write_netcdf(ens3, tmp_path / "ens.nc")
    back = open_run(p)
    for name in ("sfmc", "sfmc_ensemble", "sfmc_ensemble_mean", "sfmc_ensemble_sd", "start_offset"):
        assert np.array_equal(back[name].values, ens3[name].values), name
        assert back[name].attrs["units"] == ens3[name].attrs["units"]
    assert back["sfmc_ensemble"].dims == ("start_offset",)
    assert back.attrs["start_ensemble_play_rad"] == ens3.attrs["start_ensemble_play_rad"]
    s = gyro.summary(back)
    assert s["sfmc_ensemble_mean"] == float(ens3["sfmc_ensemble_mean"])
    assert s["sfmc_ensemble_sd"] == float(ens3["sfmc_ensemble_sd"])
    lines = gyro.ensemble_lines(back)
    assert len(lines) == 4 and "+/-" in lines[0] and "(the default start)" in lines[2]
    assert f"{float(ens3['sfmc_ensemble_mean']) * 1e6:.4g}" in lines[0]


def test_cli_run_prints_the_ensemble(tmp_path, capsys):
    out = tmp_path / "run.nc"
    rc = cli.main(["run", "jiang2014_gyro", "--set", f"operating.oscillation_period={T} s", "--set",
                   "simulation.start_positions=3", "--duration", f"{T}s", "-o", str(out), "--no-plot", "-q"])
    assert rc == 0
    text = capsys.readouterr().out
    assert "sfmc_ensemble_mean:" in text and "sfmc_ensemble_sd:" in text
    assert "start ensemble: SFMC =" in text and "+/-" in text
    assert text.count("start_offset") == 4  # the header and one line per start
    ds = open_run(out)
    assert ds.sizes["start_offset"] == 3


def test_sweep_summary_records_the_ensemble(tmp_path):
    """The sweep summary of a gyro point (gyro.summary via hsbearing.workflows.sweeps) records the ensemble mean and sd."""
    ds = hsbearing.sweep(_case(**{"simulation.start_positions": "3", "operating.oscillation_period": "0.1 s"}),
                         {"cage.thickness": "0.15,0.3mm"}, jobs=1, out_dir=tmp_path, duration=0.1, progress=False)
    assert list(ds["status"].values) == ["ok", "ok"]
    for name in ("sfmc_ensemble_mean", "sfmc_ensemble_sd"):
        assert np.all(np.isfinite(ds[name].values)) and ds[name].attrs["units"] == "N m", name
    run = open_run(tmp_path / str(ds["archive"].values[0]))
    assert float(ds["sfmc_ensemble_mean"].values[0]) == float(run["sfmc_ensemble_mean"])


def test_failed_start_keeps_the_run_and_the_ensemble_so_far(monkeypatch):
    """A start that fails numerically raises SolverError whose partial result holds the run and the starts done
    (NaN for the rest)."""
    real = gyro._simulate_one
    calls = []

    def flaky(case, duration=None, progress=False, **kw):
        calls.append(kw.get("cage_angle", 0.0))
        if len(calls) == 3:  # the main run, offset -0.5, (offset 0 is the main run: reused), then fail at +0.5
            raise SolverError("synthetic failure", partial=None)
        return real(case, duration, progress, **kw)

    monkeypatch.setattr(gyro, "_simulate_one", flaky)
    with pytest.raises(SolverError) as info:
        gyro.simulate(_case(**{"simulation.start_positions": "3", "operating.oscillation_period": "0.05 s"}), duration=0.05)
    part = info.value.partial
    assert "start_offset 0.5" in str(info.value) and "synthetic failure" in part.attrs["status"]
    v = part["sfmc_ensemble"].values
    assert np.isfinite(v[:2]).all() and np.isnan(v[2]) and np.isnan(float(part["sfmc_ensemble_mean"]))
    assert np.isfinite(float(part["sfmc"]))


@pytest.mark.parametrize("bad", ["0", "-2", "2.5", '"three"'])
def test_bad_start_positions_is_a_case_error(bad):
    with pytest.raises(CaseError) as info:
        _case(**{"simulation.start_positions": bad})
    assert info.value.key == "simulation.start_positions"


def test_bad_start_positions_cli_exit_2(tmp_path, capsys):
    out = tmp_path / "x.nc"
    rc = cli.main(["run", "jiang2014_gyro", "--set", "simulation.start_positions=0", "-o", str(out), "--no-plot", "-q"])
    assert rc == 2 and not out.exists()
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "simulation.start_positions" in err[0] and "must be positive" in err[0]


def test_sweep_figure_draws_the_ensemble_with_sd_bars(tmp_path):
    """plot_sweep: the friction panel gets 'SFMC, start ensemble mean' with +/- sd error bars when the summary has
    it (synthetic summary records, nothing computed), and nothing of it when it has not."""
    from hsbearing import plotting
    from hsbearing.workflows import sweeps

    def summ(with_ens):
        out = []
        for i in range(2):
            s = {"sfmc": 7.3e-6 + i * 1e-6, "sfmo": 12e-6, "sfmo_stderr": 1e-6, "rfmc": 2.7e-6}
            if with_ens:
                s.update(sfmc_ensemble_mean=11.4e-6 + i * 1e-6, sfmc_ensemble_sd=5.3e-6)
            out.append(s)
        return out

    plan = sweeps.plan_sweep("jiang2014_gyro", {"cage.thickness": "0.15,0.30mm"}, kind="run", duration=0.1)
    for with_ens in (True, False):
        recs = [{"status": "ok", "error": "", "summary": s, "wall_time": 0.1, "archive": f"p{i}.nc"}
                for i, s in enumerate(summ(with_ens))]
        ds = sweeps.assemble(plan, recs)
        prep = plotting.sweep._prepare_sweep(ds)
        (_title, _, items), = prep["panels"]
        names = [it[0] for it in items]
        if with_ens:
            assert names == ["sfmc", "sfmc_ensemble_mean", "sfmo", "rfmc"]
            assert np.allclose(prep["yerr"]["sfmc_ensemble_mean"], 5.3)  # uN m, the panel's unit
            assert ds["sfmc_ensemble_sd"].attrs["units"] == "N m"
        else:
            assert names == ["sfmc", "sfmo", "rfmc"] and "sfmc_ensemble_mean" not in prep["yerr"]
        png = plotting.plot_sweep(ds, tmp_path / f"s{with_ens}.png")
        assert png.exists() and png.stat().st_size > 10_000


def test_ensemble_follows_duration_and_reuses_the_default_start(monkeypatch):
    """Issue 27: the ensemble ignored --duration (each start ran a whole oscillation_period) and ran the offset-0
    start, which is the run itself for a constant-rate run, a second time."""
    calls = []
    real = gyro._simulate_one

    def counting(case, duration=None, *a, **k):
        calls.append(duration)
        return real(case, duration, *a, **k)

    monkeypatch.setattr(gyro, "_simulate_one", counting)
    ds = gyro.simulate(_case(**{"simulation.start_positions": "3"}), duration=0.1)
    assert calls == [0.1, 0.1, 0.1]  # the run + offsets -1/2 and +1/2; offset 0 is the run itself
    assert ds.attrs["start_ensemble_duration_s"] == pytest.approx(0.1)
    offs = list(ds["start_offset"].values)
    assert float(ds["sfmc_ensemble"].values[offs.index(0.0)]) == float(ds["sfmc"])


def test_gyro_figure_title_shows_the_ensemble(monkeypatch, tmp_path):
    from hsbearing.plotting import common
    from hsbearing.systems.gyro.figures import plot_gyro

    figs = []
    monkeypatch.setattr(common, "save_figure", lambda fig, path, *a, **k: figs.append(fig) or path)
    ds = gyro.simulate(_case(**{"simulation.start_positions": "3"}), duration=0.05)
    plot_gyro(ds, tmp_path / "g.png")
    title = figs[0]._suptitle.get_text().replace("\n", " ")
    assert "SFMC over 3 start positions" in title and "mean +/- sd" in title, title
