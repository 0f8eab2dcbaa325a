"""Arrowhead block LU (hsbearing.solvers.arrowhead) against dense solves, its use as CVODE's linear solver, and
the arrowhead structure of the dynamic model's Jacobian checked against an independent finite-difference
Jacobian of the kernel."""

from __future__ import annotations

import numpy as np
import pytest

from hsbearing.solvers.arrowhead import ArrowheadLU, ArrowheadStructure, outside_entries, structure_from_pattern


def _random_structure(rng, sizes, m, shuffle=True):
    n = sum(sizes) + m
    perm = rng.permutation(n) if shuffle else np.arange(n)
    blocks, o = [], 0
    for s in sizes:
        blocks.append(perm[o:o + s])
        o += s
    return ArrowheadStructure.from_blocks(n, blocks, perm[o:])


def _random_arrowhead(rng, st, diag=3.0):
    M = rng.standard_normal((st.n, st.n)) * st.mask()
    return M + diag * np.eye(st.n)


@pytest.mark.parametrize("sizes,m,shuffle", [
    ([9] * 11, 22, False),   # the bearing's shape, contiguous
    ([9] * 11, 22, True),    # same, scattered indices (the model interleaves ball states with stride Z)
    ([1, 4, 2, 7, 3], 5, True),  # unequal blocks
    ([3, 3], 0, True),       # no border: block diagonal
    ([], 6, False),          # border only: plain dense LU
])
def test_solve_matches_dense_on_random_arrowheads(sizes, m, shuffle):
    rng = np.random.default_rng(28)
    for trial in range(20):
        st = _random_structure(rng, sizes, m, shuffle)
        M = _random_arrowhead(rng, st, diag=0.0 if trial % 2 else 3.0)  # odd trials: no diagonal boost
        lu = ArrowheadLU(st).factor(M)
        for b in (rng.standard_normal(st.n), np.zeros(st.n), np.eye(st.n)[trial % st.n]):
            x = lu.solve(b)
            ref = np.linalg.solve(M, b)
            scale = np.linalg.norm(M, np.inf) * np.linalg.norm(x, np.inf) + np.linalg.norm(b, np.inf)
            assert np.linalg.norm(M @ x - b, np.inf) <= 1e-12 * max(scale, 1e-300)
            assert np.allclose(x, ref, rtol=1e-9, atol=1e-12 * np.abs(ref).max(initial=1.0))


def test_entries_outside_the_structure_are_never_read():
    rng = np.random.default_rng(1)
    st = _random_structure(rng, [9] * 11, 22)
    M = _random_arrowhead(rng, st)
    b = rng.standard_normal(st.n)
    x = ArrowheadLU(st).factor(M).solve(b)
    garbage = np.where(st.mask(), M, np.nan)  # NaN wherever the structure says zero
    assert np.array_equal(ArrowheadLU(st).factor(garbage).solve(b), x)


def test_zero_pivot_is_reported_not_divided_by():
    rng = np.random.default_rng(2)
    st = _random_structure(rng, [3, 3], 2)
    M = _random_arrowhead(rng, st)
    blk = st.blocks()[1]
    M[np.ix_(blk, blk)] = 0.0  # a singular diagonal block
    with pytest.raises(np.linalg.LinAlgError, match="zero pivot"):
        ArrowheadLU(st).factor(M)
    M = _random_arrowhead(rng, st)
    M[np.ix_(st.border, st.border)] = 0.0
    M[np.ix_(st.border, st.idx)] = 0.0  # C = 0 and E = 0: Schur complement S = 0
    with pytest.raises(np.linalg.LinAlgError, match="zero pivot"):
        ArrowheadLU(st).factor(M)


def test_structure_validation_and_derivation():
    with pytest.raises(ValueError, match="partition"):
        ArrowheadStructure.from_blocks(5, [[0, 1], [1, 2]], [3, 4])  # 1 twice
    with pytest.raises(ValueError, match="partition"):
        ArrowheadStructure.from_blocks(5, [[0, 1]], [3, 4])  # 2 missing
    rng = np.random.default_rng(3)
    st = _random_structure(rng, [4, 2, 5], 3)
    M = _random_arrowhead(rng, st)
    # the blocks are recovered from the pattern (connected components off the border)
    d = structure_from_pattern(M != 0, st.border)
    assert sorted(map(tuple, map(np.sort, d.blocks()))) == sorted(map(tuple, map(np.sort, st.blocks())))
    assert outside_entries(M != 0, st).size == 0
    M2 = M.copy()
    b0, b1 = st.blocks()[0], st.blocks()[1]
    M2[b0[0], b1[0]] = 1.0  # a coupling between two blocks
    out = outside_entries(M2 != 0, st)
    assert out.tolist() == [[b0[0], b1[0]]]
    merged = structure_from_pattern(M2 != 0, st.border)  # derivation merges the two coupled blocks
    assert merged.nblocks == 2 and outside_entries(M2 != 0, merged).size == 0


def test_cvode_with_the_arrowhead_solver_matches_the_exact_solution():
    """A stiff linear arrowhead ODE y' = J y against expm(J t) y0, with both linear solvers."""
    from scipy.linalg import expm

    from hsbearing.solvers.cvode import counters_available, integrate

    if not counters_available():
        pytest.skip("CVODE's solver memory is not reachable with this scikit-sundae build")
    rng = np.random.default_rng(5)
    st = _random_structure(rng, [3] * 5, 4)
    J = rng.standard_normal((st.n, st.n)) * st.mask()
    J -= np.diag(np.abs(J).sum(1) + np.geomspace(1.0, 1e4, st.n))  # stable, stiffness ratio 1e4
    y0 = rng.standard_normal(st.n)
    te = np.linspace(0.0, 1.0, 11)
    exact = np.array([expm(J * t) @ y0 for t in te])
    runs = {}
    for ls in ("dense", "arrowhead"):
        r = integrate(lambda t, y, yd: yd.__setitem__(slice(None), J @ y), y0, te, rtol=1e-8, atol=1e-12,
                      jacfn=lambda t, y, yd, JJ: JJ.__setitem__((slice(None), slice(None)), J), linsolver=ls,
                      structure=st)
        assert r.success, r.status
        assert np.abs(r.y - exact).max() < 1e-7 * np.abs(y0).max()
        runs[ls] = r
    assert "arrowhead block LU" in runs["arrowhead"].stats["linear_solver"]
    # same Newton matrices solved to round-off: the same step sequence on this non-chaotic problem
    assert runs["arrowhead"].stats["steps"] == runs["dense"].stats["steps"]
    assert runs["arrowhead"].stats["linear_solver_setups"] == runs["dense"].stats["linear_solver_setups"]
    with pytest.raises(ValueError, match="structure"):
        integrate(lambda t, y, yd: None, y0, te, linsolver="arrowhead")


def _fd_jacobian(m, y):
    """Column-by-column forward differences of the compiled rhs (independent of the arrowhead-coloured jac)."""
    n = y.size
    f0 = m.f(y)
    J = np.zeros((n, n))
    for j in range(n):
        h = 1e-7 * max(abs(y[j]), float(m.hscale[j]))
        yp = y.copy()
        yp[j] += h
        J[:, j] = (m.f(yp) - f0) / h
    return J


def test_model_jacobian_is_an_arrowhead_checked_by_finite_differences():
    """The ball-block / cage-ring-border structure that dynamics.simulate(linear_solver="arrowhead") uses,
    checked on full finite-difference Jacobians at the quasi-static start and after 3 ms (pocket and guide
    contacts active): no entry outside it, and the blocks derived from the pattern are exactly the balls."""
    from hsbearing.case import load_case
    from hsbearing.systems.angular_contact import dynamics

    case = load_case("zhang2016")
    m = dynamics.build_model(case)
    st = dynamics.arrowhead_structure(m.layout)
    assert st.describe() == f"{m.layout.Z} blocks of 9, border 22"
    ds = dynamics.simulate(case, 0.003, model=m, annotate=False)
    for y in (m.y0, np.asarray(ds["final_state"].values, float)):
        J = _fd_jacobian(m, np.asarray(y, float))
        p = J != 0
        assert outside_entries(p, st).size == 0
        derived = structure_from_pattern(p, st.border)
        assert [b.tolist() for b in derived.blocks()] == [sorted(b.tolist()) for b in st.blocks()]
        balls = st.idx
        assert p[np.ix_(balls, st.border)].any() and p[np.ix_(st.border, balls)].any()  # a real border


def test_arrowhead_is_available_in_this_build():
    """The locked scikit-sundae build is the one whose layout the hook checks: the default must not silently
    fall back to the dense solver here (a new build that fails the checks shows up as this failure)."""
    from hsbearing.solvers.cvode import arrowhead_available

    assert arrowhead_available()


def test_simulate_with_the_arrowhead_solver_runs_and_records_it():
    from hsbearing.case import load_case
    from hsbearing.solvers.cvode import counters_available
    from hsbearing.systems.angular_contact import dynamics

    if not counters_available():
        pytest.skip("CVODE's solver memory is not reachable with this scikit-sundae build")
    case = load_case("zhang2016")
    m = dynamics.build_model(case)
    d = dynamics.simulate(case, 0.002, model=m, annotate=False, linear_solver="dense")
    a = dynamics.simulate(case, 0.002, model=m, annotate=False, linear_solver="arrowhead")
    default = dynamics.simulate(case, 0.002, model=m, annotate=False)  # the default where it can be installed
    assert default.attrs["solver_linear_solver"] == a.attrs["solver_linear_solver"]
    np.testing.assert_array_equal(default["cage_speed"].values, a["cage_speed"].values)
    assert a.attrs["solver_linear_solver"].startswith("arrowhead block LU") and d.attrs["solver_linear_solver"] == "dense"
    # chaotic cage: the trajectories differ from the last bits on, the mean cage speed over 2 ms does not
    assert float(a["cage_speed"].mean()) == pytest.approx(float(d["cage_speed"].mean()), rel=1e-3)
    with pytest.raises(ValueError, match="linear_solver"):
        dynamics.simulate(case, 0.002, model=m, linear_solver="lu")
