"""Lubricant definitions as data: one TOML file per oil.

A lubricant file (format: docs/traction.md, "Lubricant files"; bundled files in
``hsbearing/lubricants/``) gives an oil's name and class, its kinematic (or dynamic) viscosity at two
or more temperatures (Walther / ASTM D341 through them [1]), its density (a value at a stated
temperature with a thermal-expansion coefficient, or two points), its pressure-viscosity coefficient
(a value, ``[T, alpha]`` points, or an estimate from the So & Klaus 1980 correlation [2]), its thermal
conductivity and the traction law it uses (one of the laws registered in
:mod:`hsbearing.models.traction`, named by the registered oil whose laws it borrows).

Every quantity is a string with units, parsed by :func:`hsbearing.case.parse_quantity`; every error is
a :class:`hsbearing.errors.CaseError` naming the lubricant file and the key (the CLI prints it as
``hsbearing: error: FILE: KEY: message`` and exits with code 2).

How a case uses it (``hsbearing.case``): ``lubricant.file = "my_oil.toml"`` (or ``lubricant.oil`` set to
a bundled lubricant name or a ``.toml`` path) replaces the oil.  At the case temperature T the file's
kinematic viscosity nu(T), density rho(T) and alpha(T) fill ``lubricant.kinematic_viscosity``,
``lubricant.density`` and ``lubricant.pressure_viscosity_coefficient`` -- unless the case gives those
keys itself, which then win -- and ``lubricant.oil`` / ``lubricant.traction_law`` name the traction
law.  :func:`hsbearing.models.ehl.lubricant_parameters` (the one entry point of the dynamic model, the
quasi-static solver and the friction models) then sees eta = nu(T) rho(T) and alpha(T).

References
----------
[1] ASTM D341: log10 log10(nu + 0.7) = A - B log10(T), nu in mm^2/s, T in K
    (:mod:`hsbearing.models.viscosity`).
[2] So B.Y.C., Klaus E.E., "Viscosity-pressure correlation of liquids", ASLE Trans. 23(4) (1980)
    409-421: alpha [1e-8 1/Pa] = 1.216 + 4.143 L^3.0627 + 2.848e-4 b^5.1903 L^1.5976
    - 3.999 L^3.0975 rho^0.1162, L = log10(nu [mm^2/s]) at the temperature of interest, rho [g/cm^3]
    at that temperature, b the ASTM D341 slope (B above).  Constants as reproduced in tribology
    texts; the paper itself was not re-read here (docs/traction.md, "Lubricant files").
"""

from __future__ import annotations

import difflib
import math
import tomllib
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path

import numpy as np

from hsbearing.errors import CaseError

__all__ = [
    "LubricantDefinition",
    "ALPHA_ESTIMATES",
    "bundled_lubricants",
    "bundled_path",
    "load_lubricant",
    "loads_lubricant",
    "resolve_lubricant",
    "so_klaus_alpha",
    "describe",
    "oil_name",
    "oil_label",
    "provenance",
    "notices",
    "identity_attrs",
    "name_in_case_text",
    "header_lines",
    "header_lines_of_archive",
    "TEMPLATE",
]

#: Correlations accepted as ``pressure_viscosity_coefficient = "<name>"`` (an estimate, flagged as such).
ALPHA_ESTIMATES = ("so_klaus_1980",)

#: Top-level keys of a lubricant file.
KEYS = ("name", "class", "description", "source", "density", "density_temperature",
        "density_temperature_coefficient", "viscosity", "viscosity_index", "pressure_viscosity_coefficient",
        "thermal_conductivity", "traction", "service_temperature")
#: ``traction.model``: the registered curve fits (oil + law), the physical model, the seed form with user
#: coefficients, a measured mu(S) table (fitted by the seed form).  docs/traction.md, "Lubricant files".
TRACTION_MODELS = ("zhang2016", "eyring", "coefficients", "table")
TRACTION_KEYS_BY_MODEL = {
    "zhang2016": ("model", "oil", "law"),
    "eyring": ("model", "oil", "limiting_shear_coefficient", "eyring_stress", "shear_modulus", "reference_temperature",
               "limiting_shear_temperature_coefficient", "eyring_stress_temperature_coefficient"),
    "coefficients": ("model", "oil", "coefficients", "temperature", "load", "speed"),
    "table": ("model", "oil", "slide_roll_ratio", "mu", "temperature", "load", "speed"),
}
TRACTION_KEYS = tuple(dict.fromkeys(k for keys in TRACTION_KEYS_BY_MODEL.values() for k in keys))
#: A measured table must be followed by its fitted seed form within max(TABLE_FIT_ABS, TABLE_FIT_REL * max mu).
TABLE_FIT_ABS, TABLE_FIT_REL = 0.002, 0.1
#: abs(T_case - T_stated) beyond which ``hsbearing check`` warns that user traction data is used outside its conditions [K].
CONDITIONS_WARN_DT = 10.0

WALTHER_OFFSET = 0.7  # [mm^2/s], ASTM D341 [1]
T40, T100 = 313.15, 373.15


def so_klaus_alpha(nu, rho, b):
    """Pressure-viscosity coefficient from the So & Klaus 1980 correlation [2] [1/Pa].

    Parameters
    ----------
    nu : kinematic viscosity at the temperature of interest [m^2/s] (> 1 mm^2/s)
    rho : density at that temperature [kg/m^3]
    b : ASTM D341 slope B of the oil [-] (:func:`hsbearing.models.viscosity.walther_coefficients`)
    """
    L = math.log10(float(nu) * 1e6)
    if not L > 0.0:
        raise ValueError(f"the So & Klaus correlation needs nu > 1 mm^2/s (got {float(nu) * 1e6:.3g} mm^2/s)")
    r = float(rho) * 1e-3  # g/cm^3
    a = 1.216 + 4.143 * L**3.0627 + 2.848e-4 * b**5.1903 * L**1.5976 - 3.999 * L**3.0975 * r**0.1162  # [2]
    return a * 1e-8


@dataclass(frozen=True)
class LubricantDefinition:
    """A parsed, validated lubricant file (SI)."""

    name: str
    oil_class: str
    path: str  #: file it was read from ("<bundled>/NAME.toml" names a bundled one)
    viscosity_points: tuple  #: ((T [K], value), ...) sorted by T
    viscosity_kind: str  #: "kinematic" [m^2/s] or "dynamic" [Pa s]
    traction_oil: str  #: registered oil whose traction laws the oil uses
    traction_law: str  #: law name (KNOWN_LAWS of traction_oil)
    description: str = ""
    source: str = ""
    density_ref: float | None = None  #: density at density_temperature [kg/m^3]; None: the case's lubricant.density
    density_temperature: float = 288.15  #: [K]
    density_coefficient: float | None = None  #: rho = rho_ref (1 - k (T - T_ref)) [1/K]; None: constant
    alpha_value: float | None = None  #: given pressure-viscosity coefficient [1/Pa]
    alpha_points: tuple | None = None  #: ((T [K], alpha [1/Pa]), ...), linear in T, held at the ends
    alpha_estimate: str | None = None  #: name of the correlation (ALPHA_ESTIMATES) when estimated
    conductivity: float | None = None  #: thermal conductivity [W/(m K)]
    traction_model: str = "zhang2016"  #: one of TRACTION_MODELS
    eyring: object = None  #: models.traction.eyring.EyringParameters (model "eyring")
    coefficients: tuple | None = None  #: (A, B, C, D), S a fraction (models "coefficients" and "table")
    traction_table: tuple | None = None  #: ((S...), (mu...)) as given (model "table")
    traction_conditions: dict | None = None  #: stated conditions {"T": K, "W": N, "U": m/s} (None entries: not stated)
    table_fit_deviation: float | None = None  #: largest |fit - table| [-] (model "table")
    viscosity_index: float | None = None  #: VI as stated by the source (reported, not used)
    service_range: tuple | None = None  #: (T_low, T_high) [K] the source states the oil for (envelope warning)
    traction_recommended: bool = False  #: no [traction] table: models.traction.RECOMMENDED_LAW with its defaults
    text: str = field(default="", repr=False)  #: the file's TOML text

    @property
    def alpha_estimated(self) -> bool:
        return self.alpha_estimate is not None

    def density(self, T, fallback=None) -> float:
        """rho(T) [kg/m^3]; the file's, or ``fallback`` (the case's lubricant.density) when it gives none."""
        if self.density_ref is None:
            if fallback is None:
                raise ValueError(f"lubricant {self.name!r} gives no density and no fallback was given")
            return float(fallback)
        k = self.density_coefficient or 0.0
        return float(self.density_ref * (1.0 - k * (float(T) - self.density_temperature)))

    def walther(self, fallback_density=None) -> tuple[float, float]:
        """ASTM D341 coefficients (A, B) through the viscosity points (least squares beyond two) [1]."""
        T = np.array([p[0] for p in self.viscosity_points])
        v = np.array([p[1] for p in self.viscosity_points])
        if self.viscosity_kind == "dynamic":
            v = v / np.array([self.density(t, fallback_density) for t in T])
        z = np.log10(np.log10(v * 1e6 + WALTHER_OFFSET))
        x = np.log10(T)
        if len(T) == 2:  # exact through two points (as models.viscosity.walther_coefficients)
            B = (z[0] - z[1]) / (x[1] - x[0])
            A = z[0] + B * x[0]
        else:
            slope, A = np.polyfit(x, z, 1)
            B = -slope
        return float(A), float(B)

    def kinematic_viscosity(self, T, fallback_density=None):
        """nu(T) [m^2/s] (vectorised in T)."""
        A, B = self.walther(fallback_density)
        z = A - B * np.log10(np.asarray(T, dtype=float))
        return (10.0 ** (10.0**z) - WALTHER_OFFSET) * 1e-6

    def dynamic_viscosity(self, T, fallback_density=None) -> float:
        """eta(T) = nu(T) rho(T) [Pa s]."""
        return float(self.kinematic_viscosity(T, fallback_density)) * self.density(T, fallback_density)

    def alpha(self, T, fallback_density=None) -> float:
        """Pressure-viscosity coefficient at T [1/Pa] (given, interpolated, or estimated [2])."""
        if self.alpha_value is not None:
            return float(self.alpha_value)
        if self.alpha_points is not None:
            Ts = [p[0] for p in self.alpha_points]
            return float(np.interp(float(T), Ts, [p[1] for p in self.alpha_points]))
        _, B = self.walther(fallback_density)
        return so_klaus_alpha(self.kinematic_viscosity(T, fallback_density), self.density(T, fallback_density), B)

    def at(self, T, fallback_density=None) -> dict:
        """Derived values at T: nu, rho, eta, alpha (and whether alpha is estimated)."""
        nu = float(self.kinematic_viscosity(T, fallback_density))
        rho = self.density(T, fallback_density)
        return {"T": float(T), "nu": nu, "rho": rho, "eta": nu * rho, "alpha": self.alpha(T, fallback_density),
                "alpha_estimated": self.alpha_estimated, "K": self.conductivity}


# ----------------------------------------------------------------------------
# bundled library


def _bundled_dir() -> Path:
    return Path(str(resources.files("hsbearing") / "lubricants"))


def bundled_lubricants() -> dict[str, Path]:
    """Bundled lubricant names -> file paths (``hsbearing/lubricants/*.toml``)."""
    return {p.stem: p for p in sorted(_bundled_dir().glob("*.toml"))}


def bundled_path(name: str) -> Path | None:
    return bundled_lubricants().get(str(name))


def resolve_lubricant(spec: str, *, base_dir: str | Path | None = None) -> Path | None:
    """A lubricant file path from ``spec``: a path (relative to ``base_dir``, the case file's directory,
    then to the working directory) or a bundled name; None if neither exists."""
    spec = str(spec).strip()
    if not spec:
        return None
    p = Path(spec).expanduser()
    cands = []
    if not p.is_absolute() and base_dir is not None:
        cands.append(Path(base_dir) / p)
    cands.append(p)
    for c in cands:
        if c.is_file():
            return c
    if p.suffix != ".toml" and "/" not in spec and "\\" not in spec:
        return bundled_path(spec)
    return None


def unresolved_message(spec: str) -> str:
    names = list(bundled_lubricants())
    close = difflib.get_close_matches(str(spec), names, n=1)
    hint = f"; did you mean {close[0]!r}?" if close else ""
    return (f"no such lubricant file or bundled lubricant {str(spec)!r}{hint} "
            f"(bundled: {', '.join(names)}; a file path is read relative to the case file, then the working directory)")


# ----------------------------------------------------------------------------
# parsing


def load_lubricant(path: str | Path) -> LubricantDefinition:
    """Read and validate a lubricant file; :class:`CaseError` naming the file and the key."""
    path = Path(path)
    src = str(path)
    if path.is_dir():
        raise CaseError(src, None, "is a directory, not a lubricant file")
    try:
        text = path.read_bytes().decode("utf-8")
    except UnicodeDecodeError as exc:
        raise CaseError(src, None, f"not a UTF-8 text file (byte {exc.start}); lubricant files are TOML") from None
    except OSError as exc:
        raise CaseError(src, None, f"cannot read the lubricant file ({exc.strerror or type(exc).__name__})") from None
    return loads_lubricant(text, src, default_name=path.stem)


def _q(value, kind, src, key, *, positive=True):
    from hsbearing.units import parse_quantity

    x = parse_quantity(value, kind, source=src, key=key)
    if positive and not x > 0:
        raise CaseError(src, key, f"must be positive, got {value!r}")
    return x


def _pair(item, src, key, kinds):
    """``["40 degC", "27.6 mm^2/s"]`` -> (T [K], value SI, kind) with kind the first of ``kinds`` that parses."""
    if not (isinstance(item, list) and len(item) == 2):
        raise CaseError(src, key, f"expected a [temperature, value] pair like [\"40 degC\", \"27.6 mm^2/s\"], got {item!r}")
    T = _q(item[0], "temperature", src, key)
    last = None
    for kind in kinds:
        try:
            return T, _q(item[1], kind, src, key), kind
        except CaseError as exc:
            last = exc
            if "must be positive" in exc.message or "absurd" in exc.message:
                raise
    if len(kinds) > 1:
        want = " or ".join(_KIND_WORDS.get(k, k) for k in kinds)
        raise CaseError(src, key, f"{item[1]!r} is not {want}")
    raise last


_KIND_WORDS = {"kinematic_viscosity": "a kinematic viscosity (mm^2/s)", "dynamic_viscosity": "a dynamic viscosity (Pa*s)",
               "pressure_coefficient": "a pressure-viscosity coefficient (1/Pa)"}


def loads_lubricant(text: str, source: str = "<lubricant>", *, default_name: str = "") -> LubricantDefinition:
    """Parse a lubricant file's TOML text (see :func:`load_lubricant`)."""
    from hsbearing.models import traction

    src = source
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise CaseError(src, None, f"malformed TOML: {exc}") from None
    for key in raw:
        if key not in KEYS:
            close = difflib.get_close_matches(key, KEYS, n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            raise CaseError(src, key, f"unknown key{hint} (known: {', '.join(KEYS)})")

    def text_key(key, default=""):
        v = raw.get(key, default)
        if not isinstance(v, str):
            raise CaseError(src, key, f"expected a string, got {v!r}")
        return v

    name = text_key("name", default_name) or default_name
    if not name:
        raise CaseError(src, "name", "missing required key (the oil's name)")
    oil_class = text_key("class")

    # --- viscosity: two or more [T, nu] (or [T, eta]) points, all of one kind
    if "viscosity" not in raw:
        raise CaseError(src, "viscosity", 'missing required key: two or more [temperature, viscosity] points, '
                                          'e.g. viscosity = [["40 degC", "27.6 mm^2/s"], ["100 degC", "5.1 mm^2/s"]]')
    pts = raw["viscosity"]
    if not isinstance(pts, list) or len(pts) < 2:
        raise CaseError(src, "viscosity", f"expected two or more [temperature, viscosity] points, got {pts!r}")
    parsed = [_pair(item, src, f"viscosity[{i}]", ("kinematic_viscosity", "dynamic_viscosity")) for i, item in enumerate(pts)]
    kinds = {p[2] for p in parsed}
    if len(kinds) > 1:
        raise CaseError(src, "viscosity", "mixes kinematic (mm^2/s) and dynamic (Pa*s) viscosities: give one kind")
    parsed.sort(key=lambda p: p[0])
    Ts = [p[0] for p in parsed]
    if len(set(Ts)) != len(Ts):
        raise CaseError(src, "viscosity", "two points at the same temperature")
    vals = [p[1] for p in parsed]
    if any(b >= a for a, b in zip(vals, vals[1:])):
        raise CaseError(src, "viscosity", "viscosity must fall as the temperature rises (ASTM D341 needs it)")
    vkind = kinds.pop().replace("_viscosity", "")

    # --- density
    density_ref, density_T, density_k = None, 288.15, None
    if "density" in raw:
        d = raw["density"]
        if isinstance(d, list):
            if "density_temperature" in raw or "density_temperature_coefficient" in raw:
                raise CaseError(src, "density", "give either density points or density with density_temperature(_coefficient), not both")
            if len(d) != 2:
                raise CaseError(src, "density", f"expected two [temperature, density] points, got {d!r}")
            (T1, r1, _), (T2, r2, _) = (_pair(item, src, f"density[{i}]", ("density",)) for i, item in enumerate(d))
            if T1 == T2:
                raise CaseError(src, "density", "two points at the same temperature")
            density_ref, density_T = r1, T1
            density_k = -(r2 - r1) / (r1 * (T2 - T1))
        else:
            density_ref = _q(d, "density", src, "density")
            if "density_temperature" in raw:
                density_T = _q(raw["density_temperature"], "temperature", src, "density_temperature")
            if "density_temperature_coefficient" in raw:
                density_k = _q(raw["density_temperature_coefficient"], "temperature_coefficient", src,
                               "density_temperature_coefficient", positive=False)
                if not 0.0 <= density_k < 5e-3:
                    raise CaseError(src, "density_temperature_coefficient",
                                    f"expected 0 to 5e-3 1/K (oils: about 6e-4 to 8e-4 1/K), got {raw['density_temperature_coefficient']!r}")
        if not 300.0 <= density_ref <= 2500.0:
            raise CaseError(src, "density", f"{density_ref:g} kg/m^3 is not the density of a lubricant (300-2500 kg/m^3)")
    elif "density_temperature" in raw or "density_temperature_coefficient" in raw:
        raise CaseError(src, "density", "missing: density_temperature / density_temperature_coefficient need a density")

    # --- pressure-viscosity coefficient
    alpha_value = alpha_points = alpha_estimate = None
    key = "pressure_viscosity_coefficient"
    # a data sheet rarely gives alpha: absent, it is estimated by the first correlation (flagged as estimated,
    # a notice wherever the oil is used)
    a = raw.get(key, ALPHA_ESTIMATES[0])
    if isinstance(a, list):
        if not a:
            raise CaseError(src, key, "empty list")
        ap = sorted((_pair(item, src, f"{key}[{i}]", ("pressure_coefficient",))[:2] for i, item in enumerate(a)))
        if len({p[0] for p in ap}) != len(ap):
            raise CaseError(src, key, "two points at the same temperature")
        alpha_points = tuple(ap)
    elif isinstance(a, str) and a.strip() in ALPHA_ESTIMATES:
        alpha_estimate = a.strip()
    elif isinstance(a, str) and a.strip() and a.strip()[0].isalpha():
        close = difflib.get_close_matches(a.strip(), ALPHA_ESTIMATES, n=1)
        hint = f"; did you mean {close[0]!r}?" if close else ""
        raise CaseError(src, key, f"unknown correlation {a!r}{hint} (known: {', '.join(ALPHA_ESTIMATES)}), "
                                  "or give a value with units such as \"1.8e-8 1/Pa\"")
    else:
        alpha_value = _q(a, "pressure_coefficient", src, key)
    for v in ([alpha_value] if alpha_value is not None else []) + [p[1] for p in (alpha_points or ())]:
        if not 1e-9 <= v <= 1e-7:
            raise CaseError(src, key, f"{v:.3g} 1/Pa is outside 1e-9 to 1e-7 1/Pa (1 to 100 GPa^-1), the range of oils")

    # --- thermal conductivity, VI
    K = None
    if "thermal_conductivity" in raw:
        K = _q(raw["thermal_conductivity"], "thermal_conductivity", src, "thermal_conductivity")
        if not 0.01 <= K <= 1.0:
            raise CaseError(src, "thermal_conductivity", f"{K:g} W/(m K) is not an oil's (0.01-1 W/(m K); oils about 0.1-0.15)")
    service = None
    if "service_temperature" in raw:  # [low, high]: the range the source states the oil for (warned beyond it)
        st = raw["service_temperature"]
        if not isinstance(st, list) or len(st) != 2:
            raise CaseError(src, "service_temperature", f'expected ["LOW degC", "HIGH degC"], got {st!r}')
        lo_t, hi_t = (_q(v, "temperature", src, f"service_temperature[{i}]") for i, v in enumerate(st))
        if not lo_t < hi_t:
            raise CaseError(src, "service_temperature", "the low end must be below the high end")
        service = (lo_t, hi_t)
    vi = raw.get("viscosity_index")
    if vi is not None and (isinstance(vi, bool) or not isinstance(vi, (int, float))):
        raise CaseError(src, "viscosity_index", f"expected a plain number, got {vi!r}")

    # --- traction
    tr = raw.get("traction")
    recommended = tr is None
    if recommended:  # data-sheet values only: the recommended law, fed by the oil's own viscosity and alpha
        tr = {"model": traction.RECOMMENDED_LAW}
    if not isinstance(tr, dict):
        raise CaseError(src, "traction", f"expected a table [traction], got {tr!r}")
    model = tr.get("model", "zhang2016")
    if model not in TRACTION_MODELS:
        close = difflib.get_close_matches(str(model), TRACTION_MODELS, n=1)
        hint = f"; did you mean {close[0]!r}?" if close else ""
        raise CaseError(src, "traction.model", f"unknown traction model {model!r}{hint} (known: {', '.join(TRACTION_MODELS)})")
    allowed = TRACTION_KEYS_BY_MODEL[model]
    for k in tr:
        if k not in allowed:
            close = difflib.get_close_matches(k, allowed, n=1)
            hint = f"; did you mean 'traction.{close[0]}'?" if close else ""
            other = [m for m, keys in TRACTION_KEYS_BY_MODEL.items() if k in keys]
            why = f" (a key of model {' / '.join(other)})" if other else ""
            raise CaseError(src, f"traction.{k}", f"not a key of traction model {model!r}{why}{hint} "
                                                  f"(known: {', '.join(allowed)})")
    toil = tr.get("oil")
    if toil is None and model == "zhang2016":
        raise CaseError(src, "traction.oil", f"missing required key (one of {', '.join(traction.OILS)}: the registered "
                                             "oil whose traction laws this oil uses; or traction.model = \"eyring\", "
                                             "the physical model)")
    toil = str(toil) if toil is not None else "4109"
    if toil not in traction.OILS:
        raise CaseError(src, "traction.oil", f"unknown registered oil {toil!r} (known: {', '.join(traction.OILS)})")
    law = tr.get("law", "default")
    eyring_params = coefficients = table = conditions = None
    fit_dev = None
    if model == "zhang2016":
        seed = [x for x in traction.KNOWN_LAWS[toil] if traction.is_seed_law(x)]
        if not isinstance(law, str) or law not in seed:
            raise CaseError(src, "traction.law", f"unknown traction law {law!r} for oil {toil} (known: {', '.join(seed)}; "
                                                 "the physical model is traction.model = \"eyring\")")
    elif model == "eyring":
        law = traction.EYRING_LAW
        eyring_params = _eyring_parameters(tr, src)
    else:
        law = traction.USER_LAW
        conditions = _traction_conditions(tr, src, model)
        if model == "coefficients":
            coefficients = _user_coefficients(tr, src)
        else:
            table, coefficients, fit_dev = _traction_table(tr, src)

    d = LubricantDefinition(
        name=name, oil_class=oil_class, path=source, viscosity_points=tuple((T, v) for T, v, _ in parsed),
        viscosity_kind=vkind, traction_oil=toil, traction_law=law, description=text_key("description"),
        source=text_key("source"), density_ref=density_ref, density_temperature=density_T,
        density_coefficient=density_k, alpha_value=alpha_value, alpha_points=alpha_points,
        alpha_estimate=alpha_estimate, conductivity=K, viscosity_index=None if vi is None else float(vi), text=text,
        traction_model=model, eyring=eyring_params, coefficients=coefficients, traction_table=table,
        traction_conditions=conditions, table_fit_deviation=fit_dev, service_range=service,
        traction_recommended=recommended,
    )
    # a Walther line must come out of the points (falling viscosity, finite coefficients)
    try:
        A, B = d.walther(fallback_density=density_ref or 900.0)
    except (FloatingPointError, ValueError):
        A = B = float("nan")
    if not (math.isfinite(A) and math.isfinite(B) and B > 0):
        raise CaseError(src, "viscosity", "no ASTM D341 (Walther) line through these points")
    return d


def _number(v, src, key):
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise CaseError(src, key, f"expected a plain number, got {v!r}")
    return float(v)


def _eyring_parameters(tr, src):
    """traction.model = "eyring": the rheological constants (defaults: models.traction.eyring)."""
    from hsbearing.models.traction import eyring

    kw = {}
    # key, field, kind, plausible range (SI), how the range reads, what oils have
    for key, field_, kind, lo, hi, scale, unit, typical in (
            ("limiting_shear_coefficient", "Lambda", None, 0.01, 0.15, 1.0, "", "measured tau_L/p of oils: 0.035-0.088"),
            ("eyring_stress", "tau0", "pressure", 0.1e6, 100e6, 1e-6, " MPa", "Eyring stresses of EHL oils: about 2-20 MPa"),
            ("shear_modulus", "G", "pressure", 1e6, 1e11, 1e-6, " MPa", "EHL films: about 0.1-1 GPa")):
        if key in tr:
            name = f"traction.{key}"
            v = _number(tr[key], src, name) if kind is None else _q(tr[key], kind, src, name)
            if not lo <= v <= hi:
                raise CaseError(src, name, f"{v * scale:g}{unit} is outside {lo * scale:g}-{hi * scale:g}{unit} ({typical})")
            kw[field_] = v
    if "reference_temperature" in tr:
        kw["T_ref"] = _q(tr["reference_temperature"], "temperature", src, "traction.reference_temperature")
    for key, field_ in (("limiting_shear_temperature_coefficient", "k_Lambda"),
                        ("eyring_stress_temperature_coefficient", "k_tau0")):
        if key in tr:
            k = _q(tr[key], "temperature_coefficient", src, f"traction.{key}", positive=False)
            if not abs(k) <= 0.02:
                raise CaseError(src, f"traction.{key}", f"{k:g} 1/K is outside -0.02 to 0.02 1/K")
            kw[field_] = k
    if "eyring_stress_temperature_coefficient" in tr and "eyring_stress" not in tr:
        raise CaseError(src, "traction.eyring_stress_temperature_coefficient",
                        "needs traction.eyring_stress (without it tau_0 = 2 Lambda / alpha follows alpha(T))")
    return eyring.EyringParameters(**kw)


def _traction_conditions(tr, src, model):
    """Stated conditions of user traction data: temperature (required), load and speed (optional, reported)."""
    if "temperature" not in tr:
        raise CaseError(src, "traction.temperature", f"missing required key: the temperature at which the {model} "
                                                     "were measured or fitted (e.g. \"80 degC\")")
    out = {"T": _q(tr["temperature"], "temperature", src, "traction.temperature"), "W": None, "U": None}
    if "load" in tr:
        out["W"] = _q(tr["load"], "force", src, "traction.load")
    if "speed" in tr:
        out["U"] = _q(tr["speed"], "velocity", src, "traction.speed")
    return out


def _check_curve(A, B, C, D, src, key):
    """A user curve must be a traction curve: bounded, 0 <= mu < 0.5 for 0 < S <= 1."""
    from hsbearing.models.traction import zhang2016

    S = np.logspace(-5, 0, 200)
    mu = zhang2016.traction_coefficient(A, B, C, D, S)
    if not np.all(np.isfinite(mu)) or mu.min() < -1e-3 or mu.max() >= 0.5:
        raise CaseError(src, key, f"mu = (A + B S) exp(-C S) + D with these values is not a traction curve: it reaches "
                                  f"{mu.min():.3g} to {mu.max():.3g} for S in 1e-5..1 (S a fraction; expected 0 to 0.5)")


def _user_coefficients(tr, src):
    key = "traction.coefficients"
    if "coefficients" not in tr:
        raise CaseError(src, key, "missing required key: [A, B, C, D] of mu = (A + B S) exp(-C S) + D, S a fraction")
    c = tr["coefficients"]
    if not (isinstance(c, list) and len(c) == 4):
        raise CaseError(src, key, f"expected [A, B, C, D] (four numbers), got {c!r}")
    A, B, C, D = (_number(v, src, key) for v in c)
    if not C > 0.0:
        raise CaseError(src, key, f"C must be positive (mu grows without bound otherwise), got {C:g}")
    _check_curve(A, B, C, D, src, key)
    return (A, B, C, D)


def fit_seed_form(S, mu):
    """Least-squares (B, C, D) of mu = D (1 - e^(-C S)) + B S e^(-C S) (the seed form with A = -D: mu(0) = 0)
    through a measured table; returns ((A, B, C, D), largest |fit - mu|)."""
    from scipy.optimize import least_squares

    S, mu = np.asarray(S, dtype=float), np.asarray(mu, dtype=float)

    def f(x):
        B, lC, D = x
        e = np.exp(-np.exp(lC) * S)
        return D * (1.0 - e) + B * S * e - mu

    best = None
    for S_half in S:  # starts: the knee at each tabulated slip
        x0 = (0.0, math.log(math.log(2.0) / S_half), float(mu.max()))
        r = least_squares(f, x0, method="lm", max_nfev=2000)
        if best is None or r.cost < best.cost:
            best = r
    B, lC, D = best.x
    return (-D, B, math.exp(lC), D), float(np.max(np.abs(f(best.x))))


def _traction_table(tr, src):
    for k in ("slide_roll_ratio", "mu"):
        if k not in tr:
            raise CaseError(src, f"traction.{k}", "missing required key: a measured table gives slide_roll_ratio "
                                                  "(fractions, increasing) and mu (same length, at least 4 points)")
    S = tr["slide_roll_ratio"]
    mu = tr["mu"]
    if not isinstance(S, list) or len(S) < 4:
        raise CaseError(src, "traction.slide_roll_ratio", f"expected a list of at least 4 slide-roll ratios, got {S!r}")
    if not isinstance(mu, list) or len(mu) != len(S):
        raise CaseError(src, "traction.mu", f"expected a list of {len(S)} traction coefficients (one per slide_roll_ratio)")
    S = [_number(v, src, "traction.slide_roll_ratio") for v in S]
    mu = [_number(v, src, "traction.mu") for v in mu]
    if not (S[0] > 0 and all(b > a for a, b in zip(S, S[1:])) and S[-1] <= 1.0):
        raise CaseError(src, "traction.slide_roll_ratio", "must increase strictly within (0, 1] (fractions, not percent)")
    if not all(0.0 <= m < 0.5 for m in mu):
        raise CaseError(src, "traction.mu", "traction coefficients must lie in 0 to 0.5")
    coefs, dev = fit_seed_form(S, mu)
    tol = max(TABLE_FIT_ABS, TABLE_FIT_REL * max(mu))
    if not dev <= tol:
        raise CaseError(src, "traction.mu", f"the seed form (A + B S) exp(-C S) + D with A = -D follows this table only "
                                            f"within {dev:.3g} (tolerance {tol:.3g}): give its coefficients "
                                            "(traction.model = \"coefficients\") or use traction.model = \"eyring\"")
    _check_curve(*coefs, src, "traction.mu")
    return (tuple(S), tuple(mu)), coefs, dev


# ----------------------------------------------------------------------------
# description (hsbearing check / hsbearing oils)


def describe(case) -> list[str]:
    """Lines for ``hsbearing check``: the case's lubricant at its temperature (and a warning if alpha is estimated)."""
    from hsbearing.models import ehl

    if case.system not in ("angular_contact", "deep_groove", "gyro_ribbon_cage"):
        return []  # the wire-race model uses no lubricant data
    lub = case.lubricant
    d = getattr(lub, "definition", None)
    lines = []
    lp = ehl.lubricant_parameters(case)
    T = lp["T"]
    if d is None:
        lines.append(f"lubricant: oil {lub.oil} (built-in), traction law {lub.traction_law}")
    else:
        lines.append(f"lubricant: {d.name} ({d.oil_class or 'class not given'}) from {d.path}; "
                     f"traction: {traction_summary(d)}")
    lines.append(f"  provenance: {provenance(lub)}")
    lines.append(f"  at {T - 273.15:.4g} degC: eta = {lp['eta'] * 1e3:.4g} mPa s, nu = {lp['eta'] / lub.density * 1e6:.4g} mm^2/s, "
                 f"rho = {lub.density:.4g} kg/m^3, alpha = {lp['alpha'] * 1e9:.4g} GPa^-1")
    if d is not None and d.density_ref is None and (case.raw or {}).get("lubricant", {}).get("density") is None:
        lines.append(f"  note: {d.name} gives no density; the case's lubricant.density {lub.density:g} kg/m^3 is used")
    if d is not None and d.alpha_estimated and lub.pressure_viscosity_coefficient is not None \
            and "pressure_viscosity_coefficient" not in (case.raw or {}).get("lubricant", {}):
        lines.append(f"  warning: alpha of {d.name} is ESTIMATED ({d.alpha_estimate} correlation), not measured")
    if d is not None and d.traction_conditions is not None and lub.traction_law == "user":
        lines.extend(condition_warnings(d, T))
    return lines


def traction_summary(d) -> str:
    """One phrase naming a lubricant definition's traction model."""
    if d.traction_model == "zhang2016":
        return f"laws of oil {d.traction_oil}, law {d.traction_law}"
    if d.traction_model == "eyring":
        e = d.eyring
        tau = "2 Lambda/alpha" if e.tau0 is None else f"{e.tau0 / 1e6:.3g} MPa"
        return f"physical model (eyring): Lambda = {e.Lambda:.3g}, tau0 = {tau}, G = {e.G / 1e9:.3g} GPa"
    A, B, C, D = d.coefficients
    src = "fitted to a measured table" if d.traction_model == "table" else "given"
    return f"seed form with user coefficients ({src}): A = {A:.4g}, B = {B:.4g}, C = {C:.4g}, D = {D:.4g}"


def condition_warnings(d, T) -> list[str]:
    """The user traction data is used as given (no scaling): warn outside its stated temperature; report load/speed."""
    c = d.traction_conditions
    out = []
    if abs(T - c["T"]) > CONDITIONS_WARN_DT:
        out.append(f"  warning: the traction {'table' if d.traction_model == 'table' else 'coefficients'} of {d.name} "
                   f"were stated at {c['T'] - 273.15:.4g} degC and are used as given at {T - 273.15:.4g} degC "
                   "(no temperature scaling; docs/traction.md)")
    if c["W"] is not None or c["U"] is not None:
        w = f"{c['W']:.4g} N" if c["W"] is not None else "load not stated"
        u = f"{c['U']:.4g} m/s" if c["U"] is not None else "speed not stated"
        out.append(f"  note: user traction stated at {w}, {u}; every contact uses it unscaled")
    return out


# ----------------------------------------------------------------------------- the oil's identity and provenance


def oil_name(lub) -> str:
    """The name of a case's oil as users know it: a lubricant file's own ``name`` ("Mobil Jet Oil II", "ISO VG 32
    data sheet"), else the built-in oil (``"4109"``).  ``lub`` is ``case.lubricant``."""
    d = getattr(lub, "definition", None)
    return d.name if d is not None and d.name else str(lub.oil)


def oil_label(lub) -> str:
    """``"oil 4109"`` for a built-in oil, the file's name otherwise (headers, titles)."""
    d = getattr(lub, "definition", None)
    return d.name if d is not None and d.name else f"oil {lub.oil}"


def _resolved_law(lub) -> str:
    """The concrete traction law of a built-in oil ("default" -> e.g. "analogue_4106_percent" for 4050)."""
    from hsbearing.models import traction

    law = str(getattr(lub, "traction_law", "default") or "default")
    try:
        return str(traction.law_name(str(lub.oil), law))
    except (KeyError, ValueError):
        return law


def provenance(lub) -> str:
    """Where the oil's data come from, in one phrase: viscosity and alpha (measured / data sheet / estimated) and
    traction (the oil's own, or borrowed from a registered oil)."""
    d = getattr(lub, "definition", None)
    if d is None:
        law = _resolved_law(lub)
        if law.startswith("analogue_4106"):
            return (f"built-in oil {lub.oil}: oil data of Zhang et al. 2016 Table 1; traction by 4106's fit form (Eq. 3) "
                    f"with {lub.oil}'s own data, law {law} (docs/traction.md)")
        return f"built-in oil {lub.oil}: oil data of Zhang et al. 2016 Table 1 and its traction fit (Eqs. 1-4), law {law}"
    parts = [f"lubricant file {Path(d.path).name}" + (f" ({d.source})" if d.source else "")]
    parts.append("alpha estimated (" + d.alpha_estimate + ")" if d.alpha_estimated else "alpha given")
    if d.traction_model == "zhang2016":
        parts.append(f"traction borrowed from oil {d.traction_oil} (law {d.traction_law})")
    elif d.traction_recommended:
        parts.append(f"traction: the recommended law ({d.traction_model}) with its default constants (the file has "
                     "no [traction] table: data sheet only)")
    elif d.traction_model == "eyring":
        parts.append("traction: physical model (eyring) with the file's parameters")
    elif d.traction_model == "table":
        parts.append("traction: the file's measured table (fitted seed form)")
    else:
        parts.append("traction: the file's seed-form coefficients")
    return "; ".join(parts)


def notices(lub, raw_lubricant: dict | None = None) -> list[str]:
    """One line per thing a user must know before reading a result of this oil as its own: traction borrowed
    from another oil, alpha estimated by a correlation, density taken from the case.  Empty for a built-in oil.
    ``raw_lubricant``: the case file's ``[lubricant]`` table (a value the case sets itself wins over the file)."""
    d = getattr(lub, "definition", None)
    if d is None:
        law = _resolved_law(lub)
        if law.startswith("analogue_4106"):
            return [f"notice: the traction of oil {lub.oil} borrows the fit form of oil 4106 (Zhang et al. 2016 Eq. 3, "
                    f"law {law}) with {lub.oil}'s own Table 1 data: its Eq. 4 as printed is no traction curve "
                    "(docs/traction.md)"]
        return []
    raw = raw_lubricant or {}
    out = []
    if d.traction_model == "zhang2016":
        out.append(f"notice: the traction of {d.name} is borrowed from oil {d.traction_oil} (its {d.traction_law} "
                   f"curve fit, Zhang et al. 2016): no traction measured on {d.name} is used, so its race traction is "
                   f"{d.traction_oil}'s, not a result for {d.name}")
    if d.traction_recommended:
        out.append(f"notice: {d.name} has no [traction] table (data sheet only): its traction is the recommended law "
                   f"{d.traction_model} with default constants and {d.name}'s own viscosity and alpha, not a measured "
                   "traction curve (docs/guide/lubricants.md)")
    if d.alpha_estimated and "pressure_viscosity_coefficient" not in raw:
        out.append(f"notice: the pressure-viscosity coefficient alpha of {d.name} is estimated ({d.alpha_estimate} "
                   "correlation), not measured")
    if d.density_ref is None and "density" not in raw:
        out.append(f"notice: {d.name} gives no density: the case's lubricant.density {lub.density:g} kg/m^3 is used")
    return out


def identity_attrs(case) -> dict:
    """Global attributes naming a case's oil in an archive: ``lubricant_name``, ``lubricant_provenance`` and
    ``lubricant_notices`` (the :func:`notices` joined by ' | ', or 'none').  Empty where the model reads no
    data of the named oil (wire race; deep-groove and gyro cases without a lubricant file)."""
    lub = getattr(case, "lubricant", None)
    if lub is None or getattr(case, "system", "") == "wire_race":  # the wire-race model uses no lubricant data
        return {}
    if getattr(case, "system", "") != "angular_contact" and getattr(lub, "definition", None) is None:
        return {}  # the deep-groove and gyro models carry the oil name as a placeholder (their own viscosity)
    ns = notices(lub, (getattr(case, "raw", None) or {}).get("lubricant", {}))
    return {"lubricant_name": oil_name(lub), "lubricant_provenance": provenance(lub),
            "lubricant_notices": " | ".join(n.removeprefix("notice: ") for n in ns) if ns else "none"}


def name_in_case_text(lubricant_table: dict) -> str | None:
    """The oil's name from the ``[lubricant]`` table of an archived case (its embedded ``file_text``), for
    figures drawn from an archive; None when the table names no lubricant file."""
    text = lubricant_table.get("file_text")
    if not text:
        return None
    try:
        name = tomllib.loads(text).get("name")
    except tomllib.TOMLDecodeError:
        return None
    return str(name) if name else None


def header_lines(case) -> list[str]:
    """The lines every command prints about its oil: ``lubricant: NAME (provenance)`` and the :func:`notices`."""
    a = identity_attrs(case)
    if not a:
        return []
    out = [f"lubricant: {a['lubricant_name']} ({a['lubricant_provenance']})"]
    if a["lubricant_notices"] != "none":
        out += [f"notice: {n}" for n in a["lubricant_notices"].split(" | ")]
    return out


def header_lines_of_archive(attrs) -> list[str]:
    """:func:`header_lines` from an archive's global attributes (``lubricant_name`` ...); [] for an older archive."""
    if "lubricant_name" not in attrs:
        return []
    out = [f"lubricant: {attrs['lubricant_name']} ({attrs.get('lubricant_provenance', '')})"]
    if attrs.get("lubricant_notices", "none") != "none":
        out += [f"notice: {n}" for n in str(attrs["lubricant_notices"]).split(" | ")]
    return out


#: ``hsbearing oils --template FILE``: a lubricant file to fill in from a data sheet (it loads as it stands: the
#: numbers are those of an ISO VG 32 mineral turbine oil; replace them with your oil's).  Format: docs/traction.md,
#: "Lubricant files".
TEMPLATE = '''# A lubricant file for hsbearing (format: docs/traction.md, "Lubricant files"; check it with
#   hsbearing oils THIS_FILE          and use it with   hsbearing run --set lubricant.file=THIS_FILE).
# Every quantity is a string with units; write where each number comes from in a comment.
# The numbers below are an ISO VG 32 mineral oil's data sheet: replace them with your oil's.

name = "ISO VG 32 (data sheet)"      # printed in every summary, header, figure and archive
class = "ISO VG 32 mineral oil"      # free text
description = "turbine / spindle oil, typical values"   # optional
source = "supplier data sheet, typical properties"      # optional: where the numbers come from

# kinematic viscosity at two temperatures or more (ASTM D341 / Walther line through them); or dynamic ("mPa*s")
viscosity = [["40 degC", "32 mm^2/s"], ["100 degC", "5.4 mm^2/s"]]

# density at a stated temperature (default 15 degC); optional: without it the case's lubricant.density is used
density = "860 kg/m^3"
density_temperature = "15 degC"
# density_temperature_coefficient = "7e-4 1/K"   # rho = rho_ref (1 - k (T - T_ref)); default 0

# pressure-viscosity coefficient alpha: a value ("1.8e-8 1/Pa"), [[T, alpha], ...] points, or the name of a
# correlation when the data sheet does not give it (then every command says that alpha is estimated); left out,
# it is estimated by so_klaus_1980 (with the same notice)
pressure_viscosity_coefficient = "so_klaus_1980"

# service_temperature = ["-10 degC", "100 degC"]   # optional: the range the data sheet states; beyond it
#                                                 # every command warns (the data are extrapolated)
# thermal_conductivity = "0.13 W/(m*K)"   # optional
# viscosity_index = 100                   # optional, as the data sheet states it (reported only)

# traction: a measured law of your oil if you have one (model = "table": measured mu(S) points, or
# model = "coefficients"; model = "eyring": the physical model with its parameters).  Without measurements,
# borrow the registered curve fit of the closest of the three oils of Zhang et al. 2016 (4109, 4106, 4050):
# every command then says that the traction is borrowed.  Or leave the [traction] table out (data-sheet values
# only): the recommended law (hsbearing.models.traction.RECOMMENDED_LAW) with its default constants is used, fed
# by this oil's own viscosity and alpha, and every command says so.
[traction]
model = "zhang2016"
oil = "4106"
law = "default"
'''

