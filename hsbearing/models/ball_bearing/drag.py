"""Drag of the balls in the air-oil mixture of the bearing cavity (F_D of Zhang et al. 2016, Eq. 7).

References
----------
[1] Harris T. A., Kotzalas M. N., *Rolling Bearing Analysis*, 5th ed., Vol. 2
    (*Advanced Concepts of Bearing Technology*), Ch. 3/5: ball drag in the
    air-oil mixture F_D = (pi/32) C_D rho_e D^2 (d_m omega_m)^1.95.  The factor pi/32 is
    1/2 (pi D^2/4) (d_m omega_m / 2)^2 / (D^2 (d_m omega_m)^2): the sphere drag 1/2 C_D rho v^2 A at the
    ball-centre orbital speed v = d_m omega_m / 2.  The exponent 1.95 is NOT used here: with C_D taken
    from the sphere's drag curve at the ball Reynolds number ([4]), the speed dependence of C_D is already
    in C_D(Re), and by the definition of C_D the force is 1/2 C_D rho_e (pi D^2/4) v^2.  v^1.95 would
    multiply that by v^-0.05, a unit-dependent factor (SI: 0.88 at 14 m/s, 0.80 at 85 m/s; in in/s
    0.73-0.67) that lowered the drag by 12-21 % over the speeds of the cases (14-99 m/s) (docs/power_loss.md,
    "The drag law checked independently").
[2] Zhang W. et al., Chin. J. Aeronaut. 29 (2016), Eq. (7) (F_D).
[3] Parker R. J., *Comparison of predicted and experimental thermal performance of
    angular-contact ball bearings*, NASA TP-2275 (1984): an empirical oil content of the air-oil
    mixture in the cavity of a jet-lubricated bearing, in the form used here
    X = 1e5 W^0.37 / (n d_m^1.7), W oil flow [cm^3/min], n shaft speed [r/min], d_m pitch
    diameter [mm].  **UNVERIFIED**: neither TP-2275 nor a reproduction of
    the formula (Harris & Kotzalas Vol. 2; Pouly et al. 2010) could be read through this project's
    search tools; no public code implementing it was found either.  The form, the constant and
    the units are those of secondary recollection; in particular whether X is a fraction or a
    percentage was open.  It is read as a FRACTION, on physical evidence (docs/power_loss.md, "The cavity
    oil fraction: fraction or percent, decided"; tools/investigations/tp2275_cavity_oil_fraction.py).  For the 35-mm
    TP-2275 bearing at 28 000-72 000 r/min and 760 cm^3/min, read as a percent: (a) the oil's part of the
    computed heat is 2.0-2.3 %, so doubling the constant 1e5 changes the total by +2.3..2.5 % and removing the
    oil altogether by -2.2..-2.5 %, both inside the +-3 % scatter of the heat data the correlation was
    fitted to -- its constant and exponents could not have been determined; (b) the mass balance
    X V_free = Q tau gives the oil 0.09-0.65 ms in the bearing (0.05-0.15 cage revolutions, 1-2 ball passes)
    and a mean axial speed of 10-140 m/s, up to 4x the fastest supply jet (33 m/s at 0.5 MPa); (b') the drag
    spends on the oil 0.20-0.24 of m_dot v^2, the power that accelerates the supplied oil once to the ball
    orbital speed, i.e. three quarters of the oil would never meet a ball.  Read as a fraction: oil 69-71 %
    of the heat (+70 % / -34 % for 2x / 0.5x the constant), 9-65 ms = 5-15 cage revolutions, 0.1-1.4 m/s,
    22-24 m_dot v^2 (oil re-accelerated ~20 times in 80-230 ball passes).  The formula itself (form,
    constant, units) stays unverified.
[4] Clift R., Grace J. R., Weber M. E., *Bubbles, Drops, and Particles*, Academic Press (1978),
    Ch. 5, Table 5.2: the standard drag curve of a rigid sphere in a steady uniform stream as ten
    correlations in w = log10 Re over 0 < Re < ~1e7, including the drag crisis (3.38e5-4e5).
    Not read here in the book: the ten forms and constants are those of several independent
    public implementations that cite this table (e.g. the ``fluids`` library, ``drag.py``,
    ``Clift``), which agree with each other.  Checked in tests/models/test_drag_coefficient.py against
    the measured sphere drag of Roos & Willmarth, AIAA J. 9 (1971) 285 (tabulated in the
    ``sheardata`` collection, CC-BY-4.0) and against points read from Achenbach, J. Fluid
    Mech. 54 (1972) 565, Fig. 4 (through the crisis).
[5] The effective viscosity of the droplet-laden air (air continuous, oil dispersed): Einstein A.,
    Ann. Phys. 19 (1906) 289 and 34 (1911) 591 (mu = mu_c (1 + 5/2 phi) for dilute rigid spheres); Taylor G. I.,
    Proc. R. Soc. A 138 (1932) 41 (drops of viscosity ratio lambda: mu = mu_c (1 + phi (1 + 5/2 lambda) /
    (1 + lambda))); Hashin Z., Shtrikman S., J. Mech. Phys. Solids 11 (1963) 127 (bounds on the effective
    shear modulus of an isotropic two-phase body, here in the Stokes-flow analogue with incompressible
    phases).  The lower bound, attained by inclusions of the more viscous phase dispersed in the less
    viscous one, is mu_c + phi / (1 / (mu_d - mu_c) + 2 (1 - phi) / (5 mu_c)); it reduces to Einstein's
    result to first order in phi and to mu_d at phi = 1.  The volume-weighted mean X mu_oil + (1 - X) mu_air
    is the opposite (Voigt, upper) bound, the viscosity of layers sheared in parallel: for a mist it
    gives d mu / d phi = mu_oil - mu_air (~90 mu_air) at phi -> 0 against at most 5/2 mu_air (Einstein).
"""

from __future__ import annotations

import math

from numba import njit

from hsbearing.compile_cache import check_compile_cache

__all__ = ["mixture_density", "ball_drag_force", "parker_cavity_oil_fraction", "cavity_oil_fraction",
           "DEFAULT_OIL_FRACTION", "mixture_viscosity", "ball_reynolds_number", "AIR_VISCOSITY",
           "sphere_drag_coefficient", "ball_drag_coefficient", "RE_SUBCRITICAL_MAX"]

#: air density at the bearing temperature is small; 1.1 kg/m^3 (about 50-130 degC) is used.
AIR_DENSITY = 1.1

#: cavity oil fraction used when the case gives neither ``lubricant.oil_volume_fraction`` nor an
#: ``oil_flow_rate`` (the constant every earlier release used; not from a correlation).
DEFAULT_OIL_FRACTION = 0.05


def parker_cavity_oil_fraction(flow_rate: float, speed: float, pitch_diameter: float) -> float:
    """Oil volume fraction X of the bearing cavity of a jet-lubricated ball bearing ([3], UNVERIFIED) [-].

    X = 1e5 W^0.37 / (n d_m^1.7)  with W [cm^3/min], n [r/min], d_m [mm]  ([3]: form, constant and units
    not checked against TP-2275; X read as a fraction, not a percentage).

    Arguments in SI: ``flow_rate`` [m^3/s] (W = 6e7 flow_rate), ``speed`` [rad/s] of the inner ring
    relative to the outer (n = 30 |speed| / pi), ``pitch_diameter`` [m].  Zero flow gives 0 (dry
    cavity: air only); the result is capped at 1 (a flooded cavity); n = 0 with oil flowing gives 1.
    """
    if flow_rate < 0.0:
        raise ValueError("flow_rate must not be negative")
    if flow_rate == 0.0:
        return 0.0
    W = flow_rate * 6.0e7  # m^3/s -> cm^3/min
    n = abs(speed) * 30.0 / math.pi  # rad/s -> r/min
    if n == 0.0:
        return 1.0
    X = 1.0e5 * W**0.37 / (n * (pitch_diameter * 1.0e3) ** 1.7)  # [3]
    return min(X, 1.0)


def cavity_oil_fraction(oil_volume_fraction, oil_flow_rate, speed: float, pitch_diameter: float,
                        lubrication: str = "oil_jet") -> tuple[float, str]:
    """The cavity oil fraction the drag uses, and where it comes from: (X, source).

    - ``oil_volume_fraction`` given (not None): that value (an explicit override, any supply);
    - else ``oil_flow_rate`` given, ``lubrication`` oil_jet or oil_air (mist / air-oil): Parker's
      correlation :func:`parker_cavity_oil_fraction` ([3]);
    - else :data:`DEFAULT_OIL_FRACTION` (oil bath, grease, or no flow given: no correlation of
      these supplies is implemented; ``dry`` gives 0).
    Both the quasi-static power loss (``hsbearing friction``) and the dynamic model call this
    through :func:`hsbearing.systems.angular_contact.dynamics.build_model` (kernel parameter ``rho_e``).
    """
    if oil_volume_fraction is not None:
        return float(oil_volume_fraction), "lubricant.oil_volume_fraction"
    if lubrication == "dry":
        return 0.0, "lubrication = dry"
    if oil_flow_rate is not None and lubrication in ("oil_jet", "oil_air"):
        return (parker_cavity_oil_fraction(oil_flow_rate, speed, pitch_diameter),
                "Parker (NASA TP-2275) from oil_flow_rate -- source UNVERIFIED (form and units as recalled), "
                "X read as a fraction (decided on evidence), docs/power_loss.md")
    return DEFAULT_OIL_FRACTION, "default 0.05 (no oil_volume_fraction, no oil_flow_rate for a jet / air-oil supply)"


def mixture_density(oil_density: float, oil_volume_fraction: float, air_density: float = AIR_DENSITY) -> float:
    """Effective density of the air-oil mixture rho_e = X rho_oil + (1 - X) rho_air [kg/m^3] ([1])."""
    return oil_volume_fraction * oil_density + (1.0 - oil_volume_fraction) * air_density


#: dynamic viscosity of air at 50-130 degC [Pa s] (1.95e-5 .. 2.3e-5; 2.1e-5 used).
AIR_VISCOSITY = 2.1e-5


def mixture_viscosity(oil_viscosity: float, oil_volume_fraction: float, air_viscosity: float = AIR_VISCOSITY) -> float:
    """Effective viscosity of the air-oil mixture of the cavity, oil droplets dispersed in air [Pa s] ([5]).

    mu_e = mu_a + X / (1 / (mu_oil - mu_a) + 2 (1 - X) / (5 mu_a))   (Hashin-Shtrikman lower bound with
    incompressible phases, air the continuous phase); to first order in X this is Einstein's
    mu_a (1 + 5/2 X) for mu_oil >> mu_a and Taylor's drop-suspension viscosity for finite
    mu_oil / mu_a; X = 0 gives mu_a, X = 1 gives mu_oil.  Used for the ball Reynolds number only.
    Needs mu_oil >= mu_a (an oil less viscous than air is rejected).
    """
    X = oil_volume_fraction
    if not 0.0 <= X <= 1.0:
        raise ValueError("oil_volume_fraction must be within [0, 1]")
    if oil_viscosity < air_viscosity:
        raise ValueError("oil viscosity below that of air")
    if X == 0.0 or oil_viscosity == air_viscosity:
        return air_viscosity
    return air_viscosity + X / (1.0 / (oil_viscosity - air_viscosity) + 0.4 * (1.0 - X) / air_viscosity)  # [5]


def ball_reynolds_number(rho_e: float, v: float, D: float, mu_e: float) -> float:
    """Reynolds number of the ball in the mixture Re = rho_e |v| D / mu_e [-] (v: orbital speed of the
    ball centre relative to the mixture, taken at rest; D: ball diameter)."""
    return rho_e * abs(v) * D / mu_e


def sphere_drag_coefficient(Re: float) -> float:
    """Drag coefficient C_D(Re) of a smooth rigid sphere in a steady uniform stream ([4], Table 5.2).

    With w = log10 Re:

    ==================  ============================================
    Re < 0.01           C_D = 3/16 + 24/Re
    0.01 .. 20          C_D = 24/Re (1 + 0.1315 Re^(0.82 - 0.05 w))
    20 .. 260           C_D = 24/Re (1 + 0.1935 Re^0.6305)
    260 .. 1.5e3        log10 C_D = 1.6435 - 1.1242 w + 0.1558 w^2
    1.5e3 .. 1.2e4      log10 C_D = -2.4571 + 2.5558 w - 0.9295 w^2 + 0.1049 w^3
    1.2e4 .. 4.4e4      log10 C_D = -1.9181 + 0.6370 w - 0.0636 w^2
    4.4e4 .. 3.38e5     log10 C_D = -4.3390 + 1.5809 w - 0.1546 w^2
    3.38e5 .. 4e5       C_D = 29.78 - 5.3 w          (drag crisis)
    4e5 .. 1e6          C_D = 0.1 w - 0.49
    > 1e6               C_D = 0.19 - 8e4 / Re
    ==================  ============================================

    Re must be > 0.  The crisis (C_D 0.48 -> 0.07 between 3.4e5 and 4e5) is that of a smooth sphere
    in a low-turbulence stream; free-stream turbulence and roughness move it to lower Re
    (docs/power_loss.md, "The drag coefficient").
    """
    if not Re > 0.0:
        raise ValueError("Reynolds number must be > 0")
    w = math.log10(Re)
    if Re < 0.01:
        return 3.0 / 16.0 + 24.0 / Re
    if Re <= 20.0:
        return 24.0 / Re * (1.0 + 0.1315 * Re ** (0.82 - 0.05 * w))
    if Re <= 260.0:
        return 24.0 / Re * (1.0 + 0.1935 * Re**0.6305)
    if Re <= 1.5e3:
        return 10.0 ** (1.6435 - 1.1242 * w + 0.1558 * w * w)
    if Re <= 1.2e4:
        return 10.0 ** (-2.4571 + 2.5558 * w - 0.9295 * w * w + 0.1049 * w**3)
    if Re <= 4.4e4:
        return 10.0 ** (-1.9181 + 0.6370 * w - 0.0636 * w * w)
    if Re <= 3.38e5:
        return 10.0 ** (-4.3390 + 1.5809 * w - 0.1546 * w * w)
    if Re <= 4.0e5:
        return 29.78 - 5.3 * w
    if Re <= 1.0e6:
        return 0.1 * w - 0.49
    return 0.19 - 8.0e4 / Re


#: Below this ball Reynolds number the drag coefficient is taken at it: a bearing standing still or
#: creeping has no meaningful drag Reynolds number, and the drag (~ v^2) is negligible there.
RE_FLOOR = 1.0


#: End of the subcritical branch of the standard drag curve ([4], Table 5.2).  The ball drag holds C_D at its
#: value here for larger Re (0.474): the smooth sphere's drag crisis is not applied in a bearing cavity.
#: Evidence: with the crisis the computed drag, and the total power loss, FALL with speed across it
#: (35-mm 7206-similar bearing: drag 2841 W at 60 000 r/min, 1049 W at 72 000), while every measured
#: bearing heat generation over speed rises monotonically (NASA TP-2275 35-mm: 350, 700, 1100, 1400 W at
#: 28, 48, 64, 72 krpm; docs/power_loss.md); the ball spins, runs in its neighbour's wake in a turbulent,
#: oil-laden cavity, not in the quiet stream of the crisis measurements.
RE_SUBCRITICAL_MAX = 3.38e5


def ball_drag_coefficient(rho_e: float, mu_e: float, v: float, D: float) -> tuple[float, float]:
    """(C_D, Re) of the ball drag: :func:`sphere_drag_coefficient` at the ball Reynolds number
    :func:`ball_reynolds_number` (floored at :data:`RE_FLOOR`), without the drag crisis: held at
    C_D(:data:`RE_SUBCRITICAL_MAX`) above it ([4]; the decision and its evidence: docs/power_loss.md).
    The returned Re is the actual one.

    One value per case: :func:`hsbearing.systems.angular_contact.dynamics.build_model` evaluates it at the orbital speed of
    the initial (quasi-static) state and the kernel keeps it for the run; ``hsbearing friction``
    reports the same number.
    """
    Re = ball_reynolds_number(rho_e, v, D, mu_e)
    return sphere_drag_coefficient(min(max(Re, RE_FLOOR), RE_SUBCRITICAL_MAX)), Re


@njit(cache=True)
def ball_drag_force(v, D, rho_e, C_D, v0):
    """Drag on a ball moving at speed v through the mixture [N], opposite to v.

    F_D = 1/2 C_D rho_e (pi D^2 / 4) v |v|  (the sphere drag that defines C_D, [4]; Harris's
    pi/32 form [1] at v = d_m omega_m / 2, with the exponent 2 instead of 1.95 because C_D(Re)
    carries the speed dependence); |v| is regularised as sqrt(v^2 + v0^2) so that the force is
    smooth at v = 0.  Returns the signed force along the direction of v (negative for v > 0).
    """
    va = math.sqrt(v * v + v0 * v0)
    return -0.5 * C_D * rho_e * 0.25 * math.pi * D * D * v * va  # [4], [1]


# numba bakes callees and captured constants into its cache: key the cache on them (compile_cache.py)
check_compile_cache(globals())
