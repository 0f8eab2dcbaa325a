"""Oil properties of a case at any temperature, shared by the dynamic model, the quasi-static loss and the thermal network.

:func:`viscosity_at` (the viscosity precedence of :func:`hsbearing.models.ehl.lubricant_parameters` at any T),
:func:`inlet_beta` (its local temperature slope, for the inlet shear heating), :func:`oil_conductivity`.  Imports
only models/, so the system's modules that need these do not import each other.
"""

from __future__ import annotations

import math

__all__ = ["viscosity_at", "inlet_beta", "oil_conductivity"]


def viscosity_at(case, T):
    """Dynamic viscosity of the case's oil at T [Pa s] (the precedence of :func:`hsbearing.models.ehl.lubricant_parameters`)."""
    from hsbearing.models import ehl
    from hsbearing.models.traction import OILS
    from hsbearing.models.viscosity import dynamic_viscosity

    lub = case.lubricant
    d = getattr(lub, "definition", None)
    if d is not None and lub.kinematic_viscosity is not None and math.isclose(
            lub.kinematic_viscosity, float(d.kinematic_viscosity(lub.temperature, lub.density)), rel_tol=1e-9):
        # the case's value came from its lubricant file at lubricant.temperature: evaluate the file at T
        return float(d.kinematic_viscosity(T, lub.density)) * lub.density
    if lub.kinematic_viscosity is not None:
        return lub.kinematic_viscosity * lub.density
    if lub.dynamic_viscosity is not None:
        return float(ehl.viscosity_at_temperature(lub.dynamic_viscosity, OILS[lub.oil].beta, T))
    return float(dynamic_viscosity(lub.oil, T, law=lub.viscosity_law, density=lub.density, T_ref=ehl.REFERENCE_TEMPERATURE))



def inlet_beta(case) -> float:
    """Temperature-viscosity coefficient beta = -d ln(eta) / dT [1/K] at lubricant.temperature for the inlet shear
    heating factor: the local slope of the viscosity the model uses (central difference over +-1 K, the precedence of
    :func:`hsbearing.models.ehl.lubricant_parameters`); the oil's table value where the case fixes the viscosity
    (a given kinematic viscosity has no slope)."""
    from hsbearing.models import ehl

    T = case.lubricant.temperature
    try:
        lo, hi = viscosity_at(case, T - 1.0), viscosity_at(case, T + 1.0)
    except (ValueError, KeyError):
        lo = hi = 0.0
    if lo > 0.0 and hi > 0.0 and lo != hi:
        return -0.5 * math.log(hi / lo)
    return float(ehl.lubricant_parameters(case)["beta"])


def oil_conductivity(case) -> float:
    """Oil thermal conductivity [W/(m K)]: thermal.oil_thermal_conductivity, else the oil's K (Table 1 / its file)."""
    from hsbearing.models.traction import OILS

    return case.thermal.oil_thermal_conductivity or OILS[case.lubricant.oil].K
