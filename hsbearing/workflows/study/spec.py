"""A study's specification and its band samples: the bundled study files, :class:`Study` and
:func:`load_study` (every consistency check, before anything is computed), the ``[bands]`` table and its
Latin-hypercube samples (:func:`band_samples`), and the layout of a study directory."""

from __future__ import annotations

import contextlib
import os
import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

import numpy as np

from hsbearing.case import DIMENSIONS, CaseError, load_case, parse_quantity

# ----------------------------------------------------------------------------- the study directory

#: point archives: ``DIR/runs/<case>-<hash>.nc``
RUNS = "runs"
#: report figures: ``DIR/figures/*.png``
FIGURES = "figures"
#: banded outputs: ``DIR/<table>_bands.nc``, ``DIR/report_bands.md``
BANDS_SUFFIX = "_bands"
#: the status of a point with no archive yet in a report-only rebuild
STATUS_MISSING = "missing"

# ----------------------------------------------------------------------------- the specification


def studies_dir() -> Path:
    return Path(str(resources.files("hsbearing") / "studies"))


def list_studies() -> dict[str, str]:
    """Bundled study names -> title."""
    out = {}
    for p in sorted(studies_dir().glob("*.toml")):
        with contextlib.suppress(tomllib.TOMLDecodeError):
            out[p.stem] = tomllib.loads(p.read_text()).get("study", {}).get("title", "")
    return out


def study_help() -> str:
    """The bundled studies for ``hsbearing study --help``: name, title and measured runtime of each."""
    lines = ["bundled studies:"]
    for p in sorted(studies_dir().glob("*.toml")):
        with contextlib.suppress(tomllib.TOMLDecodeError):
            st = tomllib.loads(p.read_text()).get("study", {})
            lines.append(f"  {p.stem}: {st.get('title', '')}")
            if st.get("runtime"):
                lines.append(f"    runtime: {st['runtime']} (--duration shortens it)")
            if st.get("runtime_bands"):
                lines.append(f"    with --bands: {st['runtime_bands']}")
    return "\n".join(lines)


def normalise_label(label: str) -> str:
    """Paper/analysis period labels to one vocabulary ("Quasi-periodicity" -> "quasi-periodic")."""
    s = str(label).strip().lower()
    if s.startswith("quasi"):
        return "quasi-periodic"
    if s.startswith("chao"):
        return "chaos"
    if s in ("1 period", "one period", "period-1", "periodic", "1 periods"):
        return "1 period"
    parts = s.split()
    if len(parts) == 2 and parts[0].isdigit() and parts[1].startswith("period"):
        return f"{int(parts[0])} period" + ("s" if int(parts[0]) > 1 else "")
    return s


@dataclass
class Study:
    name: str
    source_path: str
    spec: dict

    @property
    def tables(self) -> list[dict]:
        return self.spec.get("table", [])

    @property
    def figures(self) -> list[dict]:
        return self.spec.get("figure", [])

    @property
    def oils(self) -> list[str]:
        return list(self.spec["study"]["oils"])

    @property
    def bands(self) -> dict | None:
        """The ``[bands]`` table (unknown inputs as ranges), or None."""
        return self.spec.get("bands")


def load_study(name_or_path: str | os.PathLike) -> Study:
    """A bundled study by name, or a study TOML file; checked for consistency (CaseError if not)."""
    p = Path(name_or_path)
    if not (p.suffix == ".toml" and p.exists()):
        cand = studies_dir() / f"{name_or_path}.toml"
        if not cand.exists():
            raise CaseError(str(name_or_path), None, f"no such study (bundled: {', '.join(list_studies())})")
        p = cand
    try:
        spec = tomllib.loads(p.read_text())
    except tomllib.TOMLDecodeError as exc:
        raise CaseError(str(p), None, f"malformed TOML: {exc}") from None
    src = str(p)
    if "study" not in spec:
        raise CaseError(src, "study", "missing [study] table")
    for key in ("case", "oils"):
        if key not in spec["study"]:
            raise CaseError(src, f"study.{key}", "missing required key")
    oils = list(spec["study"]["oils"])
    ids = set()
    for i, t in enumerate(spec.get("table", [])):
        where = f"table[{i}]"
        for key in ("id", "vary", "values"):
            if key not in t:
                raise CaseError(src, f"{where}.{key}", "missing required key")
        ids.add(t["id"])
        paper = t.get("paper", {})
        for oil, labels in paper.items():
            if oil not in oils:
                raise CaseError(src, f"{where}.paper.{oil}", f"oil not in study.oils {oils}")
            if len(labels) != len(t["values"]):
                raise CaseError(src, f"{where}.paper.{oil}", f"{len(labels)} labels for {len(t['values'])} values")
    for i, f in enumerate(spec.get("figure", [])):
        for cell in f.get("cells", []):
            tab = next((t for t in spec.get("table", []) if t["id"] == cell[0]), None)
            if tab is None or cell[1] not in oils or cell[2] not in tab["values"]:
                raise CaseError(src, f"figure[{i}].cells", f"unknown cell {cell!r}")
    if "bands" in spec:
        check_bands(spec["bands"], src)
    for oil, row in spec.get("table6", {}).items():
        if oil not in oils:
            raise CaseError(src, f"table6.{oil}", f"oil not in study.oils {oils}")
        for tid in row:
            if tid not in ids:
                raise CaseError(src, f"table6.{oil}.{tid}", f"unknown table (have: {', '.join(sorted(ids))})")
    return Study(spec["study"].get("name", p.stem), src, spec)


BAND_METHODS = ("lhs",)


def check_bands(b: dict, src: str) -> None:
    """The ``[bands]`` table: keys with [low, high] ranges, method, seed, samples, include_nominal."""
    from hsbearing.workflows.sweeps import key_field

    if not isinstance(b, dict):
        raise CaseError(src, "bands", "must be a table")
    known = {"keys", "method", "seed", "samples", "include_nominal"}
    for k in b:
        if k not in known:
            raise CaseError(src, f"bands.{k}", f"unknown key (allowed: {', '.join(sorted(known))})")
    if b.get("method", "lhs") not in BAND_METHODS:
        raise CaseError(src, "bands.method", f"unknown method {b.get('method')!r} (allowed: {', '.join(BAND_METHODS)})")
    seed = b.get("seed")
    if not isinstance(seed, int) or isinstance(seed, bool) or seed < 0:
        raise CaseError(src, "bands.seed", f"must be a non-negative integer (a fixed seed), got {seed!r}")
    n = b.get("samples")
    if not isinstance(n, int) or isinstance(n, bool) or n < 1:
        raise CaseError(src, "bands.samples", f"must be a positive integer, got {n!r}")
    if not isinstance(b.get("include_nominal", True), bool):
        raise CaseError(src, "bands.include_nominal", "must be true or false")
    keys = b.get("keys")
    if not isinstance(keys, dict) or not keys:
        raise CaseError(src, "bands.keys", "missing: a table of case keys, each [low, high]")
    for key, rng in keys.items():
        table, leaf, fld = key_field(key, src)
        full = f"{table}.{leaf}"
        if full != key:
            raise CaseError(src, f"bands.keys.{key}", f"give the full case key ({full})")
        if not (isinstance(rng, list) and len(rng) == 2):
            raise CaseError(src, f"bands.keys.{key}", "must be [low, high]")
        lo, hi = (parse_quantity(v, fld.kind, source=src, key=f"bands.keys.{key}") for v in rng)
        if not lo < hi:
            raise CaseError(src, f"bands.keys.{key}", f"low {rng[0]} is not below high {rng[1]}")


# ----------------------------------------------------------------------------- band samples


@dataclass(frozen=True)
class BandSample:
    """One sample of the band: its index and label, the case overrides (unit strings; none for the nominal
    case) and the SI values of the band keys (for the nominal sample: the case's effective values)."""

    index: int
    label: str
    overrides: dict
    values: dict


def latin_hypercube(n: int, d: int, seed: int) -> np.ndarray:
    """An ``n x d`` Latin-hypercube sample of the unit cube: each column has exactly one point in each
    of the n strata [i/n, (i+1)/n), at a uniform random position inside it (McKay, Beckman & Conover,
    Technometrics 21 (1979) 239-245).  ``numpy.random.default_rng(seed)``: the same seed gives the same
    sample (PCG64 is stable across numpy versions)."""
    rng = np.random.default_rng(seed)
    u = np.empty((n, d))
    for j in range(d):
        u[:, j] = (rng.permutation(n) + rng.random(n)) / n
    return u


#: band values are rounded to this [m] so the overrides (and the archive hashes) are short and exact
BAND_RESOLUTION = 1e-7


_UNIT_OUT = {"length": (1e3, "mm")}


def format_override(kind: str, si: float) -> str:
    """A band value as a case-file string: lengths in mm with 4 decimals (0.1 um), else SI with its unit."""
    if kind in _UNIT_OUT:
        scale, unit = _UNIT_OUT[kind]
        return f"{si * scale:.4f} {unit}"
    unit = DIMENSIONS.get(kind, "")
    return f"{si!r} {unit}".strip()


def effective_value(case, key: str) -> float:
    """The SI value of a band key in a case, including the derived defaults (land width, pocket diameter)."""
    table, _, leaf = key.rpartition(".")
    obj = case
    for part in table.split("."):
        obj = getattr(obj, part)
    v = getattr(obj, leaf, None)
    if v is not None:
        return float(v)
    if key == "cage.guide_land_width":
        from hsbearing.models.geometry import guide_lands

        return float(guide_lands(case).width)
    if key == "cage.pocket_diameter" and case.cage.pocket_clearance is not None:
        return float(case.bearing.ball_diameter + 2 * case.cage.pocket_clearance)
    return float("nan")


def band_samples(study: "Study", case=None) -> list[BandSample]:
    """The band samples of a study: the nominal case first (if ``include_nominal``), then ``samples``
    Latin-hypercube points of the ranges in ``[bands.keys]`` (seed ``[bands] seed``), values rounded to
    0.1 um.  ``case`` (default: the study's base case) gives the nominal values."""
    b = study.bands
    if not b:
        raise CaseError(study.source_path, "bands", "this study defines no [bands] table")
    from hsbearing.workflows.sweeps import key_field

    keys = list(b["keys"])
    kinds = [key_field(k, study.source_path)[2].kind for k in keys]
    ranges = [tuple(parse_quantity(v, kd, source=study.source_path, key=f"bands.keys.{k}") for v in b["keys"][k])
              for k, kd in zip(keys, kinds)]
    base = case if case is not None else load_case(study.spec["study"]["case"])
    out: list[BandSample] = []
    if b.get("include_nominal", True):
        out.append(BandSample(0, "nominal", {}, {k: effective_value(base, k) for k in keys}))
    u = latin_hypercube(int(b["samples"]), len(keys), int(b["seed"]))
    for i, row in enumerate(u):
        vals, ov = {}, {}
        for k, kd, (lo, hi), x in zip(keys, kinds, ranges, row):
            v = round((lo + x * (hi - lo)) / BAND_RESOLUTION) * BAND_RESOLUTION
            ov[k] = format_override(kd, v)
            vals[k] = parse_quantity(ov[k], kd)
        out.append(BandSample(len(out), f"lhs{i + 1}", ov, vals))
    return out


def sample_text(smp: BandSample) -> str:
    return ", ".join(f"{k.rpartition('.')[2]} = {v * 1e3:.4f} mm" for k, v in smp.values.items())

