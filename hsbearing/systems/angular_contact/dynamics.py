"""Full high-speed ball-bearing dynamics (Zhang et al. 2016, Eqs. 5-21) integrated by CVODE BDF.

:func:`build_model` turns a case into a :class:`DynamicModel` (parameters,
initial state from the quasi-static solution, compiled ``rhs`` and arrowhead
``jac``); :func:`simulate` integrates it with :func:`hsbearing.solvers.cvode.integrate`
and returns the run Dataset over ``time`` and ``ball``.

The model, every term with its source and every regularisation: docs/dynamics.md.
State layout: :mod:`hsbearing.models.ball_bearing.state`.
"""

from __future__ import annotations

import math
import time as _time
from dataclasses import dataclass, field

import numpy as np

from hsbearing import results
from hsbearing.errors import Interrupted, SolverError
from hsbearing.models import hertz
from hsbearing.models.ball_bearing import kernel as K
from hsbearing.models.ball_bearing import kernel_io as kio
from hsbearing.models.ball_bearing.ball import strip_load_weights
from hsbearing.models.ball_bearing.drag import (
    ball_drag_coefficient,
    cavity_oil_fraction,
    mixture_density,
    mixture_viscosity,
)
from hsbearing.models.ball_bearing.state import StateLayout
from hsbearing.models.geometry import curvature_radii, derive
from hsbearing.systems.angular_contact.oil_properties import inlet_beta as _inlet_beta
from hsbearing.systems.angular_contact.oil_properties import oil_conductivity as _oil_conductivity

__all__ = ["DynamicModel", "build_model", "simulate", "MODEL_DEFAULTS", "SOLVER_SETTINGS", "LINEAR_SOLVERS",
           "arrowhead_structure", "mechanical_energy", "thermal_cage_film_factors", "thermal_film_attrs"]

from hsbearing.systems.angular_contact.balances import mechanical_energy  # noqa: E402  (defined there; no import circle)

#: Model constants not in the case file (documented in docs/dynamics.md, overridable by build_model kwargs).
MODEL_DEFAULTS = {
    "quadrature_points": 5,  # Gauss-Legendre strips across the contact ellipse
    "contact_damping_ratio": 0.1,  # ball/race EHL contact damping, fraction of critical (per-contact, ball mass)
    "slip_eps": 1e-4,  # m/s, regularisation of |slip| in the traction direction
    "rolling_eps": 1e-3,  # m/s, regularisation of |U|
    "pocket_film_min": 0.5e-6,  # m, pocket film floor h_c (composite roughness ball/polyamide, docs/pocket.md)
    "pocket_stations": 16,  # stations around the pocket wall (models/ball_bearing/pocket.py; 0.3 % of the film load)
    "pocket_v0": 0.01,  # m/s, Coulomb regularisation of the pocket friction
    "drag_coefficient": None,  # C_D of the ball drag; None: the sphere's C_D(Re) at the initial orbital speed (models/ball_bearing/drag.py)
    "drag_v0": 0.01,  # m/s
    "land_length": None,  # m, width of each guide-land film (None: the case's lands, geometry.guide_lands)
    "land_eps_max": 0.95,  # saturation of the guide-land eccentricity ratio
    "land_contact_K": 6e9,  # N/m^1.5, elastic rub of the cage on the land beyond the clearance
    "land_offset_eps": 1e-9,  # m, regularisation of the cage-axis offset from the land centre (film direction at 0)
    "gravity": 9.81,  # m/s^2 along -Y (horizontal shaft); 0 switches it off
}

#: CVODE optional inputs used by :func:`simulate` (docs/dynamics.md, "Newton matrix reuse"):
#: rebuild the Newton matrix I - gamma J (one dense LU) at most every 50 steps instead of CVODE's 20, and
#: re-evaluate the Jacobian at most every 200 steps instead of 51.  Neither changes what a step must satisfy
#: (the same local error test, the same Newton convergence test): the corrector converges in ~1.1 iterations
#: per step with either, and CVODE still refreshes both at once on a convergence failure or a large change
#: of gamma.  Applied when CVODE's solver memory can be reached (``counters_available``), else CVODE's defaults.
SOLVER_SETTINGS = {"LSetupFrequency": 50, "JacEvalFrequency": 200}

#: Linear solvers of CVODE's Newton iteration that :func:`simulate` accepts (``linear_solver=``): SUNDIALS'
#: dense LU or the arrowhead block LU of :mod:`hsbearing.solvers.arrowhead` (the default where it can be installed,
#: :func:`hsbearing.solvers.cvode.arrowhead_available`; measured in docs/dynamics.md, "Linear algebra").
LINEAR_SOLVERS = ("dense", "arrowhead")


def arrowhead_structure(layout):
    """Arrowhead structure of the model's Jacobian: one block per ball (its 9 states, strided by Z in the state
    vector), the cage and inner-ring states (22) as the border.

    Balls touch the rings and the cage, never each other, so a ball's derivatives depend on its own states and
    on the cage and ring states only; ``tests/solvers/test_arrowhead.py`` checks this against a column-by-column
    finite-difference Jacobian of the kernel (no entry outside the structure) and derives the same blocks from
    that pattern (:func:`hsbearing.solvers.arrowhead.structure_from_pattern`).
    """
    from hsbearing.solvers.arrowhead import ArrowheadStructure

    Z = layout.Z
    nq = layout.n_ball // Z
    blocks = [np.arange(nq) * Z + j for j in range(Z)]
    return ArrowheadStructure.from_blocks(layout.size, blocks, np.arange(layout.n_ball, layout.size))

for _n, _d, _u, _l in [
    ("cage_center_x", ("time",), "m", "cage mass-centre axial displacement along X"),
    ("cage_velocity_y", ("time",), "m/s", "cage mass-centre velocity along Y"),
    ("cage_velocity_z", ("time",), "m/s", "cage mass-centre velocity along Z"),
    ("cage_angle", ("time",), "rad", "cage rotation angle about X (unwrapped)"),
    ("cage_tilt_y", ("time",), "rad", "cage tilt about Y"),
    ("cage_tilt_z", ("time",), "rad", "cage tilt about Z"),
    ("ball_orbit_angle", ("time", "ball"), "rad", "ball orbital (azimuth) angle theta_b (unwrapped)"),
    ("inner_traction_rolling", ("time", "ball"), "N", "traction of the inner race on the ball, rolling (circumferential) component T_xi,i"),
    ("inner_traction_transverse", ("time", "ball"), "N", "traction of the inner race on the ball, transverse component T_eta,i"),
    ("outer_traction_rolling", ("time", "ball"), "N", "traction of the outer race on the ball, rolling component T_xi,o"),
    ("outer_traction_transverse", ("time", "ball"), "N", "traction of the outer race on the ball, transverse component T_eta,o"),
    ("inner_slide_roll_ratio", ("time", "ball"), "1", "slide-roll ratio at the inner contact centre (ball minus race, rolling direction, / U)"),
    ("outer_slide_roll_ratio", ("time", "ball"), "1", "slide-roll ratio at the outer contact centre (ball minus race, rolling direction, / U)"),
    ("inner_rolling_speed", ("time", "ball"), "m/s", "entrainment (rolling) speed U at the inner contact"),
    ("outer_rolling_speed", ("time", "ball"), "m/s", "entrainment (rolling) speed U at the outer contact"),
    ("inner_rolling_force", ("time", "ball"), "N", "EHL hydrodynamic rolling force F_R at the inner contact"),
    ("outer_rolling_force", ("time", "ball"), "N", "EHL hydrodynamic rolling force F_R at the outer contact"),
    ("ball_cage_force", ("time", "ball"), "N", "ball/cage-pocket force on the ball in the pocket plane Q_c (film + contact + friction)"),
    ("ball_cage_friction", ("time", "ball"), "N", "ball/cage-pocket sliding friction force P_S (magnitude)"),
    ("ball_drag_force", ("time", "ball"), "N", "drag of the air-oil mixture on the ball F_D (signed, circumferential)"),
    ("ball_cage_film_load", ("time", "ball"), "N", "ball/cage-pocket film: pressure integrated over the pocket wall (both sides)"),
    ("ball_cage_elastic_force", ("time", "ball"), "N", "ball/cage-pocket Hertz (solid) contact load"),
    ("ball_cage_film_power", ("time", "ball"), "W", "power dissipated in the ball/cage-pocket film (source pocket_film)"),
    ("ball_cage_boundary_power", ("time", "ball"), "W", "power dissipated by ball/cage-pocket boundary friction (source pocket_boundary)"),
    ("cage_land_force_y", ("time",), "N", "guide-land film force on the cage along Y"),
    ("cage_land_force_z", ("time",), "N", "guide-land film force on the cage along Z"),
    ("cage_land_moment", ("time",), "N*m", "guide-land friction moment on the cage M_cx"),
    ("inner_ring_friction_torque", ("time",), "N*m", "DEPRECATED, use drive_torque: moment about X of the ball contact actions on the inner ring (= -drive_torque for an untilted ring without external moment)"),
]:
    results.register(_n, _d, _u, _l)


@dataclass
class DynamicModel:
    """A compiled dynamic model of one case: ``y0``, ``rhs(t, y, ydot)``, ``jac(t, y, ydot, JJ)``, ``state_names``."""

    case: object
    layout: StateLayout
    P: np.ndarray  #: kernel parameter record (hsbearing.models.ball_bearing.kernel_io.PARAM_DTYPE, shape (1,))
    qu: np.ndarray
    qw: np.ndarray
    y0: np.ndarray
    hscale: np.ndarray
    info: dict = field(default_factory=dict)

    def __post_init__(self):
        Z = self.layout.Z
        self._contrib = np.zeros((Z, K.N_CONTRIB))
        self._aux = np.zeros((Z, K.N_AUX))
        self._csum = np.zeros(K.N_CONTRIB)
        self._gaux = np.zeros(K.N_GAUX)
        self._work = np.zeros(4 * self.layout.size)

    def param(self, name: str):
        """Value of the kernel parameter ``name`` (hsbearing.models.ball_bearing.kernel_io.PARAMETERS)."""
        return kio.get(self.P, name)

    @property
    def state_names(self) -> list[str]:
        return self.layout.state_names

    def rhs(self, t, y, ydot):
        """In-place right-hand side (compiled kernel)."""
        K.rhs_kernel(y, self.P, self.qu, self.qw, ydot, self._contrib, self._aux, False, self._csum, self._gaux)

    def jac(self, t, y, ydot, JJ):
        """Dense Jacobian by the arrowhead-structured finite differences (compiled)."""
        K.jac_kernel(y, self.P, self.qu, self.qw, JJ, self.hscale, self._work)

    def f(self, y):
        """Convenience: ``rhs`` returning a new array."""
        out = np.empty_like(y)
        self.rhs(0.0, np.ascontiguousarray(y, dtype=float), out)
        return out

    def outputs(self, y):
        """Per-ball and global auxiliary quantities at state ``y``: (aux (Z, N_AUX), gaux (N_GAUX,))."""
        ydot = np.empty(self.layout.size)
        aux = np.zeros((self.layout.Z, K.N_AUX))
        gaux = np.zeros(K.N_GAUX)
        K.rhs_kernel(np.ascontiguousarray(y, dtype=float), self.P, self.qu, self.qw, ydot,
                     np.zeros((self.layout.Z, K.N_CONTRIB)), aux, True, np.zeros(K.N_CONTRIB), gaux)
        return aux, gaux


def _oil(case):
    from hsbearing.models import ehl, traction

    # one precedence rule for the inlet viscosity, shared with the quasi-static solver (which builds y0)
    lub = ehl.lubricant_parameters(case)
    return lub["eta"], lub["alpha"], traction.law_id(case.lubricant.oil, case.lubricant.traction_law)


def traction_values(case, alpha) -> dict:
    """Kernel parameters of the oil-independent traction laws (docs/traction.md, "Physical model"):
    tau0, Lambda, G of the physical model at the case temperature (the lubricant file's, else the defaults of
    :class:`hsbearing.models.traction.eyring.EyringParameters` with the oil's alpha) and c_A .. c_D of the
    "user" law (the lubricant file's coefficients; zeros when the case uses another law)."""
    from hsbearing.models.traction import eyring

    d = getattr(case.lubricant, "definition", None)
    params = getattr(d, "eyring", None) or eyring.EyringParameters()
    tau0, Lam, G = params.at(case.lubricant.temperature, alpha)
    A, B, C, D = getattr(d, "coefficients", None) or (0.0, 0.0, 0.0, 0.0)
    return dict(tau0=tau0, Lambda=Lam, G=G, c_A=A, c_B=B, c_C=C, c_D=D)


def thermal_cage_film_factors(case, walls: dict, race_temperatures=None) -> dict:
    """Thermal factors eta_eff / eta_film of the guide-land and pocket films for ``run --thermal``: those of
    ``hsbearing friction --thermal`` for the same case (:func:`hsbearing.systems.angular_contact.cage_films.film_factors`
    at the quasi-static state of the isothermal model, each film between its walls' node temperatures ``walls``,
    keys ``inner_ring``, ``outer_ring``, ``balls``, ``cage``; the Couette film law
    :func:`hsbearing.models.ball_bearing.films.thermal_couette_film`).  1 with ``friction.thermal_films = "off"`` or
    without the film.  Returns film_factors' dict ({"land": {...}, "pocket": {...}}): the film temperature is frozen
    at the quasi-static state for the run (docs/power_loss.md, "Thermal cage films")."""
    from hsbearing.systems.angular_contact.cage_films import film_factors

    m = build_model(case, race_temperatures=race_temperatures)
    return film_factors(case, m, walls)


def thermal_film_attrs(ff: dict, case) -> dict:
    """Run attrs of the cage films' thermal factors ``ff`` (:func:`thermal_cage_film_factors`): the two factors, the
    film temperatures and the rule; :func:`continue_run` rebuilds the model with the factors."""
    on = case.friction.thermal_films == "on"
    fl, fp = float(ff["land"]["factor"]), float(ff["pocket"]["factor"])
    rule = ("the kernel's guide-land film viscosity times thermal_guide_land_film_factor, the pocket films' times "
            "thermal_pocket_film_factor: eta_eff / eta_film of the Couette film between its walls' node temperatures "
            "(guide land: cage and guiding ring; pocket: balls and cage) at the quasi-static state, as hsbearing "
            "friction --thermal (models/ball_bearing/films.py thermal_couette_film); the film temperature is frozen at "
            "that state for the whole run, not updated with the whirling cage's instantaneous sliding"
            if on else "friction.thermal_films = off: the guide-land and pocket films isothermal (factors 1)")
    nan = float("nan")
    return {"thermal_cage_film_rule": rule, "thermal_guide_land_film_factor": fl, "thermal_pocket_film_factor": fp,
            "thermal_guide_land_film_temperature": float(ff["land"].get("T_mean", nan)),
            "thermal_pocket_film_temperature": float(ff["pocket"].get("T_mean", nan))}


def race_oil_values(case, T=None, suffix: str = "") -> dict:
    """Kernel parameters of one race's contact inlet oil at temperature ``T`` [K] (None: lubricant.temperature):
    eta_in, alpha, beta_T, T_K, tau0, Lambda, G, their names ending in ``suffix`` ("" the inner race's fields,
    "_o" the outer race's, kernel_io ``outer_oil``).  The same precedence rules as every other temperature of the
    case (:func:`_oil`, :func:`_inlet_beta`, :func:`traction_values`), through the case at ``T``."""
    if T is not None:
        case = case.with_overrides(**{"lubricant.temperature": f"{float(T)!r} K"})
    eta, alpha, _ = _oil(case)
    tv = traction_values(case, alpha)
    vals = dict(eta_in=eta, alpha=alpha, beta_T=_inlet_beta(case), T_K=case.lubricant.temperature,
                tau0=tv["tau0"], Lambda=tv["Lambda"], G=tv["G"])
    return {k + suffix: v for k, v in vals.items()}


def build_model(case, *, friction: bool = True, damping: bool = True, ehl_rolling: bool = True,
                drag: bool = True, initial: str = "quasistatic", race_temperatures=None, cage_film_factors=None,
                **options) -> DynamicModel:
    """Build the compiled dynamic model of ``case``.

    Parameters
    ----------
    case : hsbearing.case.Case (angular_contact or deep_groove)
    friction : traction, pocket friction, guide-land friction moment (False: frictionless)
    damping : contact damping, squeeze and guide-land films (False: conservative contacts; this also
        switches off the dissipative EHL rolling force, whatever ``ehl_rolling`` says)
    ehl_rolling : EHL rolling force F_R (and F_H)
    drag : air-oil drag F_D on the balls
    initial : "quasistatic" (initial state from :func:`hsbearing.systems.angular_contact.quasistatic.solve_case`)
        or "nominal" (balls on the pitch circle at the free contact angle, cage at the epicyclic speed)
    race_temperatures : (T_inner, T_outer) [K], the contact inlet temperatures of the inner and outer race contacts:
        each race's inlet viscosity, its slope beta_T, alpha, the traction law's temperature and the physical model's
        tau0, Lambda, G at its own temperature (:func:`race_oil_values`); None: both at lubricant.temperature
        (``hsbearing friction/run --thermal`` give (T_ir + T_b)/2 and (T_or + T_b)/2).  The quasi-static initial
        state and the drag stay at lubricant.temperature.
    cage_film_factors : (f_land, f_pocket), the thermal factors eta_eff / eta_film multiplying the guide-land and the
        pocket film viscosity eta_film (constants of the run: the film temperature frozen at the quasi-static state,
        :func:`thermal_cage_film_factors`; ``hsbearing run --thermal``); None: (1, 1), the isothermal films at
        lubricant.temperature.
    **options : overrides of :data:`MODEL_DEFAULTS`
    """
    from hsbearing.case import CaseError

    unknown = set(options) - set(MODEL_DEFAULTS)
    if unknown:
        raise TypeError(f"unknown model option(s): {', '.join(sorted(unknown))}")
    opt = dict(MODEL_DEFAULTS, **options)
    g = derive(case)
    cg = case.cage
    for key, val in (("cage.outside_diameter", cg.outside_diameter), ("cage.width", cg.width),
                     ("cage.bore_diameter", cg.bore_diameter)):
        if val is None:
            raise CaseError(case.source, key, "required by the dynamic model")
    if not math.isfinite(g.pocket_clearance) or g.pocket_clearance <= 0:
        raise CaseError(case.source, "cage.pocket_diameter", "the dynamic model needs a pocket clearance > 0")
    lands = _guide_lands(case, opt["land_length"])
    Z, D, dm, fi, fo, a0 = g.Z, g.D, g.dm, g.fi, g.fo, g.alpha0
    mb, Ib = g.ball_mass, g.ball_inertia
    mat = case.materials
    Rxi, Ryi, Rxo, Ryo = (float(v) for v in curvature_radii(D, dm, a0, fi, fo))
    ci = hertz.point_contact(Rxi, Ryi, 1.0, mat.ball.elastic_modulus, mat.ball.poisson_ratio,
                             mat.races.elastic_modulus, mat.races.poisson_ratio)
    co = hertz.point_contact(Rxo, Ryo, 1.0, mat.ball.elastic_modulus, mat.ball.poisson_ratio,
                             mat.races.elastic_modulus, mat.races.poisson_ratio)
    Ep = float(hertz.reduced_modulus(mat.ball.elastic_modulus, mat.ball.poisson_ratio,
                                     mat.races.elastic_modulus, mat.races.poisson_ratio))
    # ball in the cylindrical pocket: ball radius against the (concave) pocket radius in the pocket plane,
    # ball radius against a straight line along the pocket axis
    Rb, Rp = 0.5 * D, 0.5 * (D + 2.0 * g.pocket_clearance)
    Rconf = 1.0 / (1.0 / Rb - 1.0 / Rp)
    cc = hertz.point_contact(Rb, Rconf, 1.0, mat.ball.elastic_modulus, mat.ball.poisson_ratio,
                             mat.cage.elastic_modulus, mat.cage.poisson_ratio)
    eta, alpha, law = _oil(case)
    f_land, f_pocket = (1.0, 1.0) if cage_film_factors is None else (float(f) for f in cage_film_factors)
    if not (math.isfinite(f_land) and f_land > 0 and math.isfinite(f_pocket) and f_pocket > 0):
        raise ValueError(f"cage_film_factors must be finite and positive, got {cage_film_factors!r}")
    op = case.operating
    zeta = opt["contact_damping_ratio"]
    qu, qw = strip_load_weights(opt["quadrature_points"])
    layout = StateLayout(Z)
    y0, info = initial_state(case, layout, g, kind=initial)
    # ball drag: mixture of the cavity, and C_D at the orbital speed of the initial state (one value per case)
    X, X_source = cavity_oil_fraction(case.lubricant.oil_volume_fraction, case.lubricant.oil_flow_rate,
                                      op.inner_speed - op.outer_speed, dm, case.lubricant.lubrication)
    rho_e, mu_e = mixture_density(case.lubricant.density, X), mixture_viscosity(eta, X)
    v_orbit = float(y0[layout.cage("phidot_c")]) * 0.5 * dm  # the balls start at the cage speed
    C_D, Re_D = ball_drag_coefficient(rho_e, mu_e, v_orbit, D)
    if opt["drag_coefficient"] is not None:
        C_D = float(opt["drag_coefficient"])
    # every kernel parameter, by name (declared with units in hsbearing/models/ball_bearing/kernel_io.py)
    vals = dict(
        # balls
        Z=Z, D=D, m_b=mb, I_b=Ib, dm=dm,
        # race contacts
        rho_i=0.5 * dm + (fi - 0.5) * D * math.cos(a0), g_i=(fi - 0.5) * D * math.sin(a0), off_i=(fi - 0.5) * D,
        rho_o=0.5 * dm - (fo - 0.5) * D * math.cos(a0), g_o=-(fo - 0.5) * D * math.sin(a0), off_o=(fo - 0.5) * D,
        K_i=float(ci.K), K_o=float(co.K),
        cd_i=2.0 * zeta * math.sqrt(1.5 * float(ci.K) * mb), cd_o=2.0 * zeta * math.sqrt(1.5 * float(co.K) * mb),
        acoef_i=float(ci.a), acoef_o=float(co.a), Rx_i=Rxi, Rx_o=Rxo,
        k_i=float(ci.ellipticity), k_o=float(co.ellipticity), Ep=Ep,
        omega_i=op.inner_speed, omega_o=op.outer_speed,
        # lubricant and traction law
        eta_in=eta, alpha=alpha, eta_film=eta, land_film_factor=f_land, pocket_film_factor=f_pocket, beta_T=_inlet_beta(case), K_oil=_oil_conductivity(case),
        law_id=law, T_K=case.lubricant.temperature, U_eps=opt["rolling_eps"], s_eps=opt["slip_eps"],
        **traction_values(case, alpha),
        # pocket
        c_p=g.pocket_clearance, K_c=float(cc.K), h_min=opt["pocket_film_min"],
        mu_c=case.friction.cage_coefficient, v0_c=opt["pocket_v0"],
        R_bore_c=0.5 * cg.bore_diameter, R_out_c=0.5 * cg.outside_diameter, n_pocket=opt["pocket_stations"],
        # drag
        rho_e=rho_e, C_D=C_D, v0_D=opt["drag_v0"],
        # cage body
        m_c=g.cage_mass, Ip_c=g.cage_axial_inertia, Id_c=g.cage_diametral_inertia,
        # guide lands (a ball-piloted cage has none: radius nan, clearance 1 m so nothing divides by 0)
        guide=kio.GUIDANCE[lands.guidance], n_land=lands.count,
        R_land=lands.radius, L_land=lands.width, c_land=lands.clearance,
        a_land=abs(lands.offsets[0]) if lands.count else 0.0,
        eps_max=opt["land_eps_max"], K_land=opt["land_contact_K"], offset_eps=opt["land_offset_eps"],
        # inner ring body and loads
        m_i=g.inner_ring_mass, Ip_i=g.inner_ring_axial_inertia, Id_i=g.inner_ring_diametral_inertia,
        F_x=op.axial_load, F_y=op.radial_load, F_z=op.radial_load_z, M_y=op.moment_y, M_z=op.moment_z,
        # environment and switches
        grav=opt["gravity"],
        friction=bool(friction), damping=bool(damping), ehl_rolling=bool(ehl_rolling and damping),
        drag=bool(drag and friction), inlet_heating=case.friction.inlet_heating == "on",
    )
    # the outer race's inlet oil (kernel_io outer_oil): the inner race's values, both races at lubricant.temperature
    vals.update({f"{k}_o": vals[k] for k in ("eta_in", "alpha", "beta_T", "T_K", "tau0", "Lambda", "G")})
    if race_temperatures is not None:  # each race's contacts at its own inlet temperature
        T_in, T_out = (float(t) for t in race_temperatures)
        vals.update(race_oil_values(case, T_in, ""))
        vals.update(race_oil_values(case, T_out, "_o"))
    p = kio.pack(vals)
    for name in ("m_c", "Ip_c", "Id_c", "m_i", "Ip_i", "Id_i"):
        if not (math.isfinite(vals[name]) and vals[name] > 0):
            raise CaseError(case.source, "cage" if name.endswith("_c") else "bearing",
                            f"cannot derive {name} (give the masses/inertias or the dimensions)")
    hscale = _typical_scales(layout, case)
    info.update(guide_lands=lands, options=opt, race_temperatures=race_temperatures, cage_film_factors=(f_land, f_pocket),
                friction=friction, damping=damping,
                ehl_rolling=ehl_rolling, drag=drag,
                oil_viscosity=eta, cavity_oil_fraction=X, cavity_oil_fraction_source=X_source, drag_density=rho_e,
                drag_viscosity=mu_e, drag_orbital_speed=v_orbit, drag_reynolds_number=Re_D, drag_coefficient=C_D,
                contact_K_inner=float(ci.K), contact_K_outer=float(co.K), pocket_K=float(cc.K))
    return DynamicModel(case=case, layout=layout, P=p, qu=np.ascontiguousarray(qu), qw=np.ascontiguousarray(qw),
                        y0=y0, hscale=hscale, info=info)


def _guide_lands(case, land_length=None):
    """The case's guide lands (:func:`hsbearing.models.geometry.guide_lands`), checked for the dynamic model.

    ``land_length`` (model option) replaces the width of each land (e.g. ``land_length=11e-3`` with
    ``cage.guide_land_count = 1``: a single cage-wide film).
    """
    from dataclasses import replace

    from hsbearing.case import CaseError
    from hsbearing.models.geometry import GuideLandError, guide_lands

    try:
        gl = guide_lands(case)
    except GuideLandError as exc:
        raise CaseError(case.source, exc.key, exc.message) from None
    if gl.count == 0:
        return gl
    if land_length:  # the films keep reaching the cage faces
        L = float(land_length)
        a = 0.5 * max(case.cage.width - L, 0.0)
        gl = replace(gl, width=L, offsets=(-a, a) if gl.count == 2 else (a,))
    key = "bearing.outer_land_diameter" if gl.guidance == "outer_ring" else "bearing.inner_land_diameter"
    if not (math.isfinite(gl.clearance) and gl.clearance > 0 and math.isfinite(gl.radius)):
        raise CaseError(case.source, key, f"the dynamic model needs the land diameter of the {gl.guidance.replace('_', ' ')} "
                                          "guidance (a positive guide clearance)")
    if not (math.isfinite(gl.width) and gl.width > 0):
        raise CaseError(case.source, "cage.guide_land_width", "cannot derive the land width (give it, or the ring width and "
                                                               "conformity)")
    return gl


def _typical_scales(layout: StateLayout, case) -> np.ndarray:
    """Typical magnitudes of the states (finite-difference increments of the Jacobian)."""
    Z = layout.Z
    w = max(abs(case.operating.inner_speed), abs(case.operating.outer_speed), 1.0)
    s = np.empty(layout.size)
    per = [1e-5, 1e-5, 1e-3, 1e-3, 1e-3, 1.0, w, w, w]
    for k, v in enumerate(per):
        s[k * Z:(k + 1) * Z] = v
    s[layout.cage0:layout.cage0 + 6] = [1e-5, 1e-5, 1e-5, 1e-3, 1e-5, 1e-5]
    s[layout.cage0 + 6:layout.cage0 + 12] = [1e-3, 1e-3, 1e-3, 1.0, 1e-3, 1e-3]
    s[layout.ring0:layout.ring0 + 5] = [1e-5, 1e-5, 1e-5, 1e-5, 1e-5]
    s[layout.ring0 + 5:layout.ring0 + 10] = [1e-3, 1e-3, 1e-3, 1e-3, 1e-3]
    return s


def initial_state(case, layout: StateLayout, g, kind: str = "quasistatic"):
    """Initial state near equilibrium: from the quasi-static solution (default) or nominal kinematics."""
    from hsbearing.analysis.slip import theoretical_cage_speed

    Z = layout.Z
    info = {"initial": kind}
    if kind == "quasistatic":
        from hsbearing.systems.angular_contact import quasistatic

        qs = quasistatic.solve_case(case)
        # all balls start at the cage speed: the quasi-static race-control orbit speeds of lightly
        # loaded balls (up to +40 % under a radial load) would hit the pockets at once (~1 kN impacts)
        wc = float(qs["cage_speed"])
        ball = {
            "x_b": qs["ball_center_axial"].values, "u_b": qs["ball_center_radial"].values - 0.5 * g.dm,
            "theta_rel_b": np.zeros(Z), "thetadot_b": np.full(Z, wc),
            "omega_x": qs["ball_angular_velocity_x"].values, "omega_y": qs["ball_angular_velocity_y"].values,
            "omega_z": qs["ball_angular_velocity_z"].values,
        }
        ring = {"x_i": float(qs["inner_ring_axial_displacement"]),
                "y_i": float(qs["inner_ring_radial_displacement_y"]),
                "z_i": float(qs["inner_ring_radial_displacement_z"]),
                "tilt_y_i": float(qs["inner_ring_tilt_y"]), "tilt_z_i": float(qs["inner_ring_tilt_z"])}
        info["quasistatic"] = qs
        # cage axial position and tilts fitted (least squares) to the balls' axial positions, so that no
        # ball starts inside its pocket wall when the ring is tilted (radial or moment loads)
        az = 2.0 * np.pi * np.arange(Z) / Z
        A = np.column_stack([np.ones(Z), 0.5 * g.dm * np.sin(az), -0.5 * g.dm * np.cos(az)])
        xc, psy, psz = np.linalg.lstsq(A, ball["x_b"], rcond=None)[0]
        cage_fit = {"x_c": float(xc), "tilt_y_c": float(psy), "tilt_z_c": float(psz)}
    elif kind == "nominal":
        wc = theoretical_cage_speed(g, case.operating.inner_speed, case.operating.outer_speed)
        gamma = g.D * math.cos(g.alpha0) / g.dm
        # rolling without slip on the inner race, about the axis perpendicular to the free contact line
        # (cos a0, -sin a0) in the (x, r) plane, plus the orbital rotation wc about X (absolute omega)
        ws = -(case.operating.inner_speed - wc) * (1.0 - gamma) / (g.D / g.dm)
        ball = {"x_b": np.zeros(Z), "u_b": np.zeros(Z), "theta_rel_b": np.zeros(Z), "thetadot_b": np.full(Z, wc),
                "omega_x": np.full(Z, wc + ws * math.cos(g.alpha0)), "omega_y": np.full(Z, -ws * math.sin(g.alpha0)),
                "omega_z": np.zeros(Z)}
        ring = {}
        cage_fit = {}
    else:
        raise ValueError(f"unknown initial state kind {kind!r} (quasistatic, nominal)")
    cage = {"phi_c": 0.0, "phidot_c": wc, **cage_fit}
    return layout.pack(ball, cage, ring), info


def _time_grid(duration, dt):
    n = max(int(round(duration / dt)), 1)
    return np.linspace(0.0, n * dt, n + 1) if abs(n * dt - duration) < 1e-9 * duration else np.append(
        np.arange(n) * dt, duration)


def simulate(case, duration=None, progress: bool = False, *, model: DynamicModel | None = None,
             rtol=None, atol=None, jacobian: str = "arrowhead", wall_limit=None, annotate: bool = True,
             y0=None, t0: float = 0.0, cvode_settings: dict | None = None, stop: str | None = None,
             stop_rule: dict | None = None, linear_solver: str | None = None, **model_kwargs):
    """Integrate the dynamic model of ``case`` and return the run Dataset over ``time`` and ``ball``.

    Parameters
    ----------
    case : Case
    duration : simulated time [s] (float) or None for ``[simulation] duration``
    progress : tqdm progress bar of simulated time with ETA
    model : a prebuilt :class:`DynamicModel` (else :func:`build_model` with ``model_kwargs``)
    rtol, atol : override the case tolerances
    jacobian : "arrowhead" (compiled structured Jacobian) or "cvode" (CVODE's own finite differences)
    wall_limit : stop with a SolverError after this many wall seconds
    y0, t0 : start state and time [s] (default: the model's initial state at 0); used by
        :func:`continue_run` to extend an archived run from its ``final_state``
    cvode_settings : CVODE optional inputs (:data:`hsbearing.solvers.cvode.CVODE_SETTINGS`); None =
        :data:`SOLVER_SETTINGS` when reachable, ``{}`` = CVODE's own defaults
    stop : "duration" (integrate to ``duration``) or "converged" (stop when the cage-motion answer has
        converged, :mod:`hsbearing.analysis.stoprule`; ``duration`` is the upper bound); None = ``[simulation] stop``.
        A converged run records ``stop_rule``, ``stopped_at`` (NaN when it ran to the bound) and ``stop_reason``.
    stop_rule : overrides of :data:`hsbearing.analysis.stoprule.STOP_DEFAULTS`
    linear_solver : "arrowhead" (block LU + Schur complement on the Jacobian's ball blocks and cage/ring border,
        :func:`arrowhead_structure`; docs/dynamics.md, "Linear algebra") or "dense" (SUNDIALS' dense LU); None =
        "arrowhead" where it can be installed (:func:`hsbearing.solvers.cvode.arrowhead_available`), else "dense".
        With jacobian="cvode" always "dense".

    Raises
    ------
    SolverError with ``partial`` = the Dataset up to the failure (status "failed at t = ...").
    hsbearing.errors.Interrupted (a KeyboardInterrupt) on Ctrl-C, with ``partial`` = the Dataset up to
    the last output (status "interrupted at t = ...").
    """
    from hsbearing.solvers.cvode import arrowhead_available, counters_available, integrate

    if cvode_settings is None:
        cvode_settings = dict(SOLVER_SETTINGS) if counters_available() else {}
    if linear_solver is None:
        linear_solver = "arrowhead" if jacobian == "arrowhead" and arrowhead_available() else "dense"
    if linear_solver not in LINEAR_SOLVERS:
        raise ValueError(f"linear_solver must be one of {', '.join(LINEAR_SOLVERS)}, got {linear_solver!r}")
    if isinstance(duration, str):
        from hsbearing.case import parse_quantity

        duration = parse_quantity(duration, "time", source="duration", key="duration")
    sim = case.simulation
    duration = float(sim.duration if duration is None else duration)
    if not duration > 0:
        from hsbearing.case import CaseError

        raise CaseError(case.source, "simulation.duration", f"must be positive, got {duration!r}")
    from hsbearing import jit

    if progress:  # before the quasi-static start and the compilation; the bar then times integration only
        jit.compile_notice((K.rhs_kernel, K.jac_kernel), "the model")
    m = model or build_model(case, **model_kwargs)
    jit.warm_up(m.rhs, m.y0, m.jac if jacobian == "arrowhead" else None, extra=lambda: m.outputs(m.y0))
    rtol = float(sim.rtol if rtol is None else rtol)
    atol_v = m.layout.atol(float(sim.atol if atol is None else atol))
    t_eval = float(t0) + _time_grid(duration, min(sim.output_interval, duration))
    stop = getattr(sim, "stop", "duration") if stop is None else stop
    if stop not in ("duration", "converged"):
        raise ValueError(f"stop must be 'duration' or 'converged', got {stop!r}")
    monitor = _stop_monitor(m, float(t_eval[0]), float(t_eval[-1]), stop_rule) if stop == "converged" else None
    wall0 = _time.perf_counter()
    try:
        res = integrate(m.rhs, m.y0 if y0 is None else np.asarray(y0, dtype=float), t_eval, rtol=rtol, atol=atol_v,
                        jacfn=m.jac if jacobian == "arrowhead" else None, progress=progress,
                        progress_desc=f"{case.name}", wall_limit=wall_limit, cvode_settings=cvode_settings,
                        callback=monitor, linsolver=linear_solver,
                        structure=arrowhead_structure(m.layout) if linear_solver == "arrowhead" else None)
    except KeyboardInterrupt:  # an integrator that lets Ctrl-C through: nothing to keep
        raise Interrupted("interrupted before the first output") from None
    stats = dict(res.stats)
    stats["jacobian"] = "compiled arrowhead finite differences (31 evaluations)" if jacobian == "arrowhead" else stats["jacobian"]
    stats["total_wall_time"] = _time.perf_counter() - wall0
    interrupted = _is_interrupt(res.status)
    status = f"interrupted at t = {float(res.t[-1]):.6g} s" if interrupted else res.status
    ds = to_dataset(m, res.t, res.y, stats, status, annotate=annotate)
    ds = with_final_state(ds, m, res.y[-1], requested_end=float(t_eval[-1]))
    if monitor is not None:
        ds.attrs.update(monitor.attrs())
    if interrupted:
        raise Interrupted(status, partial=ds)
    if not res.success:
        raise SolverError(res.status, partial=ds)
    return ds


def _stop_monitor(m: DynamicModel, t_start: float, t_end: float, rule: dict | None):
    """The stop-rule callback of :func:`simulate` (``stop="converged"``): keeps the cage states of each output."""
    import xarray as xr

    from hsbearing.analysis import stoprule
    from hsbearing.models.geometry import derive

    L = m.layout
    names = ("y_c", "z_c", "ydot_c", "zdot_c", "phi_c", "phidot_c")
    idx = np.array([L.cage(n) for n in names])
    vars_ = ("cage_center_y", "cage_center_z", "cage_velocity_y", "cage_velocity_z", "cage_angle", "cage_speed")

    def to_prefix(t, rows):
        t = np.asarray(t) - t_start  # the rule's times are since the start of this run
        return xr.Dataset({v: ("time", rows[:, k]) for k, v in enumerate(vars_)}, coords={"time": t})

    clearance = float(derive(m.case).guide_clearance)
    mon = stoprule.Monitor(to_prefix, t_end - t_start, m.case, rule, section=m.case.simulation.section,
                           clearance=clearance if math.isfinite(clearance) else None, keep=lambda y: y[idx].copy(),
                           t_start=t_start)
    return mon


# ----------------------------------------------------------------------------- interrupt and continue
# (Ctrl-C keeps the partial run; ``hsbearing run --continue ARCHIVE.nc`` extends it)

results.register("final_state", ("state",), "SI",
                 "state vector at the last output time, SI unit of each component (restart point of run --continue)")
results.register("state", ("state",), "1", "state-vector component (hsbearing.models.ball_bearing.state layout)")


def _is_interrupt(status: str) -> bool:
    """The integrator's status for a Ctrl-C (``solvers.cvode``: "failed at t = ...: interrupted")."""
    return status.rstrip().endswith("interrupted")


def with_final_state(ds, model: DynamicModel, y_last, *, requested_end: float | None = None):
    """Add ``final_state`` (dim ``state``, named components) and ``requested_duration`` to a run Dataset."""
    import xarray as xr

    ds = ds.copy()
    v = results.VARIABLES["final_state"]
    ds["final_state"] = xr.Variable(("state",), np.asarray(y_last, dtype=np.float64),
                                    attrs={"units": v.units, "long_name": v.long_name})
    c = results.VARIABLES["state"]
    ds = ds.assign_coords(state=xr.Variable(("state",), np.array(model.state_names, dtype=object),
                                            attrs={"long_name": c.long_name}))
    if requested_end is not None:
        ds.attrs["requested_duration"] = float(requested_end)
    return ds


def continue_run(previous, duration=None, progress: bool = False, *, source: str = "--continue", **kwargs):
    """Extend an archived dynamic run from its ``final_state``; return the whole run (old + new samples).

    Parameters
    ----------
    previous : xarray.Dataset of a run written by :func:`simulate` (``final_state``, ``case_toml``)
    duration : simulated time to add [s] (float or unit string); None = up to the run's
        ``requested_duration`` (finishes an interrupted run)
    source : name used in error messages (the archive path)

    The integrator restarts at the stored state (BDF history is not stored), so the continued
    trajectory equals an uninterrupted one only to the integration tolerance at the joint.
    """
    import xarray as xr

    from hsbearing.case import CaseError, check_output_samples, loads_case, parse_quantity

    if "final_state" not in previous or "case_toml" not in previous.attrs or "time" not in previous.dims:
        raise CaseError(source, "final_state", "not a dynamic run that can be continued (no final_state stored)")
    if previous.attrs.get("model") != "zhang2016_dynamics":
        raise CaseError(source, "model", f"runs of model {previous.attrs.get('model')!r} cannot be continued")
    case = loads_case(previous.attrs["case_toml"], source)
    t_last = float(previous["time"].values[-1])
    if isinstance(duration, str):
        duration = parse_quantity(duration, "time", source="--duration", key="duration")
    if duration is None:
        end = float(previous.attrs.get("requested_duration", t_last))
        duration = end - t_last
        if not duration > 1e-12 * max(end, 1.0):
            raise CaseError(source, None, f"the run is complete (t = {t_last:.6g} s); give --duration to extend it")
    if not duration > 0:
        raise CaseError("--duration", "duration", f"must be positive, got {duration!r}")
    check_output_samples(case, duration, source="--duration", key="duration")
    # a run --thermal archive: each race's contacts at the inlet temperatures it ran with (attrs; absent: lubricant.temperature)
    keys = ("thermal_inner_contact_inlet_temperature", "thermal_outer_contact_inlet_temperature")
    races = tuple(float(previous.attrs[k]) for k in keys) if all(k in previous.attrs for k in keys) else None
    # and its guide-land and pocket films at the thermal factors it ran with (attrs; absent: isothermal, 1)
    fkeys = ("thermal_guide_land_film_factor", "thermal_pocket_film_factor")
    films = tuple(float(previous.attrs[k]) for k in fkeys) if all(k in previous.attrs for k in fkeys) else None
    m = build_model(case, initial="nominal", race_temperatures=races,
                    cage_film_factors=films)  # the start state comes from the archive
    names = list(previous["state"].values) if "state" in previous.coords else None
    if names is not None and [str(n) for n in names] != list(m.state_names):
        raise CaseError(source, "final_state", "the stored state layout differs from this hsbearing's model")
    y0 = np.asarray(previous["final_state"].values, dtype=float)
    try:
        kwargs.setdefault("stop", "duration")  # a continuation runs its whole extension (a stopped run included)
        new = simulate(case, duration=duration, progress=progress, model=m, y0=y0, t0=t_last, annotate=False, **kwargs)
        err = None
    except (SolverError, Interrupted) as exc:
        new, err = exc.partial, exc
        if new is None:
            raise
    timed = [k for k, v in previous.data_vars.items() if "time" in v.dims]
    old = previous[timed]
    add = new[[k for k in timed if k in new]].isel(time=slice(1, None))  # the first sample is the old last one
    both = xr.concat([old, add], dim="time", data_vars="all", coords="minimal", compat="override", join="override")
    both["final_state"] = new["final_state"]
    for k, v in new.data_vars.items():  # per-run constants of the model (no time dim), if any
        if k not in both and "time" not in v.dims:
            both[k] = v
    attrs = dict(previous.attrs)
    for k in ("classification", "classification_confidence", "classification_reason", "classification_details",
              "classifier_version", "stopped_at", "stop_reason", "stop_checks", "stop_check_wall_time"):
        attrs.pop(k, None)
    if "stop_rule" in attrs:
        attrs["stop_rule"] = f"{attrs['stop_rule']}; then continued to the requested duration"
    for k, v in new.attrs.items():
        if k.startswith("solver_") and k in attrs and isinstance(v, (int, float)) and k not in ("solver_rtol", "solver_atol") \
                and isinstance(attrs[k], (int, float, np.number)):
            attrs[k] = attrs[k] + v  # steps, evaluations and wall time add up over the pieces
        elif k in ("status", "requested_duration", "created", "hsbearing_version") or k not in attrs:
            attrs[k] = v
    attrs["continued"] = (str(previous.attrs.get("continued", "")) + f" t = {t_last:.6g} s;").strip()
    both.attrs = attrs
    if both.sizes["time"] >= 8:
        try:
            from hsbearing.analysis import annotate as _annotate

            both = _annotate(both, case, section=case.simulation.section)
        except (ImportError, AttributeError):
            pass
    if err is not None:
        err.partial = both
        raise err
    return both


def to_dataset(model: DynamicModel, t, Y, stats, status="ok", annotate: bool = True):
    """Run Dataset from the trajectory (states and the auxiliary outputs re-evaluated at each output time)."""
    from hsbearing.analysis.slip import cage_slip_ratio, theoretical_cage_speed

    case = model.case
    L = model.layout
    u = L.unpack(Y)
    n = len(t)
    aux = np.zeros((n, L.Z, kio.N_AUX))
    gaux = np.zeros((n, kio.N_GAUX))
    for k in range(n):
        aux[k], gaux[k] = model.outputs(Y[k])
    A = kio.AUX_INDEX
    G = kio.GAUX_INDEX
    geom = derive(case)
    wth = theoretical_cage_speed(geom, case.operating.inner_speed, case.operating.outer_speed)
    # ball spin = magnitude of the ball's angular velocity relative to the orbiting (cage) frame, omega_R of
    # Harris (the frame turns at thetadot_b about X = the ball's x axis); the quasi-static dataset uses the same
    spin = np.sqrt((u["omega_x"] - u["thetadot_b"]) ** 2 + u["omega_y"] ** 2 + u["omega_z"] ** 2)
    # the kernel's outputs that are Dataset variables, by the one declaration (hsbearing/models/ball_bearing/kernel_io.py)
    data = {var: aux[..., A[col]] for var, col in kio.DATASET_BALL.items()}
    data.update({var: gaux[:, G[col]] for var, col in kio.DATASET_GLOBAL.items()})
    data.update({
        "cage_speed": u["phidot_c"], "cage_slip_ratio": cage_slip_ratio(u["phidot_c"], wth),
        "cage_center_x": u["x_c"], "cage_center_y": u["y_c"], "cage_center_z": u["z_c"],
        "cage_velocity_y": u["ydot_c"], "cage_velocity_z": u["zdot_c"], "cage_angle": u["phi_c"],
        "cage_tilt_y": u["tilt_y_c"], "cage_tilt_z": u["tilt_z_c"],
        "ball_orbit_speed": u["thetadot_b"], "ball_orbit_angle": L.ball_azimuth(Y), "ball_spin_speed": spin,
        "ball_angular_velocity_x": u["omega_x"], "ball_angular_velocity_y": u["omega_y"],
        "ball_angular_velocity_z": u["omega_z"],
        "ball_center_axial": u["x_b"], "ball_center_radial": L.ball_radius(Y, geom.dm),
        "inner_ring_axial_displacement": u["x_i"], "inner_ring_radial_displacement_y": u["y_i"],
        "inner_ring_radial_displacement_z": u["z_i"], "inner_ring_tilt_y": u["tilt_y_i"], "inner_ring_tilt_z": u["tilt_z_i"],
    })
    from hsbearing.systems.angular_contact import balances  # power loss by source, drive torque (registered there)

    data.update(balances.power_variables(aux, gaux, model.param("guide") == kio.GUIDE_OUTER_RING))
    # contact state per contact over time: spin-to-roll from the kernel, Hertz/EHL/lambda derived
    from hsbearing.systems.angular_contact import contact_state

    rb = L.ball_radius(Y, geom.dm)
    for side, col, w_race in (("inner", "spin_roll_i", case.operating.inner_speed),
                              ("outer", "spin_roll_o", case.operating.outer_speed)):
        data[f"{side}_spin_to_roll"] = contact_state.spin_to_roll_relative(
            aux[..., A[col]], data[f"{side}_contact_angle"], geom.D, rb, side, np.sign(w_race - u["thetadot_b"]))
    data.update(contact_state.contact_state_variables(case, data["inner_contact_load"], data["outer_contact_load"],
                                                      data["inner_contact_angle"], data["outer_contact_angle"],
                                                      data["inner_rolling_speed"], data["outer_rolling_speed"]))
    # per-ball derived quantities (forces, speeds, angles, ratios) are stored in single precision
    # (7 significant digits) to halve the archive; states that are positions stay double
    keep64 = {"ball_orbit_angle", "ball_center_axial", "ball_center_radial"}
    for name, arr in data.items():
        if name not in keep64 and np.ndim(arr) == 2:
            data[name] = np.asarray(arr, dtype=np.float32)
    import hsbearing.systems.angular_contact.quasistatic  # noqa: F401  (registers the shared ball/ring names)
    attrs = results.standard_attrs(
        case, status, model="zhang2016_dynamics", guide_clearance=geom.guide_clearance,
        pocket_clearance=geom.pocket_clearance, theoretical_cage_speed_nominal=wth,
        initial_state=model.info.get("initial"), friction=int(model.info["friction"]),
        damping=int(model.info["damping"]), model_options=model.info["options"],
        drag_law=(f"C_D {model.info['drag_coefficient']:.6g} at ball Reynolds number {model.info['drag_reynolds_number']:.6g} "
                  f"(initial orbital speed {model.info['drag_orbital_speed']:.6g} m/s); cavity oil fraction "
                  f"{model.info['cavity_oil_fraction']:.6g} ({model.info['cavity_oil_fraction_source']}); mixture density "
                  f"{model.info['drag_density']:.6g} kg/m^3 (models/ball_bearing/drag.py)"),
        state_layout="hsbearing.models.ball_bearing.state (state-major, 9 Z + 22)",
        precision="per-ball forces, speeds, angles and ratios float32; positions and cage/ring variables float64",
    )
    attrs.update(results.solver_attrs(stats))
    ds = results.make_dataset(data, coords={"time": np.asarray(t), "ball": np.arange(L.Z)}, attrs=attrs)
    env = [w for w in str(ds.attrs.get("warnings", "none")).split(" | ") if w and w != "none"]  # the case envelope
    ds.attrs["warnings"] = contact_state.format_warnings(env + contact_state.warnings_for(ds, case))
    if annotate and n >= 8:
        try:
            from hsbearing.analysis import annotate as _annotate

            ds = _annotate(ds, case, section=case.simulation.section)
        except (ImportError, AttributeError):  # analysis not available: the raw run is still complete
            pass
    return ds
