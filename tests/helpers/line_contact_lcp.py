"""Independent numerical solution of the pocket station film (test-only): a finite-volume grid of the 1-D Reynolds
equation with the p >= 0 complementarity condition, solved as a linear complementarity problem.

Nothing here comes from hsbearing.models.ball_bearing.pocket: the gap h = a + x^2/(2 R) (sphere against a plane
across one station), the equation (h^3 p')' = 6 eta U h' + F0 on [x_lo, x_hi] with p = 0 at both edges
(flooded pocket) and the cavitation condition p >= 0 with (h^3 p')' - 6 eta U h' - F0 >= 0 where p = 0
(Christopherson's complementarity formulation, Proc. IMechE 146 (1941); it gives the Reynolds/Swift-Stieber exit
condition p = p' = 0 at the film rupture: Hamrock, Schmid & Jacobson, *Fundamentals of Fluid Film Lubrication*,
2004, Ch. 7-8).

Discretisation: uniform nodes, the conservative flux form q = h^3 p' - 6 eta U h at the cell faces, so that
(q_{i+1/2} - q_{i-1/2})/dx = F0 at every interior node: a symmetric positive-definite tridiagonal matrix A with
A p = b where the film carries pressure.  The complementarity problem p >= 0, w = A p - b >= 0, p w = 0 is solved by
the primal-dual active-set method (Hintermueller, Ito & Kunisch, SIAM J. Optim. 13 (2003) 865: finite termination
for M-matrices), each step one banded solve.  Second-order accurate away from the rupture point.
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import solve_banded


def line_contact_lcp(a, U_e, F0, x_lo, x_hi, R, eta, n=8001, max_iter=5000):
    """(W, Wx, x_range, iterations): W = int p dx [N/m], Wx = int p x dx [N], the interval of nodes with p > 0
    ((nan, nan) if none) and the active-set iterations used on the finest grid.

    The active-set method moves the film rupture by about one node per iteration once the set is nearly right, so
    the set is first found on grids of n/100 and n/10 cells and carried to the next (nearest node)."""
    guess = None
    for level in (max(n // 100, 50) + 1, max(n // 10, 500) + 1):
        *_, guess = _solve(a, U_e, F0, x_lo, x_hi, R, eta, level, max_iter, guess)
    W, Wx, rng, it, _ = _solve(a, U_e, F0, x_lo, x_hi, R, eta, n, max_iter, guess)
    return W, Wx, rng, it


def _solve(a, U_e, F0, x_lo, x_hi, R, eta, n, max_iter, guess):
    """One grid of n nodes; ``guess`` = (x, active) of a coarser grid or None.  Returns (W, Wx, rng, it, (x, active))."""
    x = np.linspace(x_lo, x_hi, n)
    dx = x[1] - x[0]
    xf = 0.5 * (x[1:] + x[:-1])  # cell faces
    hf = a + xf * xf / (2.0 * R)
    k = hf ** 3 / (dx * dx)  # face conductances / dx
    m = n - 2  # interior unknowns 1 .. n-2
    diag = k[:-1] + k[1:]
    lower = -k[1:-1]  # A[i, i-1] for i = 1 .. m-1
    upper = -k[1:-1]  # A[i, i+1] for i = 0 .. m-2
    b = -F0 - 6.0 * eta * U_e * (hf[1:] - hf[:-1]) / dx
    active = np.zeros(m, dtype=bool)  # True: p = 0 there
    if guess is not None:
        gx, ga = guess
        active = np.interp(x[1:-1], gx, ga.astype(float)) > 0.5
    p = np.zeros(m)
    for it in range(1, max_iter + 1):
        ab = np.zeros((3, m))
        d = np.where(active, 1.0, diag)
        up = np.where(active[:-1], 0.0, upper)  # row i's coupling to i+1
        lo_ = np.where(active[1:], 0.0, lower)  # row i's coupling to i-1
        ab[0, 1:] = up
        ab[1, :] = d
        ab[2, :-1] = lo_
        rhs = np.where(active, 0.0, b)
        p = solve_banded((1, 1), ab, rhs)
        Ap = diag * p
        Ap[1:] += lower * p[:-1]
        Ap[:-1] += upper * p[1:]
        w = Ap - b
        new = (w - diag * p) > 0.0
        if np.array_equal(new, active):
            break
        active = new
    else:
        raise RuntimeError("active-set iteration did not settle")
    p = np.maximum(p, 0.0)  # the converged set: p >= 0 up to round-off
    pf = np.concatenate([[0.0], p, [0.0]])
    W = float(np.trapezoid(pf, x)) if hasattr(np, "trapezoid") else float(np.trapz(pf, x))
    Wx = float(np.trapezoid(pf * x, x)) if hasattr(np, "trapezoid") else float(np.trapz(pf * x, x))
    pos = np.nonzero(pf > 0.0)[0]
    rng = (float(x[pos[0] - 1]), float(x[pos[-1] + 1])) if pos.size else (float("nan"), float("nan"))
    return W, Wx, rng, it, (x[1:-1], active)

