"""Friction torque of deep-groove ball bearings: dgbb_prl sliding method and the SKF 2004 model.

:func:`friction_torque` evaluates, over a list of inner-ring speeds,

* the dgbb_prl sliding friction torque M_sl = M_s + M_r + M_d
  (:mod:`hsbearing.models.friction.sliding_prl`: pure rolling lines, ball
  equilibrium) with the sliding coefficient of ``[friction] law``
  (``stribeck``: the SKF-weighted mu_sl(n); ``coulomb``: ``[friction] coefficient``);
* the SKF 2004 moments (:mod:`hsbearing.models.friction.skf2004`).

:func:`friction_command` is ``hsbearing friction CASE [--speeds ...] [-o OUT.nc]`` of a deep-groove case;
the figures of dgbb_prl are :func:`hsbearing.systems.deep_groove.figures.make_figures`.
"""

from __future__ import annotations

import math

import numpy as np

from hsbearing.errors import CaseError
from hsbearing.models.friction import skf2004
from hsbearing.results import make_dataset, register, standard_attrs
from hsbearing.units import parse_speeds

__all__ = ["friction_torque", "friction_command", "contact_states"]

for _n, _d, _u, _l in [
    ("speed", ("speed",), "rad/s", "inner-ring rotational speed n"),
    ("spinning_torque", ("speed",), "N*m", "spinning friction torque M_s (dgbb_prl method)"),
    ("rotation_sliding_torque", ("speed",), "N*m", "differential sliding friction torque due to ball rotation M_r (dgbb_prl method)"),
    ("orbital_sliding_torque", ("speed",), "N*m", "differential sliding friction torque due to ball orbital motion M_d (dgbb_prl method)"),
    ("sliding_torque", ("speed",), "N*m", "sliding friction torque M_sl = M_s + M_r + M_d (dgbb_prl method)"),
    ("sliding_coefficient", ("speed",), "1", "sliding friction coefficient mu used by the dgbb_prl method"),
    ("ball_contact_load", ("ball",), "N", "ball-inner race normal load Q_i (= outer load without centrifugal force)"),
    ("ball_contact_angle", ("ball",), "rad", "ball-inner race contact angle alpha_i (= outer angle without centrifugal force)"),
    ("inner_prl_c1", ("ball",), "1", "first pure-rolling-line location c1 = x/a at the inner contact (nan: outside)"),
    ("inner_prl_c2", ("ball",), "1", "second pure-rolling-line location c2 = x/a at the inner contact (nan: outside)"),
    ("outer_prl_c1", ("ball",), "1", "first pure-rolling-line location c1 = x/a at the outer contact (nan: outside)"),
    ("outer_prl_c2", ("ball",), "1", "second pure-rolling-line location c2 = x/a at the outer contact (nan: outside)"),
] + list(skf2004.OUTPUTS):
    register(_n, _d, _u, _l)


def _require_dgbb(case):
    if case.system not in ("deep_groove", "angular_contact"):
        raise CaseError(case.source, "case.system", f"friction torque is for deep_groove (and angular_contact) cases, not {case.system!r}")
    # a radial ball bearing is symmetric: the sign of the axial load only mirrors the contact angles


def contact_states(case, speed=None, source: str = "static", tilt: bool = True, centrifugal: bool = True):
    """Per-ball contact loads, angles, ellipses and deformed radii.

    ``source="static"``: rigid-ring static load distribution (no centrifugal
    force, no gyroscopic moment; :func:`sliding_prl.static_load_distribution`)
    -- the seed's Tables 2-4 show no speed effect, so this is the reading used;
    ``tilt=True`` lets the inner ring tilt under the given moment
    (``operating.moment_z``, about the axis normal to the radial load F_y),
    the seed's 5-DOF loading {F_x, F_y, F_z, M_x, M_y}; False holds it square.
    ``source="quasistatic"``: :func:`hsbearing.systems.angular_contact.quasistatic.solve_case`
    at ``speed`` with (``centrifugal=True``) or without ball inertia effects.

    Returns (psi, Q, alpha, [ContactState per ball]).
    """
    from hsbearing.models import geometry
    from hsbearing.models.friction import sliding_prl as sp
    from hsbearing.models.hertz import point_contact

    g = geometry.derive(case)
    mb, mr = case.materials.ball, case.materials.races
    Fa = abs(case.operating.axial_load)
    Ri, Ro = sp.deformed_radius(g.ri, g.D), sp.deformed_radius(g.ro, g.D)
    if source == "static":
        op = case.operating
        if op.radial_load_z or op.moment_y:
            raise CaseError(case.source, "operating.radial_load_z" if op.radial_load_z else "operating.moment_y",
                            "the friction model's static load distribution is planar (radial_load along Y, moment_z); "
                            "use contacts='quasistatic' for general 5-DOF loads")
        psi, Q, al = sp.static_load_distribution(g.Z, g.D, g.dm, g.fi, g.fo, g.Pd, mb.elastic_modulus, mb.poisson_ratio,
                                                 mr.elastic_modulus, mr.poisson_ratio, Fa, abs(op.radial_load),
                                                 M=op.moment_z * (1.0 if op.radial_load >= 0 else -1.0), tilt=tilt)
        Qi = Qo = Q
        ai = ao = al
    elif source == "quasistatic":
        from hsbearing.systems.angular_contact import quasistatic

        ds = quasistatic.solve_case(case, inner_speed=speed, centrifugal=centrifugal, gyroscopic=centrifugal)
        Qi, Qo = ds["inner_contact_load"].values, ds["outer_contact_load"].values
        ai, ao = ds["inner_contact_angle"].values, ds["outer_contact_angle"].values
        psi = 2 * math.pi * np.arange(g.Z) / g.Z
        Q, al = Qi, ai
    else:
        raise ValueError(f"unknown contact source {source!r}")
    states = []
    for j in range(g.Z):
        Rxi, Ryi, _, _ = geometry.curvature_radii(g.D, g.dm, ai[j], g.fi, g.fo)
        _, _, Rxo, Ryo = geometry.curvature_radii(g.D, g.dm, ao[j], g.fi, g.fo)
        ci = point_contact(Rxi, Ryi, Qi[j], mb.elastic_modulus, mb.poisson_ratio, mr.elastic_modulus, mr.poisson_ratio)
        co = point_contact(Rxo, Ryo, Qo[j], mb.elastic_modulus, mb.poisson_ratio, mr.elastic_modulus, mr.poisson_ratio)
        states.append(sp.ContactState(Q=(float(Qi[j]), float(Qo[j])), alpha=(float(ai[j]), float(ao[j])),
                                      a=(float(ci.a), float(co.a)), b=(float(ci.b), float(co.b)), R=(Ri, Ro)))
    return psi, np.asarray(Q), np.asarray(al), states


def friction_torque(case, speeds="500,5000,15000rpm", *, traction: str = "strip", contacts: str = "static",
                    tilt: bool = True):
    """Sliding friction torque (dgbb_prl method) and SKF 2004 moments over inner-ring speeds.

    Parameters
    ----------
    case : a Case or a bundled case name / path (``system = "deep_groove"``).
    speeds : inner-ring speeds: numbers [rad/s], unit strings (``"500 rpm"``)
        or the CLI form ``"500,5000,15000rpm"``.
    traction : ``"strip"`` (dgbb_prl / Harris strip theory) or ``"full"`` (2-D slip direction).
    contacts : ``"static"`` (no centrifugal/gyroscopic, the seed's reading) or ``"quasistatic"``.
    tilt : static contacts: inner ring free to tilt under the given moment (True, the
        seed's 5-DOF loading) or held square (False).

    Returns
    -------
    xarray.Dataset over ``speed`` [rad/s] (and ``ball`` for the contact data and
    PRLs at the first speed) with the variables registered above, all torques in N m.
    """
    from hsbearing.case import Case, load_case
    from hsbearing.models import geometry
    from hsbearing.models.friction import sliding_prl as sp

    case = case if isinstance(case, Case) else load_case(case)
    _require_dgbb(case)
    w = parse_speeds(speeds)
    g = geometry.derive(case)
    fr, lub = case.friction, case.lubricant
    if case.system == "deep_groove":
        skf = skf2004.skf_moments(case, w)
        skf_note = None
    else:  # the SKF model's angular-contact formulas are not implemented: report NaN, say so
        skf = {k: np.full_like(w, np.nan) for k in ("skf_rolling_torque", "skf_sliding_torque", "skf_drag_torque",
                                                     "skf_total_torque", "skf_sliding_coefficient")}
        skf_note = "SKF 2004 moments are implemented for deep-groove ball bearings only (NaN here)"
        if fr.law == "stribeck":
            raise CaseError(case.source, "friction.law",
                            "the Stribeck-type (SKF-weighted) coefficient needs the SKF DGBB model; use law = \"coulomb\" for this system")
    if fr.law == "stribeck":
        mu = skf["skf_sliding_coefficient"]
    else:
        mu = np.full_like(w, fr.coefficient)
    speed_ratio = case.operating.outer_speed / case.operating.inner_speed if case.operating.inner_speed else 0.0
    comps = np.zeros((len(w), 3))
    prl = None
    cache = None
    for i, wi in enumerate(w):
        if contacts == "static" and cache is not None:
            per_mu = cache
        else:
            psi, Q, al, states = contact_states(case, wi, source=contacts, tilt=tilt)
            balls = [sp.solve_ball(st, g.D, g.dm, outer_speed_ratio=speed_ratio, traction=traction) for st in states]
            if fr.spin_torque_reading == "projection":
                # [S] Eq. 8 read as Tong & Hong: M_s = sum_j (|m_s,i| sin a_i + |m_s,e| sin a_e)
                spin = sum(abs(b.spin_moment[0]) * abs(math.sin(st.alpha[0])) + abs(b.spin_moment[1]) * abs(math.sin(st.alpha[1]))
                           for b, st in zip(balls, states))
            else:  # dissipated power of the spin tractions over omega_i (energy-consistent)
                spin = sum(b.spin_power for b in balls)
            per_mu = np.array([spin, sum(b.rotation_power for b in balls), sum(b.orbital_power for b in balls)])
            if prl is None:
                prl = (Q, al, np.array([[b.prl[0][0], b.prl[0][1], b.prl[1][0], b.prl[1][1]] for b in balls]))
            cache = per_mu
        comps[i] = mu[i] * per_mu  # powers per unit mu and unit omega_i -> torques [N m]
    Q, al, c = prl
    data = {
        "spinning_torque": comps[:, 0],
        "rotation_sliding_torque": comps[:, 1],
        "orbital_sliding_torque": comps[:, 2],
        "sliding_torque": comps.sum(axis=1),
        "sliding_coefficient": mu,
        "ball_contact_load": Q,
        "ball_contact_angle": al,
        "inner_prl_c1": c[:, 0], "inner_prl_c2": c[:, 1], "outer_prl_c1": c[:, 2], "outer_prl_c2": c[:, 3],
    }
    data.update({k: v for k, v in skf.items()})
    attrs = standard_attrs(
        case, "ok", title="hsbearing friction torque (dgbb_prl sliding method, SKF 2004 model)",
        friction_law=fr.law, traction_model=traction, contact_source=contacts, ring_tilt_free=bool(tilt),
        kinematic_viscosity_mm2_s=lub.kinematic_viscosity * 1e6 if lub.kinematic_viscosity else None,
        skf_reading=fr.skf_reading, spin_torque_reading=fr.spin_torque_reading,
        note="ball data (contact_load/angle, PRLs) at the first speed; torques in N m",
        skf_note=skf_note,
    )
    return make_dataset(data, coords={"speed": w, "ball": np.arange(g.Z)}, attrs=attrs)


def friction_command(case, args) -> int:
    """``hsbearing friction CASE [--speeds 500,5000,15000rpm] [--set k=v] [-o OUT.nc]`` of a deep-groove case
    (``case``: loaded by the CLI with the ``--set`` overrides)."""
    from hsbearing.results import write_netcdf

    speeds = parse_speeds(args.speeds or "500,5000,15000rpm")
    ds = friction_torque(case, speeds)
    print(f"case {case.name}: Fa = {abs(case.operating.axial_load):g} N, Fr = {math.hypot(case.operating.radial_load, case.operating.radial_load_z):g} N, "
          f"law = {case.friction.law}" + (f", nu = {case.lubricant.kinematic_viscosity * 1e6:g} mm^2/s"
                                          if case.lubricant.kinematic_viscosity else ""))
    cols = [("n [r/min]", None), ("mu [-]", "sliding_coefficient"), ("M_s [N mm]", "spinning_torque"),
            ("M_r [N mm]", "rotation_sliding_torque"), ("M_d [N mm]", "orbital_sliding_torque"),
            ("M_sl [N mm]", "sliding_torque"), ("SKF M_sl [N mm]", "skf_sliding_torque"),
            ("SKF M_rr [N mm]", "skf_rolling_torque"), ("SKF M_drag [N mm]", "skf_drag_torque"),
            ("SKF M [N mm]", "skf_total_torque")]
    print("torques in N mm")
    print("  ".join(f"{h:>17s}" for h, _ in cols))
    for i, wi in enumerate(ds["speed"].values):
        row = [f"{wi * 60 / (2 * math.pi):17.0f}"]
        for _, name in cols[1:]:
            v = float(ds[name].values[i])
            row.append(f"{v:17.4f}" if name.endswith("coefficient") else f"{v * 1e3:17.4f}")
        print("  ".join(row))
    if args.output:
        write_netcdf(ds, args.output)
        print(f"archive: {args.output}")
    return 0
