"""Material helpers: reduced moduli of the contact pairs of a case.

References: Hamrock & Dowson, *Ball Bearing Lubrication* (1981), Eq. 3.35 (E');
the material constants themselves come from the case file (``[materials.*]``).
"""

from __future__ import annotations

from hsbearing.models.hertz import reduced_modulus

__all__ = ["ball_race_modulus", "ball_cage_modulus"]


def ball_race_modulus(case) -> float:
    """E' [Pa] of the ball/raceway pair (Hamrock & Dowson Eq. 3.35)."""
    b, r = case.materials.ball, case.materials.races
    return float(reduced_modulus(b.elastic_modulus, b.poisson_ratio, r.elastic_modulus, r.poisson_ratio))


def ball_cage_modulus(case) -> float:
    """E' [Pa] of the ball/cage-pocket pair (Hamrock & Dowson Eq. 3.35)."""
    b, c = case.materials.ball, case.materials.cage
    return float(reduced_modulus(b.elastic_modulus, b.poisson_ratio, c.elastic_modulus, c.poisson_ratio))
