"""The wire-race bearing system (Shan et al. 2010): contacts of a case over preloads, the preload
sweep, the fit of the rolling resistance zeta and M_u, the preload window for a target starting torque,
``hsbearing preload`` and its figure.  The closed forms are :mod:`hsbearing.models.friction.wire_race`.
"""

from __future__ import annotations

import math
import re
import sys
from dataclasses import dataclass

import numpy as np
import xarray as xr
from scipy.optimize import brentq

from hsbearing.case import parse_quantity
from hsbearing.errors import CaseError
from hsbearing.models.friction import wire_race as _physics
from hsbearing.models.friction.wire_race import (  # noqa: F401 - the physics, also public here
    bearing_rolling_torque,
    contact_deformation,
    contact_forces_from_preload,
    contact_forces_from_torque,
    contact_stiffness,
    framework_equilibrium_F2,
    framework_equilibrium_residual_printed,
    preload_from_forces,
    preload_from_torque,
    rolling_resistance_moment,
    starting_torque,
    wire_contact_radii,
)
from hsbearing.models.hertz import point_contact
from hsbearing.results import check_archive_name, make_dataset, register, standard_attrs, write_netcdf

#: the physics' public names (re-exported above) and this module's own
__all__ = [*_physics.__all__,
           "fit_rolling_resistance",
           "RollingResistanceFit",
           "WireRaceContacts",
           "contacts",
           "preload_sweep",
           "preload_window",
           "plot_torque_vs_preload",
           "preload_command",
           "parse_range",
           "DEFAULT_PRELOADS",
           ]

#: Default preload grid of :func:`preload_sweep`: 10-160 um in 5 um steps (Table 2 of [1] spans 10-160 um).
DEFAULT_PRELOADS = np.linspace(10e-6, 160e-6, 31)

# ----------------------------------------------------------------------------- output variables

register("preload", ("preload",), "m", "preload magnitude delta (shim grinding), Shan et al. 2010 Eq. 10")
for _j, _where in ((1, "inner wire, diagonal 1-3"), (2, "inner wire, diagonal 2-4"),
                   (3, "outer wire, diagonal 1-3"), (4, "outer wire, diagonal 2-4")):
    register(f"F{_j}", ("preload",), "N", f"ball-wire normal contact force F_{_j} ({_where}), Shan et al. 2010 Eqs. 7-10")
    register(f"delta{_j}", ("preload",), "m", f"ball-wire Hertz contact deformation delta_{_j} ({_where})")
    register(f"p_max{_j}", ("preload",), "Pa", f"maximum Hertz pressure P_0{_j} at contact {_j} ({_where})")
register("torque", ("preload",), "N*m", "starting torque M_s = rolling torque + M_u (Shan et al. 2010 Eqs. 4 and 11)")
register("rolling_torque", ("preload",), "N*m", "rolling-resistance bearing torque M_sc = zeta Z sum F_j cos(alpha) (Shan et al. 2010 Eq. 4)")
register("contact_stiffness_inner", (), "N*m**-1.5", "ball-inner wire load-deflection constant K_i, F = K_i delta^1.5 (Shan et al. 2010 Eq. 5)")
register("contact_stiffness_outer", (), "N*m**-1.5", "ball-outer wire load-deflection constant K_o, F = K_o delta^1.5 (Shan et al. 2010 Eq. 6)")


@dataclass(frozen=True)
class RollingResistanceFit:
    """Result of :func:`fit_rolling_resistance`; unpacks as ``zeta, M_u = fit``."""

    zeta: float  #: coefficient of rolling frictional resistance [m]
    M_u: float  #: torque of the unconsidered factors [N m]
    method: str
    M_s_mean: float  #: mean measured torque [N m]
    F_sum_mean: float  #: mean of F1 + F2 [N]
    M_s_I: float = float("nan")  #: mean measured torque, first group [N m] (grouping method)
    M_s_II: float = float("nan")  #: second group [N m]
    F_sum_I: float = float("nan")  #: mean F1 + F2, first group [N]
    F_sum_II: float = float("nan")  #: second group [N]
    residual_rms: float = float("nan")  #: rms of measured - Eq. 11 [N m]

    def __iter__(self):
        return iter((self.zeta, self.M_u))


def fit_rolling_resistance(preloads=None, measured_torques=None, case=None, *, forces=None, Z=None, alpha=None,
                           method: str = "grouping", first_group: int | None = None, stiffness=None
                           ) -> RollingResistanceFit:
    """zeta and M_u from measured starting torques (Eqs. 11-13 of [1]).

    Model (Eq. 11): M_sn = 2 zeta Z (F1n + F2n) cos(alpha) + M_u, linear in
    x_n = 2 Z (F1n + F2n) cos(alpha).

    Parameters
    ----------
    preloads : preloads of the measurements [m] (used with ``case`` to compute F1, F2)
    measured_torques : measured bearing torques M_sn [N m]
    case : a wire_race case (Z, alpha, G_o, stiffness); optional if ``forces``, ``Z`` and ``alpha`` are given
    forces : (F1, F2) arrays [N] to use instead of computing them (e.g. the paper's Table 2 columns)
    method : ``"grouping"`` -- [1], Eqs. 12-13: the slope through the means of two
        groups (first ``first_group`` points, default n // 2, and the rest) and
        the intercept through the overall mean (Wald's grouping method, what
        the paper uses for Table 3); ``"least_squares"`` -- ordinary least
        squares of Eq. 11.
    stiffness : (K_i, K_o) override, passed to :func:`contacts`.

    Returns
    -------
    RollingResistanceFit (iterates as ``zeta, M_u``).
    """
    M = np.asarray(measured_torques, dtype=float)
    if forces is not None:
        F1, F2 = (np.asarray(f, dtype=float) for f in forces)
    else:
        if case is None or preloads is None:
            raise ValueError("give either forces=(F1, F2) or preloads and case")
        c = contacts(case, preloads, stiffness=stiffness)
        F1, F2 = c.F1, c.F2
    if Z is None or alpha is None:
        if case is None:
            raise ValueError("Z and alpha are needed (or a case)")
        Z = case.bearing.ball_count if Z is None else Z
        alpha = case.bearing.contact_angle if alpha is None else alpha
    if not (M.shape == F1.shape == F2.shape) or M.ndim != 1 or M.size < 3:
        raise ValueError("measured torques and forces must be 1-D of the same length >= 3")
    S = F1 + F2
    Ms_mean, S_mean = float(M.mean()), float(S.mean())
    extra = {}
    if method == "grouping":
        n1 = M.size // 2 if first_group is None else int(first_group)
        if not 1 <= n1 < M.size:
            raise ValueError(f"first_group must be in 1..{M.size - 1}")
        MI, MII = float(M[:n1].mean()), float(M[n1:].mean())
        SI, SII = float(S[:n1].mean()), float(S[n1:].mean())
        zeta = (MII - MI) / (2.0 * Z * (SII - SI) * math.cos(alpha))  # [1], Eq. 12
        extra = dict(M_s_I=MI, M_s_II=MII, F_sum_I=SI, F_sum_II=SII)
    elif method == "least_squares":
        x = 2.0 * Z * S * math.cos(alpha)
        zeta = float(np.sum((x - x.mean()) * (M - Ms_mean)) / np.sum((x - x.mean()) ** 2))  # LSQ slope of Eq. 11
    else:
        raise ValueError(f"unknown method {method!r} (grouping, least_squares)")
    M_u = Ms_mean - 2.0 * zeta * Z * S_mean * math.cos(alpha)  # [1], Eq. 13
    resid = M - starting_torque(zeta, Z, F1, F2, alpha, M_u)
    return RollingResistanceFit(zeta=float(zeta), M_u=float(M_u), method=method, M_s_mean=Ms_mean, F_sum_mean=S_mean,
                                residual_rms=float(np.sqrt(np.mean(resid**2))), **extra)


# ----------------------------------------------------------------------------- case-level API


@dataclass(frozen=True)
class WireRaceContacts:
    """Contact state of a wire-race bearing over a set of preloads (arrays over ``preload``)."""

    preload: np.ndarray
    F1: np.ndarray
    F2: np.ndarray
    F3: np.ndarray
    F4: np.ndarray
    delta1: np.ndarray
    delta2: np.ndarray
    delta3: np.ndarray
    delta4: np.ndarray
    p_max1: np.ndarray
    p_max2: np.ndarray
    p_max3: np.ndarray
    p_max4: np.ndarray
    rolling_torque: np.ndarray
    torque: np.ndarray
    K_i: float
    K_o: float
    stiffness_source: str


def _require(case, value, key):
    if value is None:
        raise CaseError(case.source, key, "missing required key for a wire_race case")
    return value


def _wire_params(case):
    if case.system != "wire_race":
        raise CaseError(case.source, "case.system", f"'hsbearing preload' needs system = \"wire_race\", got {case.system!r}")
    b = case.bearing
    d_w = _require(case, b.wire_diameter, "bearing.wire_diameter")
    alpha = b.contact_angle
    if not 0.0 < alpha < 0.5 * math.pi:
        raise CaseError(case.source, "bearing.contact_angle", f"must be between 0 and 90 deg for a four-point wire race, got {math.degrees(alpha):g} deg")
    f_w = b.wire_groove_conformity
    if f_w is not None and f_w <= 0.5:
        raise CaseError(case.source, "bearing.wire_groove_conformity", f"must be > 0.5 (track radius larger than the ball radius), got {f_w}")
    G_o = case.operating.framework_weight or 0.0
    zeta = _require(case, case.friction.rolling_resistance, "friction.rolling_resistance")
    M_u = case.friction.unconsidered_torque or 0.0
    return dict(Z=b.ball_count, D=b.ball_diameter, d_m=b.pitch_diameter, d_w=d_w, alpha=alpha, f_w=f_w,
                G_o=G_o, zeta=zeta, M_u=M_u)


def contacts(case, preloads=None, *, stiffness=None) -> WireRaceContacts:
    """Contact forces, deformations, pressures and torques of a wire_race case at the given preloads.

    Parameters
    ----------
    case : a :class:`hsbearing.case.Case` with ``system = "wire_race"``
    preloads : preloads [m] (default :data:`DEFAULT_PRELOADS`)
    stiffness : optional (K_i, K_o) [N/m^1.5] replacing the Hertz values of
        Eqs. 5-6 (e.g. the constants implied by Table 2 of [1]); pressures
        are still the Hertz pressures of the case geometry.
    """
    p = _wire_params(case)
    pre = np.atleast_1d(np.asarray(DEFAULT_PRELOADS if preloads is None else preloads, dtype=float))
    if pre.ndim != 1 or pre.size == 0 or np.any(~np.isfinite(pre)) or np.any(pre < 0):
        raise CaseError(case.source, "operating.preload", "preloads must be a non-empty list of finite values >= 0")
    mb, mr = case.materials.ball, case.materials.races
    Rx_i, Ry_i, Rx_o, Ry_o = wire_contact_radii(p["D"], p["d_w"], p["d_m"], p["alpha"], p["f_w"])
    if stiffness is None:
        K_i = float(contact_stiffness(Rx_i, Ry_i, mb.elastic_modulus, mb.poisson_ratio, mr.elastic_modulus, mr.poisson_ratio))
        K_o = float(contact_stiffness(Rx_o, Ry_o, mb.elastic_modulus, mb.poisson_ratio, mr.elastic_modulus, mr.poisson_ratio))
        source = "hertz_exact"
    else:
        K_i, K_o = (float(k) for k in stiffness)
        if not (K_i > 0 and K_o > 0):
            raise ValueError("stiffness override must be two positive numbers (K_i, K_o)")
        source = "override"
    F1, F2 = contact_forces_from_preload(pre, p["Z"], p["alpha"], p["G_o"], K_i, K_o)
    F3, F4 = F1.copy(), F2.copy()  # ball equilibrium along each diagonal, [1] below Eq. 7
    d = [contact_deformation(F, K) for F, K in ((F1, K_i), (F2, K_i), (F3, K_o), (F4, K_o))]
    pm = []
    for F, (Rx, Ry) in ((F1, (Rx_i, Ry_i)), (F2, (Rx_i, Ry_i)), (F3, (Rx_o, Ry_o)), (F4, (Rx_o, Ry_o))):
        pm.append(point_contact(min(Rx, Ry), max(Rx, Ry), F, mb.elastic_modulus, mb.poisson_ratio,
                                mr.elastic_modulus, mr.poisson_ratio).p_max)
    M_sc = bearing_rolling_torque(p["zeta"], p["Z"], F1, F2, F3, F4, p["alpha"])  # [1], Eq. 4
    return WireRaceContacts(preload=pre, F1=F1, F2=F2, F3=F3, F4=F4, delta1=d[0], delta2=d[1], delta3=d[2],
                            delta4=d[3], p_max1=pm[0], p_max2=pm[1], p_max3=pm[2], p_max4=pm[3],
                            rolling_torque=M_sc, torque=M_sc + p["M_u"], K_i=K_i, K_o=K_o,
                            stiffness_source=source)


def preload_sweep(case, preloads=None, *, stiffness=None) -> xr.Dataset:
    """Dataset over the coordinate ``preload`` [m]: F1..F4 [N], delta1..delta4 [m], p_max1..p_max4 [Pa], torque [N m].

    ``torque`` is the starting torque of Eq. 11 (rolling torque of Eq. 4 plus
    ``friction.unconsidered_torque`` M_u); ``rolling_torque`` is Eq. 4 alone
    (the M_sc column of Table 2 of [1]).  See :func:`contacts` for ``stiffness``.
    """
    c = contacts(case, preloads, stiffness=stiffness)
    p = _wire_params(case)
    names = [f"{q}{j}" for q in ("F", "delta", "p_max") for j in (1, 2, 3, 4)] + ["torque", "rolling_torque"]
    data = {n: getattr(c, n) for n in names}
    data["contact_stiffness_inner"] = np.float64(c.K_i)
    data["contact_stiffness_outer"] = np.float64(c.K_o)
    n_unloaded = int(np.sum(c.F1 == 0.0))
    attrs = standard_attrs(
        case, "ok", title="hsbearing wire-race preload sweep (Shan et al. 2010)", model="shan2010_wire_race",
        stiffness_source=c.stiffness_source, rolling_resistance=p["zeta"], unconsidered_torque=p["M_u"],
        framework_weight=p["G_o"], contact_angle=p["alpha"], ball_count=p["Z"],
        wire_geometry="round wire" if p["f_w"] is None else f"ground track, conformity {p['f_w']}",
        note=(f"{n_unloaded} preload(s) below the contact limit: diagonal 1-3 unloaded" if n_unloaded else None),
    )
    return make_dataset(data, coords={"preload": c.preload}, attrs=attrs)


def _window_pressure_caveat(ds, p_all, window) -> str:
    """The caveat on the preload-window line when the maximum contact pressure there exceeds ISO 76's 4.2 GPa (the Shan et al. 2010 window lies at 10.7-11.0 GPa and the line said nothing)."""
    from hsbearing.display import ISO76_BALL_PRESSURE

    x = np.asarray(ds["preload"].values, dtype=float)
    p = np.asarray(p_all, dtype=float)
    ok = np.isfinite(x) & np.isfinite(p)
    if ok.sum() < 2 or not (x[ok].min() <= window[0] and window[1] <= x[ok].max()):
        return ""  # the window lies outside the computed preloads: no pressure to quote
    lo, hi = np.interp(window, x[ok], p[ok])
    if max(lo, hi) <= ISO76_BALL_PRESSURE:
        return ""
    return (f" -- caveat: maximum contact pressure there {min(lo, hi) * 1e-9:.3g}-{max(lo, hi) * 1e-9:.3g} GPa, above "
            f"the {ISO76_BALL_PRESSURE * 1e-9:g} GPa of ISO 76: the elastic (Hertz) model describes no real bearing there")


def preload_window(case, torque_lo, torque_hi, *, stiffness=None, delta_max: float = 2e-3) -> tuple[float, float]:
    """Preload window (lo, hi) [m] in which the starting torque (Eq. 11) lies in [torque_lo, torque_hi] [N m].

    The inverse of :func:`preload_sweep` (torque increases monotonically with
    the preload).  [1], Sec. 4.1: 90-100 N m -> 130-140 um (read from the
    measured curve).  Raises CaseError if a target is out of reach.
    """
    lo_t, hi_t = float(torque_lo), float(torque_hi)
    if not (np.isfinite(lo_t) and np.isfinite(hi_t)) or lo_t > hi_t:
        raise CaseError("--target-torque", None, f"need finite lo <= hi, got {torque_lo}..{torque_hi}")

    def torque_at(d):
        return float(contacts(case, [d], stiffness=stiffness).torque[0])

    t0, tmax = torque_at(0.0), torque_at(delta_max)
    out = []
    for t in (lo_t, hi_t):
        if t < t0:
            raise CaseError("--target-torque", None,
                            f"{t:g} N m is below the torque at zero preload ({t0:.4g} N m: weight of the framework and M_u)")
        if t > tmax:
            raise CaseError("--target-torque", None, f"{t:g} N m needs a preload above {delta_max * 1e6:g} um")
        out.append(0.0 if t == t0 else brentq(lambda d: torque_at(d) - t, 0.0, delta_max, xtol=1e-12))  # noqa: B023 - solved here
    return out[0], out[1]


# ----------------------------------------------------------------------------- figure


def plot_torque_vs_preload(ds: xr.Dataset, path, measured: dict | None = None, paper: dict | None = None,
                           window: tuple[float, float] | None = None, target: tuple[float, float] | None = None):
    """Torque vs preload like Fig. 9a of [1]: our Eq. 4 / Eq. 11 curves, optional paper/measured points.

    measured : {label: (preload [m], torque [N m])}; paper : the same for the
    paper's calculated column.  Returns the PNG path.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.6), dpi=120)
    um = ds["preload"].values * 1e6
    ax.plot(um, ds["rolling_torque"].values, "-", color="C0", label="ours: $M_{sc}$, Eq. 4")
    ax.plot(um, ds["torque"].values, "--", color="C0", label="ours: $M_{sc} + M_u$, Eq. 11")
    for label, (x, y) in (paper or {}).items():
        ax.plot(np.asarray(x) * 1e6, y, "s", mfc="none", color="C1", label=label)
    markers = ("o", "^", "v", "D")
    for i, (label, (x, y)) in enumerate((measured or {}).items()):
        ax.plot(np.asarray(x) * 1e6, y, markers[i % 4] + ":", color=f"C{i + 2}", label=label)
    if target is not None:
        ax.axhspan(target[0], target[1], color="0.85", zorder=0, label=f"target {target[0]:g}-{target[1]:g} N m")
    if window is not None:
        ax.axvspan(window[0] * 1e6, window[1] * 1e6, color="C0", alpha=0.12, zorder=0,
                   label=f"our window {window[0] * 1e6:.0f}-{window[1] * 1e6:.0f} $\\mu$m")
    ax.set_xlabel("preload magnitude $\\delta$ [$\\mu$m]")
    ax.set_ylabel("bearing torque [N m]")
    ax.set_title(ds.attrs.get("case_name", "wire race") + ": torque vs preload (cf. Shan et al. 2010 Fig. 9a)", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    from hsbearing.plotting.common import save_figure

    save_figure(fig, path)
    plt.close(fig)
    return path


# ----------------------------------------------------------------------------- CLI

_NUM = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


def _split_num(token: str, option: str):
    m = _NUM.match(token)
    if not m:
        raise CaseError(option, None, f"cannot read a number in {token!r}")
    return m.group(1), m.group(2)


def parse_range(text: str, kind: str, option: str, n: int = 31) -> np.ndarray:
    """``"10..160um"`` (n points), ``"10..160:5um"`` (step), or ``"10,20,40um"`` -> SI array.

    The unit written on the last value applies to the values without one.
    Bad syntax, missing/incompatible units, lo > hi -> CaseError(option, None, msg).
    """
    if text is None or not str(text).strip():
        raise CaseError(option, None, "empty value")
    text = str(text).strip()

    def convert(nums_units):
        unit = nums_units[-1][1]
        if not unit:
            raise CaseError(option, None, f"{text!r}: give a unit, e.g. {'10..160um' if kind == 'length' else '90..100N*m'}")
        return np.array([parse_quantity(f"{num} {u or unit}", kind, source=option) for num, u in nums_units])

    if ".." in text:
        lo_s, _, rest = text.partition("..")
        step_s = None
        if ":" in rest:
            rest, _, step_s = rest.partition(":")
        lo_n, lo_u = _split_num(lo_s, option)
        hi_n, hi_u = _split_num(rest, option)
        parts = [(lo_n, lo_u), (hi_n, hi_u)]
        if step_s is not None:
            st_n, st_u = _split_num(step_s, option)
            parts.append((st_n, st_u))
            unit = st_u or hi_u
            parts = [(a, b or unit) for a, b in parts]
        vals = convert(parts)
        lo, hi = vals[0], vals[1]
        if lo > hi:
            raise CaseError(option, None, f"{text!r}: lower bound above the upper bound")
        if step_s is not None:
            step = vals[2]
            if step <= 0:
                raise CaseError(option, None, f"{text!r}: step must be positive")
            count = int(math.floor((hi - lo) / step * (1 + 1e-12))) + 1
            if count > 100000:
                raise CaseError(option, None, f"{text!r}: too many points ({count})")
            return lo + step * np.arange(count)
        return np.linspace(lo, hi, n) if hi > lo else np.array([lo])
    tokens = [t for t in text.split(",")]
    if any(not t.strip() for t in tokens):
        raise CaseError(option, None, f"{text!r}: empty item in the list")
    return convert([_split_num(t, option) for t in tokens])


def _format_table(ds: xr.Dataset) -> list[str]:
    head = (f"{'preload':>8} {'F1':>9} {'F2':>9} {'F3':>9} {'F4':>9} {'delta1':>7} {'delta2':>7} {'delta3':>7} {'delta4':>7} "
            f"{'P01':>6} {'P02':>6} {'P03':>6} {'P04':>6} {'M_sc':>8} {'M_s':>8}")
    um = "[\u00b5m]"
    units = (f"{um:>8} {'[N]':>9} {'[N]':>9} {'[N]':>9} {'[N]':>9} {um:>7} {um:>7} {um:>7} {um:>7} "
             f"{'[GPa]':>6} {'[GPa]':>6} {'[GPa]':>6} {'[GPa]':>6} {'[N m]':>8} {'[N m]':>8}")
    lines = [head, units]
    for i in range(ds.sizes["preload"]):
        v = {k: float(ds[k].values[i]) for k in ds.data_vars if ds[k].dims == ("preload",)}
        lines.append(
            f"{ds['preload'].values[i] * 1e6:8.2f} {v['F1']:9.2f} {v['F2']:9.2f} {v['F3']:9.2f} {v['F4']:9.2f} "
            f"{v['delta1'] * 1e6:7.2f} {v['delta2'] * 1e6:7.2f} {v['delta3'] * 1e6:7.2f} {v['delta4'] * 1e6:7.2f} "
            f"{v['p_max1'] / 1e9:6.3f} {v['p_max2'] / 1e9:6.3f} {v['p_max3'] / 1e9:6.3f} {v['p_max4'] / 1e9:6.3f} "
            f"{v['rolling_torque']:8.2f} {v['torque']:8.2f}")
    return lines


def preload_command(case, args) -> int:
    """``hsbearing preload CASE [--preload 10..160um | 10,20,40um] [--target-torque 90..100N*m] [--set k=v] [-o OUT.nc]``
    (``case``: loaded by the CLI with the ``--set`` overrides)."""
    _wire_params(case)  # validate the case before anything is computed
    preloads = parse_range(getattr(args, "preload", None) or "10..160um", "length", "--preload")
    if np.any(preloads < 0):
        raise CaseError("--preload", None, "preloads must be >= 0")
    target = None
    if getattr(args, "target_torque", None):
        t = parse_range(args.target_torque, "moment", "--target-torque", n=2)
        if t.size != 2:
            raise CaseError("--target-torque", None, "expected a window lo..hi, e.g. 90..100N*m")
        target = (float(t[0]), float(t[-1]))
    out = getattr(args, "output", None)
    check_archive_name(out)
    ds = preload_sweep(case, preloads)
    window = preload_window(case, *target) if target else None
    p = _wire_params(case)
    print(f"case {case.name}: Z = {p['Z']}, alpha = {math.degrees(p['alpha']):g} deg, G_o = {p['G_o']:g} N, "
          f"zeta = {p['zeta']:.5g} m, M_u = {p['M_u']:.5g} N m")
    print(f"contact stiffness (exact Hertz, Eqs. 5-6): K_i = {float(ds.contact_stiffness_inner):.5g}, "
          f"K_o = {float(ds.contact_stiffness_outer):.5g} N/m^1.5")
    for line in _format_table(ds):
        print(line)
    print("M_sc: rolling-resistance torque, Eq. 4; M_s = M_sc + M_u, Eq. 11")
    from hsbearing.display import contact_pressure_warning

    p_all = np.max([ds[f"p_max{j}"].values for j in range(1, 5)], axis=0)
    warn = contact_pressure_warning(p_all, f"at preload {float(ds['preload'].values[int(np.nanargmax(p_all))]) * 1e6:.4g} \u00b5m")
    if warn:
        print(warn, file=sys.stderr)
    if window is not None:
        ds.attrs["target_torque"] = list(target)
        ds.attrs["preload_window"] = [window[0], window[1]]
        print(f"preload window for {target[0]:g}..{target[1]:g} N m: {window[0] * 1e6:.2f} .. {window[1] * 1e6:.2f} \u00b5m"
              + _window_pressure_caveat(ds, p_all, window))
    if out:
        write_netcdf(ds, out)
        print(f"archive: {out}")
    sys.stdout.flush()
    return 0
