"""Table 6 of the paper (the recommended working condition per oil) derived from our classes by a stated
rule, :data:`TABLE6_RULE`: the most stable oil at every value of every table."""

from __future__ import annotations

from typing import Any

import numpy as np
import xarray as xr

from hsbearing.workflows import sweeps
from hsbearing.workflows.study.cells import _ours, cell_stats, fmt, stability_rank, tables_in, value_label
from hsbearing.workflows.study.spec import Study

TABLE6_RULE = (
    "For every condition (a value of a table) the most stable oil is the one whose cage class ranks best by the "
    "paper's own criterion (Sec. 5: \"fewer periods of dynamic response ... and smaller slip ratio of cage are "
    "beneficial to cage's stability\"): k periods -> rank k, quasi-periodic -> 10, chaos -> 11, undetermined "
    "not ranked; the class is the majority class over the band (banded study) or the single run's class; ties "
    "are broken by the cage-instability index (sd/mean of the whirl radius, Ghaisas et al. 2004; band mean; "
    "differences below 0.05 do not count), then by the absolute cage slip ratio (band mean; differences below "
    "0.1 percentage point do not count); oils still tied are all recommended. Each table's values are split into a lower half "
    "(low temperature / light load), an upper half (high / heavy) and, for an odd count, the middle value "
    "(medium); an oil is recommended for a category when it is the most stable oil at a value of it.")


def _cell_score(ds: xr.Dataset, dim: str, oil: str, i: int) -> tuple[float, float, float, str]:
    cell = ds.sel(oil=oil).isel({dim: i})
    if "sample" in ds.dims:
        st = cell_stats(ds, dim, oil, i)
        cls = st["majority"] if not st["tie"] else max(st["majority"].split(" / "), key=lambda c: (
            stability_rank(c) if np.isfinite(stability_rank(c)) else 99))  # a tie counts as the worse class
        ok = np.asarray(cell["status"].values) == sweeps.STATUS_OK
    else:
        cls = _ours(cell)
        ok = np.array(cell["status"].item() == sweeps.STATUS_OK)

    def mean(name):
        if name not in cell:
            return float("nan")
        v = np.atleast_1d(np.asarray(cell[name].values, float))[np.atleast_1d(ok)]
        v = v[np.isfinite(v)]
        return float(np.mean(np.abs(v) if name == "mean_cage_slip_ratio" else v)) if v.size else float("nan")

    return stability_rank(cls), mean("cage_instability_index"), mean("mean_cage_slip_ratio"), cls


#: differences below these are not told apart by the Table 6 rule (the index of a steady orbit is noise of
#: ~0.01-0.05; slip ratios within 0.1 percentage point are the same for the paper's Figs. 13-15)
TABLE6_INDEX_TOL = 0.05
TABLE6_SLIP_TOL = 1e-3


def _most_stable(oils: list[str], scores: dict) -> list[str]:
    """Best class rank; then the instability index within TABLE6_INDEX_TOL of the lowest; then the absolute
    slip ratio within TABLE6_SLIP_TOL of the lowest; every oil left is a winner."""
    r0 = min(scores[o][0] for o in oils)
    left = [o for o in oils if scores[o][0] == r0]
    for j, tol in ((1, TABLE6_INDEX_TOL), (2, TABLE6_SLIP_TOL)):
        vals = [scores[o][j] for o in left if np.isfinite(scores[o][j])]
        if vals:
            m = min(vals)
            left = [o for o in left if np.isfinite(scores[o][j]) and scores[o][j] <= m + tol]
    return left


def _categories(t: dict) -> list[str]:
    n = len(t["values"])
    low, high = (("low temperature", "high temperature") if t["vary"].endswith("temperature")
                 else ("light load", "heavy load"))
    mid = "medium temperature" if t["vary"].endswith("temperature") else "medium load"
    half = n // 2
    return [low] * half + ([mid] if n % 2 else []) + [high] * half


def derive_table6(study: Study, datasets: dict[str, xr.Dataset]) -> dict[str, Any]:
    """Our Table 6 by :data:`TABLE6_RULE`: ``{"best": {table: [(value label, [oils], detail)]},
    "table": {oil: {table: "category (values)"}}}``."""
    best: dict[str, list] = {}
    table: dict[str, dict[str, str]] = {o: {} for o in study.oils}
    for t, ds, dim in tables_in(study, datasets):
        cats = _categories(t)
        rows = []
        per_oil: dict[str, dict[str, list[str]]] = {o: {} for o in study.oils}
        for i in range(ds.sizes[dim]):
            scores = {o: _cell_score(ds, dim, o, i) for o in study.oils}
            ranked = [o for o in study.oils if np.isfinite(scores[o][0])]
            if not ranked:
                rows.append((value_label(ds, dim, i), [], "no oil classified"))
                continue

            winners = _most_stable(ranked, scores)
            detail = "; ".join(f"{o}: {scores[o][3]}, index {fmt(scores[o][1], '.2f')}, |slip| "
                               f"{fmt(scores[o][2] * 100, '.2f')} %" for o in study.oils)
            rows.append((value_label(ds, dim, i), winners, detail))
            for o in winners:
                per_oil[o].setdefault(cats[i], []).append(value_label(ds, dim, i))
        best[t["id"]] = rows
        for o in study.oils:
            table[o][t["id"]] = "; ".join(f"{c} ({', '.join(v)})" for c, v in per_oil[o].items()) or "-"
    return {"best": best, "table": table}

