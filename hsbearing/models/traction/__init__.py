"""EHL traction laws, registered by oil name.

``get(oil)`` returns a callable ``mu(S, W, U, T, E, R)`` (SI; T in kelvin).
``OILS`` maps the closed vocabulary of oil names to their Table 1 data
(seed 004): eta0 [Pa s], alpha [1/Pa], beta [1/degC], K [N/(s degC)].
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class OilProperties:
    name: str
    eta0: float  #: dynamic viscosity at ambient temperature [Pa s]
    alpha: float  #: pressure-viscosity coefficient [1/Pa]
    beta: float  #: temperature-viscosity coefficient [1/degC]
    K: float  #: thermal conductivity [N/(s degC)] = [W/(m K)]


# Seed 004 (Zhang et al. 2016), Table 1.
OILS: dict[str, OilProperties] = {
    "4109": OilProperties("4109", 0.033, 1.28e-8, 0.0215, 0.0966),
    "4106": OilProperties("4106", 0.055, 1.85e-8, 0.031531, 0.0965788),
    "4050": OilProperties("4050", 0.060, 2.02e-8, 0.035, 0.0966),
}
