"""Independent finite-volume solution of a plane Couette film heated by its own shear (reference for models/ball_bearing/films.py).

The full problem, without the closed form's uniform-dissipation assumption: across a film 0 <= y <= h,
  momentum   tau = eta(T) du/dy uniform (no pressure gradient), u(0) = 0, u(h) = U  ->  tau int_0^h dy / eta(T) = U;
  energy     d/dy (k dT/dy) + tau du/dy = 0, i.e. k T'' = -tau^2 / eta(T), T(0) = T_a, T(h) = T_b.
Discretised on N equal cells (cell-centred temperatures, half-cell distance to the walls), the dissipation of each cell
tau^2 / eta(T_i) with tau from the discrete momentum integral; solved by Picard iteration (tridiagonal solve of the
conduction with the source of the previous iterate, under-relaxed) until the temperatures change by < 1e-10 K.
Second-order in the cell size (checked by the test at two resolutions).
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import solve_banded


def solve_couette_film_fv(eta_of_T, U, h, k, T_a, T_b, n=400, relax=0.5, tol=1e-10, max_iter=20000):
    """(tau [Pa], T [K] at the cell centres, y [m]) of the heated Couette film (module docstring)."""
    dy = h / n
    y = (np.arange(n) + 0.5) * dy
    T = T_a + (T_b - T_a) * y / h
    # conduction matrix (banded): interior k/dy^2 (T_{i-1} - 2 T_i + T_{i+1}); wall cells 2k/dy^2 (T_w - T_i)
    ab = np.zeros((3, n))
    ab[0, 1:] = 1.0
    ab[2, :-1] = 1.0
    ab[1, :] = -2.0
    ab[1, 0] = ab[1, -1] = -3.0
    ab *= k / dy**2
    bc = np.zeros(n)
    bc[0] = 2.0 * k / dy**2 * T_a
    bc[-1] = 2.0 * k / dy**2 * T_b
    vec = np.vectorize(lambda t: float(eta_of_T(t)))
    tau = 0.0
    for _ in range(max_iter):
        eta = vec(T)
        tau = U / float(np.sum(dy / eta))
        rhs = -(tau * tau / eta) - bc
        T_new = solve_banded((1, 1), ab, rhs)
        step = T_new - T
        T = T + relax * step
        if float(np.max(np.abs(step))) < tol:
            break
    else:
        raise RuntimeError("finite-volume Couette film did not converge")
    return tau, T, y
