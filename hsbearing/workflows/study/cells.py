"""Reading the cells of a study table: our class of a cell, the class fractions of a banded cell over its
samples (:func:`band_cell_stats`), the stability rank of a class, number formatting and the per-point wall
times.  Shared by the reports, the figures and the Table 6 rule."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import xarray as xr

from hsbearing.workflows import sweeps
from hsbearing.workflows.study.spec import normalise_label


def tables_in(study, datasets: dict[str, xr.Dataset]):
    """(table spec, its Dataset, its dim) of every study table that has a Dataset, in the study's order."""
    for t in study.tables:
        ds = datasets.get(t["id"])
        if ds is not None:
            yield t, ds, t["vary"].rpartition(".")[2]


def value_label(ds: xr.Dataset, dim: str, i: int) -> str:
    return str(ds[f"{dim}_label"].values[i])


def fmt(x, spec=".3g") -> str:
    try:
        x = float(x)
    except (TypeError, ValueError):
        return str(x)
    return "-" if not math.isfinite(x) else format(x, spec)


def _ours(pt: xr.Dataset, name: str = "classification") -> str:
    status = pt["status"].item()
    if status != sweeps.STATUS_OK:
        return f"({status})" if name == "classification" else "-"
    if name not in pt:
        return "-"
    return normalise_label(pt[name].item()) or "-"


def _details(pt: xr.Dataset) -> str:
    bits = []
    if "classification_confidence" in pt and np.isfinite(float(pt["classification_confidence"].item())):
        bits.append(f"confidence {float(pt['classification_confidence'].item()):.2f}")
    if "n_poincare_points" in pt and np.isfinite(float(pt["n_poincare_points"].item())):
        bits.append(f"{int(pt['n_poincare_points'].item())} section points")
    return f" ({', '.join(bits)})" if bits else ""


def band_cell_stats(labels, statuses, confidences=None, details=None, paper: str = "") -> dict[str, Any]:
    """Aggregate one cell over the band samples.

    ``labels``/``statuses``/``confidences``/``details``: one entry per sample (the classification, the
    point status, the classifier confidence, the sub-label).  Samples whose status is not ok are left
    out of the fractions (``n_failed``); "undetermined" is an outcome like any class.  Returns
    ``fractions`` {class: fraction of the completed samples}, ``subfractions`` {class: {sub-label:
    fraction}}, ``majority`` (the most frequent class; ties joined with " / "), ``tie``, ``agrees``
    (the paper's class is the majority, alone), ``agrees_tied`` (the paper's class is one of tied
    majorities), ``occurs`` (the paper's class appears in at least one sample), ``confidence`` (mean
    confidence of the samples in the majority class), ``n_ok``, ``n_failed``, ``n``.
    """
    n = len(labels)
    confidences = list(confidences) if confidences is not None else [float("nan")] * n
    details = list(details) if details is not None else [""] * n
    ok = [i for i in range(n) if statuses[i] == sweeps.STATUS_OK]
    counts: dict[str, int] = {}
    sub: dict[str, dict[str, int]] = {}
    for i in ok:
        c = normalise_label(labels[i]) or "-"
        counts[c] = counts.get(c, 0) + 1
        if details[i]:
            sub.setdefault(c, {})
            sub[c][str(details[i])] = sub[c].get(str(details[i]), 0) + 1
    n_ok = len(ok)
    paper = normalise_label(paper) if paper else ""
    if n_ok:
        top = max(counts.values())
        winners = sorted(c for c, k in counts.items() if k == top)
    else:
        winners = []
    maj = " / ".join(winners) if winners else "-"
    conf = [float(confidences[i]) for i in ok if (normalise_label(labels[i]) or "-") in winners
            and confidences[i] is not None and np.isfinite(float(confidences[i]))]
    return {
        "fractions": {c: k / n_ok for c, k in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0]))},
        "subfractions": {c: {d: k / n_ok for d, k in sorted(v.items())} for c, v in sub.items()},
        "majority": maj,
        "tie": len(winners) > 1,
        "agrees": bool(paper) and winners == [paper],
        "agrees_tied": bool(paper) and len(winners) > 1 and paper in winners,
        "occurs": bool(paper) and counts.get(paper, 0) > 0,
        "confidence": float(np.mean(conf)) if conf else float("nan"),
        "n_ok": n_ok,
        "n_failed": n - n_ok,
        "n": n,
    }


def cell_stats(ds: xr.Dataset, dim: str, oil: str, i: int) -> dict:
    pt = ds.sel(oil=oil).isel({dim: i})
    n = pt.sizes["sample"]

    def col(name, default):
        return list(pt[name].values) if name in pt else [default] * n

    paper = str(pt["paper_classification"].values) if "paper_classification" in pt else ""
    return band_cell_stats(col("classification", ""), col("status", ""), col("classification_confidence", np.nan),
                           col("classification_detail", ""), paper=paper) | {"paper": paper}


def band_counts(stats: list[dict]) -> dict[str, int]:
    evaluated = [s for s in stats if s["paper"] and s["n_ok"]]
    return {
        "cells": len([s for s in stats if s["paper"]]),
        "evaluated": len(evaluated),
        "agrees": sum(s["agrees"] for s in evaluated),
        "tied": sum(s["agrees_tied"] for s in evaluated),
        "occurs": sum(s["occurs"] for s in evaluated),
        "undetermined": sum(s["majority"] == "undetermined" for s in evaluated),
    }


def fraction_text(st: dict) -> str:
    bits = []
    for c, f in st["fractions"].items():
        sub = st["subfractions"].get(c)
        extra = f" [{', '.join(f'{d} {g:.2f}' for d, g in sub.items())}]" if sub else ""
        bits.append(f"{c} {f:.2f}{extra}")
    return "; ".join(bits) or "-"


def band_range(cell: xr.Dataset, name: str) -> str:
    """'a .. b' of a summary over the completed samples of a cell (2 decimals), '-' if none."""
    if name not in cell:
        return "-"
    v = np.asarray(cell[name].values, float)
    v = v[(np.asarray(cell["status"].values) == sweeps.STATUS_OK) & np.isfinite(v)]
    if not v.size:
        return "-"
    return f"{v.min():.2f}" if np.isclose(v.min(), v.max(), atol=5e-3) else f"{v.min():.2f} .. {v.max():.2f}"


def section_stats(datasets) -> list[str]:
    n = np.concatenate([np.asarray(ds["n_poincare_points"].values, float).ravel() for ds in datasets.values()
                        if "n_poincare_points" in ds] or [np.array([])])
    n = n[np.isfinite(n)]
    if not n.size:
        return []
    line = (f"- Poincare section points per run: median {np.median(n):.0f} (min {n.min():.0f}, max {n.max():.0f})")
    try:
        from hsbearing.analysis.periods import DEFAULTS

        line += (f"; the classifier needs >= {DEFAULTS['n_min']} for any label and >= {DEFAULTS['n_min_aperiodic']} "
                 "to tell quasi-periodic from chaos (docs/analysis.md)")
    except Exception:
        pass
    return [line]


def point_walls(datasets) -> dict[str, float]:
    """Archive -> recorded wall time [s] of every distinct point of the tables (a point shared by two tables
    counted once; points with no archive or no finite wall time left out)."""
    walls: dict[str, float] = {}
    for ds in datasets.values():
        for a, w in zip(np.asarray(ds["archive"].values).ravel(), np.asarray(ds["wall_time"].values).ravel()):
            if a and a not in walls and np.isfinite(w):
                walls[str(a)] = float(w)
    return walls


def sum_wall(datasets) -> float:
    """Sum of the recorded wall times of the distinct points [s]."""
    return sum(point_walls(datasets).values(), 0.0)


def stability_rank(label: str) -> float:
    """Rank of a class by the paper's criterion "fewer periods ... are beneficial to cage's stability" (Sec. 5):
    k periods -> k (1 period -> 1), quasi-periodic -> 10, chaos -> 11; undetermined / failed -> NaN."""
    c = normalise_label(label)
    if c == "1 period":
        return 1.0
    parts = c.split()
    if len(parts) == 2 and parts[0].isdigit() and parts[1].startswith("period"):
        return float(parts[0])
    return {"quasi-periodic": 10.0, "chaos": 11.0}.get(c, float("nan"))

