"""EHL traction laws, registered by oil name.

``get(oil, law="default")`` returns a callable ``mu(S, W, U, T, E, R)`` (SI; T in
kelvin; E = reduced modulus E', R = Rx); ``contact_mu`` evaluates it from the
physical contact quantities; ``law_id`` gives the integer id used by the numba
kernels ``_kernels.coefficients_nb`` / ``_kernels.mu_nb`` of the dynamics hot
path.  Conventions and the decision per oil: docs/traction.md.
``OILS`` maps the closed vocabulary of oil names to their Table 1 data
(Zhang et al. 2016): eta0 [Pa s], alpha [1/Pa], beta [1/degC], K [N/(s degC)].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class OilProperties:
    name: str
    eta0: float  #: dynamic viscosity at ambient temperature [Pa s]
    alpha: float  #: pressure-viscosity coefficient [1/Pa]
    beta: float  #: temperature-viscosity coefficient [1/degC]
    K: float  #: thermal conductivity [N/(s degC)] = [W/(m K)]


# Zhang et al. 2016, Table 1.
OILS: dict[str, OilProperties] = {
    "4109": OilProperties("4109", 0.033, 1.28e-8, 0.0215, 0.0966),
    "4106": OilProperties("4106", 0.055, 1.85e-8, 0.031531, 0.0965788),
    "4050": OilProperties("4050", 0.060, 2.02e-8, 0.035, 0.0966),
}


# ----------------------------------------------------------------------------
# registry of traction laws (one module per published law; Zhang et al. 2016 -> zhang2016)

from hsbearing.models.traction import zhang2016  # noqa: E402

#: The physical model (:mod:`hsbearing.models.traction.eyring`): a law of every oil, fed by the oil's own
#: viscosity and alpha (its rheological constants: kernel parameters traction.tau0, Lambda, G).
EYRING_LAW = "eyring"
#: The thermal physical model (:mod:`hsbearing.models.traction.thermal`): Roelands viscosity, Eyring stress
#: proportional to T, limiting shear, Maxwell build-up and shear heating of the film and both surfaces; a law of
#: every oil, evaluated by :func:`contact_mu` / ``hsbearing.traction_coefficient`` (not compiled in the kernel).
PHYSICAL_LAW = "physical"
#: The law recommended for an oil without a fitted traction law (a lubricant file without a [traction] table):
#: decision and evidence in docs/traction.md, "Thermal physical model" (item "Which law for an oil without a fit");
#: everything that applies the recommendation reads this one name (hsbearing.lubricant).
RECOMMENDED_LAW = "eyring"
#: The seed form mu = (A + B S) e^(-C S) + D with constant user coefficients (a lubricant file's
#: ``traction.model = "coefficients"`` or a fitted ``"table"``; kernel parameters traction.c_A .. c_D).
USER_LAW = "user"
#: Kernel law ids of the two oil-independent laws (the seed laws are the rows 0, 1, ... of zhang2016.PARAMS);
#: the same values as ``_kernels.EYRING_LAW_ID`` / ``COEFFICIENTS_LAW_ID`` (a test checks).
EYRING_LAW_ID = -1
COEFFICIENTS_LAW_ID = -2

#: law names accepted by :func:`get` for each oil ("default" resolves per oil); "user" is accepted only
#: with a lubricant file that gives the coefficients (hsbearing.case checks)
KNOWN_LAWS: dict[str, tuple[str, ...]] = {
    oil: tuple(["default"] + [law for (o, law) in zhang2016.LAWS if o == oil] + [EYRING_LAW, PHYSICAL_LAW])
    for oil in OILS
}


def _resolve(oil, law: str = "default") -> tuple[str, str]:
    oil = str(oil)
    if oil not in OILS:
        raise ValueError(f"unknown oil {oil!r} (known: {', '.join(OILS)})")
    if law in (EYRING_LAW, USER_LAW, PHYSICAL_LAW):
        return oil, law
    name = zhang2016.DEFAULT_LAW[oil] if law == "default" else law
    if (oil, name) not in zhang2016.LAWS:
        raise ValueError(f"unknown traction law {law!r} for oil {oil} (known: {', '.join(KNOWN_LAWS[oil])})")
    return oil, name


def law_id(oil, law: str = "default") -> int:
    """Integer id of a law for the numba kernels ``_kernels.traction_coefficients_nb`` (seed laws: the row of
    zhang2016.PARAMS; :data:`EYRING_LAW_ID`, :data:`COEFFICIENTS_LAW_ID` for the two oil-independent laws)."""
    oil, name = _resolve(oil, law)
    if name == PHYSICAL_LAW:
        raise ValueError("law 'physical' is not compiled in the dynamics kernel: evaluate it with "
                         "hsbearing.traction_coefficient / traction.contact_mu (the kernel runs 'eyring')")
    if name == EYRING_LAW:
        return EYRING_LAW_ID
    if name == USER_LAW:
        return COEFFICIENTS_LAW_ID
    return zhang2016.LAWS[(oil, name)]


def is_seed_law(law: str) -> bool:
    """True for the registered curve-fit laws of Zhang et al. 2016 (False: "eyring", "physical", "user")."""
    return law not in (EYRING_LAW, USER_LAW, PHYSICAL_LAW)


def law_name(oil, law: str = "default") -> str:
    """The concrete law name that ``law`` resolves to (e.g. "default" -> "analogue_4106" for 4050)."""
    return _resolve(oil, law)[1]


def _check_temperature(T):
    if np.any(np.asarray(T, dtype=float) <= 273.15):
        raise ValueError("the Zhang et al. 2016 traction laws are fitted in degC and undefined at or below 0 degC "
                         f"(got T = {np.min(T)} K)")


def get(oil, law: str = "default"):
    """Traction law of an oil as a callable ``mu(S, W, U, T, E, R)``.

    Parameters
    ----------
    oil : str
        A registered oil: ``"4109"``, ``"4106"`` or ``"4050"`` (Zhang et al. 2016, Table 1).
    law : str
        ``"default"`` (see docs/traction.md), ``"printed"`` (the paper's equation as printed) or another name
        in :data:`KNOWN_LAWS`.  Unknown oil or law -> ValueError listing the known ones.

    Returns
    -------
    callable
        ``mu(S, W, U, T, E, R)`` with SI, broadcastable arguments: S the signed slide-roll ratio
        (U_1 - U_2)/U [-] (mu has the sign of S); W the normal contact load [N]; U the rolling (entrainment)
        velocity (U_1 + U_2)/2 [m/s]; T the lubricant inlet temperature [K] (the laws of Zhang et al. 2016
        use degC internally); E the reduced modulus E' = 2/((1-nu1^2)/E1 + (1-nu2^2)/E2) [Pa]
        (:func:`hsbearing.models.hertz.reduced_modulus`); R the effective radius of curvature in the rolling
        direction Rx [m].

    Examples
    --------
    Oil 4109 at 130 degC (403.15 K), 500 N, 16.3 m/s, 5 % slide-roll ratio; mu is odd in S:

    >>> from hsbearing.models import traction
    >>> mu = traction.get("4109")
    >>> print(f"{float(mu(0.05, 500.0, 16.3, 403.15, 2.286e11, 3.87e-3)):.4f}")
    0.0090
    >>> print(f"{float(mu(-0.05, 500.0, 16.3, 403.15, 2.286e11, 3.87e-3)):.4f}")
    -0.0090
    """
    oil, name = _resolve(oil, law)
    if not is_seed_law(name):
        raise ValueError(f"law {name!r} needs the contact's geometry and oil data: use contact_mu(..., Ry/k, a, "
                         "eta, alpha, ...) or models.traction.eyring")
    lid = zhang2016.LAWS[(oil, name)]

    def mu(S, W, U, T, E, R):
        _check_temperature(T)
        A, B, C, D = zhang2016.coefficients(lid, W, U, T, E, R)
        return zhang2016.traction_coefficient(A, B, C, D, S)

    mu.oil, mu.law, mu.law_id = oil, name, lid
    mu.__doc__ = f"Traction coefficient of oil {oil}, law {name!r}: {zhang2016.describe(oil, name)}."
    return mu


def contact_mu(oil, S, Q, U, T, Ep, Rx, Ry=None, law: str = "default", *, k=None, a=None, eta=None,
               alpha=None, eyring=None, coefficients=None, beta=None, K=None, physical=None, spin=0.0):
    """Traction coefficient of a ball/race contact from its physical quantities.

    Maps the contact onto the convention of the laws (E = E', R = Rx; see
    docs/traction.md) and evaluates them; vectorised.

    Parameters
    ----------
    oil : oil name (closed vocabulary :data:`OILS`)
    S : signed slide-roll ratio [-]
    Q : normal contact load [N]
    U : rolling (entrainment) velocity [m/s]
    T : lubricant temperature [K]
    Ep : reduced modulus E' [Pa] (hertz.reduced_modulus)
    Rx, Ry : effective radii in the rolling / transverse directions [m];
        Ry is accepted for a uniform contact interface and not used by the
        Zhang et al. 2016 laws (their R is Rx).
    law : as in :func:`get`, or "eyring" (the isothermal physical model), "physical" (the thermal physical model)
        or "user" (constant coefficients)
    k, a : ellipticity a/b [-] and semi-major axis [m] of the contact ("eyring", "physical")
    eta, alpha : inlet viscosity [Pa s] and pressure-viscosity coefficient [1/Pa] ("eyring", "physical")
    beta, K : temperature-viscosity coefficient -d ln eta/dT [1/K] and thermal conductivity [W/(m K)] of the oil
        at T ("physical"); physical : thermal.PhysicalParameters ("physical"; default: its defaults);
        spin : change of the slide-roll ratio across the major axis, strip y = a u has S + spin u ("physical")
    eyring : (tau0 [Pa], Lambda [-], G [Pa]) at T ("eyring" only; default: eyring.EyringParameters().at(T, alpha))
    coefficients : (A, B, C, D) of the "user" law (S a fraction)

    Returns
    -------
    mu [-] (sign of S)
    """
    oil, name = _resolve(oil, law)
    if name == PHYSICAL_LAW:
        from hsbearing.models.traction import thermal

        if k is None or a is None or eta is None or alpha is None or beta is None or K is None:
            raise ValueError("law 'physical' needs k, a, eta, alpha, beta and K of the contact")
        return thermal.contact_mu(S, float(Q), float(U), float(Ep), float(Rx), float(k), float(a), float(T),
                                  float(eta), float(alpha), float(beta), float(K), physical, spin=float(spin))
    if name == USER_LAW:
        if coefficients is None:
            raise ValueError("law 'user' needs its coefficients (A, B, C, D)")
        A, B, C, D = (float(c) for c in coefficients)
        return zhang2016.traction_coefficient(A, B, C, D, S)
    if name == EYRING_LAW:
        from hsbearing.models.traction import eyring as ey

        if k is None or a is None or eta is None or alpha is None:
            raise ValueError("law 'eyring' needs k, a, eta and alpha of the contact")
        tau0, Lam, G = eyring if eyring is not None else ey.EyringParameters().at(T, alpha)
        return ey.contact_mu(S, float(Q), float(U), float(Ep), float(Rx), float(k), float(a), float(eta),
                             float(alpha), tau0, Lam, G)
    return get(oil, law)(S, Q, U, T, Ep, Rx)
