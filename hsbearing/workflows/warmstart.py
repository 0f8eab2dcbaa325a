"""Warm starts for maps and sweeps (experimental, off by default: docs/sweeps.md "Warm starts").

A point starts from the settled final state (``final_state`` of its archive) of its nearest finished neighbour
instead of the quasi-static state, with a shorter transient rule for the stop rule (:data:`WARM_RULE`).  The
rotational states are scaled by the ratio of the inner-ring speeds when the neighbour ran at another speed (ball
orbit and spin speeds, cage speed, cage-centre velocities); positions and angles are kept.

A warm start may land on another attractor than a cold start (coexisting attractors: a whirl that a cold start
never reaches, or the other way round).  :func:`nearest` picks the neighbour; the agreement with cold starts must be
measured on a sample of points (``tools/investigations/warmstart_agreement.py``) before a map relies on it.
"""

from __future__ import annotations

import numpy as np

__all__ = ["WARM_RULE", "warm_state", "simulate_warm", "nearest", "WarmNearest", "seed_indices"]

#: Stop-rule overrides of a warm-started run: the start is already settled, so the checks discard only the first
#: 10 % of the run (not >= 30 %), the growth fit starts at 0 and the first check is at 0.2 s.  The point minimum
#: (40) and the confirmation stay.
WARM_RULE = {"min_time": 0.2, "transient": 0.1, "growth_t_min": 0.0}

_ROTATIONAL = ("thetadot_b", "omega_x", "omega_y", "omega_z")
_CAGE_ROTATIONAL = ("phidot_c", "ydot_c", "zdot_c")


def warm_state(neighbour, case, model) -> np.ndarray:
    """The start state for ``case`` from the archive Dataset ``neighbour`` (its ``final_state``).

    Velocity states scale with the inner-ring speed ratio (the epicyclic kinematics are linear in it).
    """
    from hsbearing.case import loads_case

    y = np.array(neighbour["final_state"].values, dtype=float)
    names = [str(n) for n in neighbour["state"].values] if "state" in neighbour.coords else None
    if names is not None and names != list(model.state_names):
        raise ValueError("the neighbour's state layout differs from this point's model")
    prev = loads_case(neighbour.attrs["case_toml"], "<neighbour>")
    w0, w1 = prev.operating.inner_speed, case.operating.inner_speed
    if w0 and w1 and w0 != w1:
        k = w1 / w0
        L = model.layout
        for name in _ROTATIONAL:
            y[L.ball(name)] *= k
        for name in _CAGE_ROTATIONAL:
            y[L.cage(name)] *= k
    y[model.layout.cage("phi_c")] = 0.0  # the cage angle is an ordinary state of an autonomous system
    return y


def simulate_warm(case, neighbour, duration=None, *, rule: dict | None = None, **kwargs):
    """A stop-rule run of ``case`` started from ``neighbour``'s final state; annotated with the warm transient."""
    from hsbearing.analysis import annotate
    from hsbearing.systems.angular_contact.dynamics import build_model, simulate

    r = dict(WARM_RULE, **(rule or {}))
    m = build_model(case, initial="nominal")  # the start state comes from the neighbour
    y0 = warm_state(neighbour, case, m)
    ds = simulate(case, duration=duration, model=m, y0=y0, stop="converged", stop_rule=r, annotate=False, **kwargs)
    ds = annotate(ds, case, section=case.simulation.section, transient=r["transient"])
    ds.attrs["warm_start"] = (f"from the final state of {neighbour.attrs.get('case_name', '?')} "
                              f"(inner speed {neighbour.attrs.get('operating_inner_speed', '')}); rule {r}")
    return ds


def seed_indices(n: int) -> list[int]:
    """Seed indices along an axis of ``n`` values: every other one, and the last (every point is next to a seed)."""
    idx = list(range(0, n, 2))
    if idx[-1] != n - 1:
        idx.append(n - 1)
    return idx


def nearest(done: list[tuple], idx: tuple) -> tuple | None:
    """The finished grid index nearest to ``idx`` (max-norm, then Euclidean; ties: the first listed)."""
    if not done:
        return None
    d = [(max(abs(a - b) for a, b in zip(p, idx)), sum((a - b) ** 2 for a, b in zip(p, idx)), k)
         for k, p in enumerate(done)]
    return done[min(d)[2]]


class WarmNearest:
    """Point function of a warm-started map (:func:`hsbearing.workflows.maps.run_map` with ``warm_start=True``).

    ``index``: case TOML -> grid index; ``seeds``: grid index -> archive path of the seed points, which run
    cold; every other point starts from the final state of its nearest seed (cold if that seed has no final
    state).  Module-level and picklable; its name is part of the point hash, so warm and cold archives never alias.
    """

    def __init__(self, index: dict | None = None, seeds: dict | None = None):
        self.index = dict(index or {})
        self.seeds = dict(seeds or {})

    def __call__(self, case, duration):
        import xarray as xr

        from hsbearing.systems import simulate

        idx = self.index.get(case.to_toml())
        if idx is None or idx in self.seeds or not self.seeds:
            return simulate(case, duration=duration)
        src = self.seeds[nearest(sorted(self.seeds), idx)]
        try:
            from hsbearing.results import sigint_held_during_netcdf_io

            with sigint_held_during_netcdf_io(), xr.open_dataset(src) as nb:
                nb = nb[["final_state"]].assign_attrs(nb.attrs).load()
        except (OSError, KeyError, ValueError):
            return simulate(case, duration=duration)  # the seed failed: this point runs cold
        ds = simulate_warm(case, nb, duration)
        ds.attrs["warm_start_from"] = str(src)
        return ds
