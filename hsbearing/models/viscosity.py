"""Ambient-pressure viscosity of the aviation oils 4109, 4106 and 4050 against temperature.

(Oils defined in a lubricant file -- ``lubricant.file`` -- use the same Walther relation
through their own points: :mod:`hsbearing.lubricant`.)

Two laws, selected by the case key ``lubricant.viscosity_law`` (decision and evidence in
docs/traction.md, "Viscosity"):

* ``"walther"`` (default): the Walther / ASTM D341 relation fitted through the kinematic
  viscosity of each oil's specification class at 40 degC and 100 degC ([2]-[4]),
  eta = nu(T) rho;
* ``"table1"``: Zhang et al. 2016's exponential law eta = eta0 exp(-beta (T - T_ref)) with Table 1's
  eta0 and beta ([1]), T_ref = 27 degC (:data:`hsbearing.models.ehl.REFERENCE_TEMPERATURE`).

The pressure-viscosity coefficient alpha stays Table 1's in both laws.  Everything here is pure
numpy and SI; ``hsbearing.models.ehl.lubricant_parameters`` is the one entry point the dynamic
model, the quasi-static solver and the friction models use.

References
----------
[1] Zhang W., Deng S., Chen G., Cui Y., Chin. J. Aeronaut. (2016), doi:10.1016/j.cja.2016.08.019,
    Table 1 (Zhang et al. 2016): eta0, alpha, beta, K; Sec. 2: 4109 "low viscosity", 4106 "medium
    viscosity", 4050 "medium viscosity, high-temperature resistant".
[2] ASTM D341, Standard practice for viscosity-temperature equations and charts of liquid
    petroleum or hydrocarbon products: log10 log10(nu + 0.7) = A - B log10(T), nu in mm^2/s, T in K.
[3] MIL-PRF-23699F (1997), Sec. 1.1: "nominal viscosity of 5 centistokes at 100 degC ...
    neopentyl polyol ester"; class representative: Mobil Jet Oil II (MIL-PRF-23699 STD) typical
    27.6 mm^2/s at 40 degC and 5.1 mm^2/s at 100 degC (ExxonMobil product data).
[4] MIL-PRF-7808L, Grade 3 (the 3 cSt diester grade; Bruce R., "Ester-based gas turbine
    lubricants", in Synthetics, Mineral Oils and Bio-Based Lubricants, CRC 2017): minimum
    3.0 mm^2/s at 100 degC and 11.5 mm^2/s at 40 degC.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = [
    "VISCOSITY_LAWS",
    "SpecPoints",
    "OIL_SPEC",
    "table1_ratio",
    "walther_coefficients",
    "walther_kinematic_viscosity",
    "exponential_dynamic_viscosity",
    "dynamic_viscosity",
]

#: Closed vocabulary of ``lubricant.viscosity_law``.
VISCOSITY_LAWS = ("walther", "table1")

#: ASTM D341 offset [mm^2/s] ([2]).
WALTHER_OFFSET = 0.7


@dataclass(frozen=True)
class SpecPoints:
    """Two published kinematic-viscosity points of an oil's specification class."""

    oil_class: str  #: specification class the oil is taken to belong to
    nu40: float  #: kinematic viscosity at 40 degC [m^2/s]
    nu100: float  #: kinematic viscosity at 100 degC [m^2/s]
    source: str  #: where the numbers come from (docs/traction.md, "Viscosity")


def table1_ratio(oil, ref, T):
    """Zhang et al. 2016 Table 1 viscosity of ``oil`` over that of ``ref`` at T [K] ([1]):
    (eta0_oil / eta0_ref) exp(-(beta_oil - beta_ref) (T - T_ref)), T_ref = 27 degC.

    The ratio of two fits of one form from one source: the form's systematic error against the class
    data (docs/traction.md, "Viscosity") largely cancels in it, unlike in either law alone.
    """
    from hsbearing.models.traction import OILS

    a, b = OILS[oil], OILS[ref]
    return float(a.eta0 / b.eta0 * np.exp(-(a.beta - b.beta) * (float(T) - 300.15)))


# 4109 ("low viscosity", Table 1 beta 0.0215/degC) -> 3 cSt diester class (MIL-PRF-7808 grade 3) [4];
# 4106 ("medium viscosity") -> 5 cSt polyol-ester class (MIL-PRF-23699) [3];
# 4050 ("medium viscosity, high-temperature resistant") -> its own points: the 4106 class points
# times Table 1's 4050/4106 viscosity ratio at 40 and 100 degC (table1_ratio: 1.043 and 0.847), i.e.
# 28.8 and 4.32 mm^2/s (decision and evidence: docs/traction.md, "4050 as an oil of its own").
_NU40_23699, _NU100_23699 = 27.6e-6, 5.1e-6
OIL_SPEC: dict[str, SpecPoints] = {
    "4109": SpecPoints("MIL-PRF-7808 grade 3", 11.5e-6, 3.0e-6, "MIL-PRF-7808L grade 3 minima [4]"),
    "4106": SpecPoints("MIL-PRF-23699", _NU40_23699, _NU100_23699, "Mobil Jet Oil II typical (MIL-PRF-23699 STD) [3]"),
    "4050": SpecPoints("4050 (Table 1 relative to 4106)", _NU40_23699 * table1_ratio("4050", "4106", 313.15),
                       _NU100_23699 * table1_ratio("4050", "4106", 373.15),
                       "MIL-PRF-23699 class points [3] x Table 1 eta(4050)/eta(4106) at 40 and 100 degC [1]"),
}


def walther_coefficients(T1, nu1, T2, nu2):
    """Coefficients (A, B) of ASTM D341 through two points ([2]).

    log10 log10(nu + 0.7) = A - B log10(T)

    Parameters
    ----------
    T1, T2 : temperatures [K];  nu1, nu2 : kinematic viscosities [m^2/s]

    Returns
    -------
    (A, B) [-] (nu in mm^2/s and T in K inside the relation, as ASTM D341 defines it)
    """
    z1 = np.log10(np.log10(nu1 * 1e6 + WALTHER_OFFSET))  # [2]
    z2 = np.log10(np.log10(nu2 * 1e6 + WALTHER_OFFSET))
    B = (z1 - z2) / (np.log10(T2) - np.log10(T1))
    A = z1 + B * np.log10(T1)
    return float(A), float(B)


def walther_kinematic_viscosity(T, A, B):
    """Kinematic viscosity from ASTM D341 ([2]) [m^2/s].

    Parameters
    ----------
    T : temperature [K];  A, B : coefficients of :func:`walther_coefficients` [-]
    """
    z = A - B * np.log10(np.asarray(T, dtype=float))  # [2]
    return (10.0 ** (10.0**z) - WALTHER_OFFSET) * 1e-6


def exponential_dynamic_viscosity(eta0, beta, T, T_ref):
    """Zhang et al. 2016's law eta = eta0 exp(-beta (T - T_ref)) [Pa s] ([1], Table 1).

    Parameters
    ----------
    eta0 : viscosity at T_ref [Pa s];  beta : temperature-viscosity coefficient [1/K]
    T, T_ref : temperatures [K]
    """
    return np.asarray(eta0, dtype=float) * np.exp(-np.asarray(beta, dtype=float) * (np.asarray(T, dtype=float) - T_ref))


def dynamic_viscosity(oil, T, law="walther", density=None, T_ref=300.15):
    """Ambient-pressure dynamic viscosity of a Zhang et al. 2016 oil [Pa s].

    Parameters
    ----------
    oil : "4109", "4106" or "4050"
    T : temperature [K] (vectorised)
    law : "walther" (ASTM D341 through the class points of :data:`OIL_SPEC`, times ``density``)
        or "table1" (Table 1 exponential law, reference temperature ``T_ref`` [K])
    density : oil density [kg/m^3]; required by "walther"

    Returns
    -------
    eta [Pa s]
    """
    from hsbearing.models.traction import OILS

    if law == "table1":
        o = OILS[oil]
        return exponential_dynamic_viscosity(o.eta0, o.beta, T, T_ref)
    if law == "walther":
        if density is None:
            raise ValueError("the walther viscosity law needs the oil density")
        s = OIL_SPEC[oil]
        A, B = walther_coefficients(313.15, s.nu40, 373.15, s.nu100)
        return walther_kinematic_viscosity(T, A, B) * density
    raise ValueError(f"unknown viscosity law {law!r} (known: {', '.join(VISCOSITY_LAWS)})")
