"""Arrowhead (block-diagonal + border) LU factorisation and solve, and its use as CVODE's direct linear solver.

Nothing here knows about bearings.  A square matrix of size N has *arrowhead structure* when its unknowns split
into ``nb`` disjoint **blocks** (index sets, any order, not necessarily contiguous) and one **border** (the
remaining indices) such that every non-zero entry lies in a diagonal block (row and column in the same block),
in a border row or in a border column.  Ordered blocks first, border last::

    M = [ D   B ]     D = blockdiag(D_1 ... D_nb)   (n_i x n_i each)
        [ C   E ]     B: block rows x border columns, C: border rows x block columns, E: border x border (m x m)

Factorisation (block Gaussian elimination, the Schur complement of D; Golub & Van Loan, *Matrix Computations*,
4th ed., Sec. 3.2.10 and 4.5 "block LU"):

1. ``D_i = P_i L_i U_i``                    LU with partial pivoting of every diagonal block;
2. ``X_i = D_i^{-1} B_i``                   (n_i x m), stored over B_i;
3. ``S = E - sum_i C_i X_i``                the Schur complement (m x m), stored over E;
4. ``S = P_S L_S U_S``                      LU with partial pivoting.

Solve ``M z = r``: ``y_i = D_i^{-1} r_i``; ``S z_b = r_b - sum_i C_i y_i``; ``z_i = y_i - X_i z_b``.

Cost for nb blocks of size n and a border m: ``nb (2/3 n^3 + 2 n^2 m + 2 n m^2) + 2/3 m^3`` flops against
``2/3 N^3`` for a dense LU (N = nb n + m); for 11 blocks of 9 and a border of 22: 0.10 M flops vs 1.18 M.
Pivoting is restricted to each diagonal block and to S, so the factorisation exists when every D_i and S is
non-singular (true for CVODE's Newton matrix ``I - gamma J`` at the small ``gamma`` BDF takes, where D_i -> I);
a zero pivot is reported, never divided by.

Everything works **in place on a dense column-major array** (SUNDIALS' dense matrix storage, ``A[i, j] =
data[j * N + i]``) addressed through the index sets, so no copy or permutation of the matrix or vectors is
made; entries outside the arrowhead are never read.

:func:`install` replaces the ``setup`` and ``solve`` of the SUNDIALS dense linear solver that scikit-sundae
created (scikit-sundae offers no way to supply a direct linear solver: its ``linsolver`` is one of SUNDIALS'
own, and ``precond`` / ``jactimes`` serve only the Krylov solvers; docs/dynamics.md, "Linear algebra") by two
compiled C callbacks (``numba.cfunc``) running this factorisation on CVODE's Newton matrix ``A = I - gamma J``
(formed by CVODE from the user Jacobian exactly as for the dense solver).  Everything else of CVODE's direct
linear-solver interface (when to re-form and re-factor, the ``gamma`` ratio correction, the Jacobian function)
is unchanged.  :func:`uninstall` restores the dense solver before scikit-sundae frees it.
"""

from __future__ import annotations

import ctypes
import glob
import os
from dataclasses import dataclass

import numba as nb
import numpy as np
from numba import types
from numba.extending import intrinsic

from hsbearing.compile_cache import check_compile_cache

__all__ = ["ArrowheadStructure", "structure_from_pattern", "outside_entries", "factor", "solve",
           "ArrowheadLU", "work_size", "install", "uninstall", "LUFACT_FAIL"]

#: SUNDIALS' recoverable "LU factorisation failed" code (SUNLS_LUFACT_FAIL of sundials_linearsolver.h), the
#: value SUNDIALS' dense solver returns for a zero pivot (checked: SUNLinSolSetup_Dense of the SUNDIALS 7.9 bundled
#: with scikit-sundae 1.2 returns 808 on a zero matrix); CVODE then retries the step with a new Jacobian/step.
LUFACT_FAIL = 808


# ----------------------------------------------------------------------------------------------------------- data
@dataclass(frozen=True)
class ArrowheadStructure:
    """Index sets of the diagonal blocks and of the border of an N x N arrowhead matrix.

    ``blocks``: sequence of integer index arrays (one per block; sizes may differ); ``border``: the rest.
    Every index 0..N-1 appears exactly once in the blocks or the border (checked).
    """

    n: int
    idx: np.ndarray  #: block indices, concatenated (int64)
    offsets: np.ndarray  #: block k is idx[offsets[k]:offsets[k + 1]] (int64, nb + 1)
    border: np.ndarray  #: border indices (int64, m)

    @classmethod
    def from_blocks(cls, n: int, blocks, border) -> "ArrowheadStructure":
        blocks = [np.asarray(b, dtype=np.int64).ravel() for b in blocks]
        border = np.asarray(border, dtype=np.int64).ravel()
        if any(b.size == 0 for b in blocks):
            raise ValueError("an arrowhead block is empty")
        idx = np.concatenate(blocks) if blocks else np.zeros(0, np.int64)
        allidx = np.concatenate([idx, border])
        if allidx.size != n or not np.array_equal(np.sort(allidx), np.arange(n)):
            raise ValueError(f"blocks and border must partition 0..{n - 1} (each index exactly once)")
        offsets = np.zeros(len(blocks) + 1, np.int64)
        offsets[1:] = np.cumsum([b.size for b in blocks])
        return cls(int(n), np.ascontiguousarray(idx), offsets, np.ascontiguousarray(border))

    @property
    def nblocks(self) -> int:
        return int(self.offsets.size - 1)

    @property
    def block_sizes(self) -> list[int]:
        return [int(s) for s in np.diff(self.offsets)]

    def blocks(self) -> list[np.ndarray]:
        return [self.idx[self.offsets[k]:self.offsets[k + 1]] for k in range(self.nblocks)]

    def mask(self) -> np.ndarray:
        """Boolean N x N: True where the arrowhead may hold a non-zero."""
        m = np.zeros((self.n, self.n), bool)
        m[self.border, :] = True
        m[:, self.border] = True
        for b in self.blocks():
            m[np.ix_(b, b)] = True
        return m

    def flops(self) -> tuple[int, int]:
        """(arrowhead factorisation, dense LU) flop counts, leading terms."""
        m = self.border.size
        fa = sum(2 * s ** 3 // 3 + 2 * s * s * m + 2 * s * m * m for s in self.block_sizes) + 2 * m ** 3 // 3
        return int(fa), int(2 * self.n ** 3 // 3)

    def describe(self) -> str:
        sizes = self.block_sizes
        if sizes and all(s == sizes[0] for s in sizes):
            blk = f"{len(sizes)} blocks of {sizes[0]}"
        else:
            blk = f"{len(sizes)} blocks of sizes {sizes}"
        return f"{blk}, border {self.border.size}"


def structure_from_pattern(pattern, border) -> ArrowheadStructure:
    """Derive the blocks from a sparsity ``pattern`` (N x N, non-zero = coupled) and a given ``border``.

    The blocks are the connected components of the pattern restricted to the non-border indices (i ~ j when
    ``pattern[i, j]`` or ``pattern[j, i]``), each sorted; an index coupled to nothing is a block of its own.
    The pattern then has no entry outside the structure by construction.
    """
    from scipy.sparse import csr_matrix
    from scipy.sparse.csgraph import connected_components

    p = np.asarray(pattern) != 0
    n = p.shape[0]
    border = np.unique(np.asarray(border, dtype=np.int64))
    inner = np.setdiff1d(np.arange(n), border)
    sub = p[np.ix_(inner, inner)]
    ncomp, lab = connected_components(csr_matrix(sub | sub.T), directed=False)
    blocks = [inner[lab == k] for k in range(ncomp)]
    blocks.sort(key=lambda b: int(b[0]))
    return ArrowheadStructure.from_blocks(n, blocks, border)


def outside_entries(pattern, structure: ArrowheadStructure) -> np.ndarray:
    """(row, column) pairs of the non-zeros of ``pattern`` outside the arrowhead ``structure`` (shape (k, 2))."""
    p = np.asarray(pattern) != 0
    return np.argwhere(p & ~structure.mask())


# -------------------------------------------------------------------------------------------- compiled kernels
def work_size(structure: "ArrowheadStructure") -> int:
    """Length of the float64 workspace of :func:`factor`: the blocks D_k, X_k, C_k, then S, then X and C of all
    blocks again, transposed (the layouts the solve streams through: axpys of length m and of length sum n_k)."""
    m = structure.border.size
    return int(sum(s * s + 2 * s * m for s in structure.block_sizes) + m * m + 2 * m * structure.idx.size)


@nb.njit(cache=True, nogil=True)
def _lu_rows(d, s, piv, p0):
    """In-place LU with partial pivoting of the row-major s x s ``d``; ``piv[p0 + k]`` = row swapped with k.

    Returns 0, or k + 1 for a zero pivot in column k.
    """
    for k in range(s):
        p = k
        amax = abs(d[k, k])
        for i in range(k + 1, s):
            v = abs(d[i, k])
            if v > amax:
                amax = v
                p = i
        piv[p0 + k] = p
        if amax == 0.0:
            return k + 1
        if p != k:
            for j in range(s):
                t = d[k, j]
                d[k, j] = d[p, j]
                d[p, j] = t
        inv = 1.0 / d[k, k]
        for i in range(k + 1, s):
            f = d[i, k] * inv
            d[i, k] = f
            if f != 0.0:
                for j in range(k + 1, s):
                    d[i, j] -= f * d[k, j]
    return 0


@nb.njit(cache=True, nogil=True)
def _lu_solve_rows(d, s, piv, p0, x):
    """Solve (LU of :func:`_lu_rows`) z = x in place for one vector ``x`` (s,)."""
    for k in range(s):
        p = piv[p0 + k]
        if p != k:
            t = x[k]
            x[k] = x[p]
            x[p] = t
    for k in range(s):
        v = x[k]
        for i in range(k + 1, s):
            x[i] -= d[i, k] * v
    for k in range(s - 1, -1, -1):
        v = x[k] / d[k, k]
        x[k] = v
        for i in range(k):
            x[i] -= d[i, k] * v


@nb.njit(cache=True, nogil=True)
def _lu_solve_rows_mat(d, s, piv, p0, x, m):
    """Solve (LU of :func:`_lu_rows`) Z = X in place for the row-major (s, m) ``x`` (no temporaries)."""
    for k in range(s):
        p = piv[p0 + k]
        if p != k:
            for q in range(m):
                t = x[k, q]
                x[k, q] = x[p, q]
                x[p, q] = t
    for k in range(s):
        for i in range(k + 1, s):
            f = d[i, k]
            if f != 0.0:
                for q in range(m):
                    x[i, q] -= f * x[k, q]
    for k in range(s - 1, -1, -1):
        inv = 1.0 / d[k, k]
        for q in range(m):
            x[k, q] *= inv
        for i in range(k):
            f = d[i, k]
            if f != 0.0:
                for q in range(m):
                    x[i, q] -= f * x[k, q]


@nb.njit(cache=True, nogil=True)
def _views(work, offsets, m, k, w0):
    """(D_k, X_k, C_k) views of the workspace for block k starting at word w0; and the next block's w0."""
    s = offsets[k + 1] - offsets[k]
    d = work[w0:w0 + s * s].reshape((s, s))
    x = work[w0 + s * s:w0 + s * s + s * m].reshape((s, m))
    c = work[w0 + s * s + s * m:w0 + s * s + 2 * s * m].reshape((m, s))
    return d, x, c, w0 + s * s + 2 * s * m


@nb.njit(cache=True, nogil=True)
def factor(a, n, idx, offsets, border, piv, work):
    """Arrowhead LU of the column-major N x N ``a`` (flat, ``A[i, j] = a[j * n + i]``; steps 1-4 of the module
    docstring) into the compact workspace ``work`` (length :func:`work_size`); ``a`` is only read, and only
    inside the arrowhead.

    ``piv`` (int64, N): block pivots at ``offsets[k] + local`` and the Schur pivots at ``idx.size + local``.
    Returns 0, or a positive value on a zero pivot (1 + position).
    """
    nbk = offsets.size - 1
    m = border.size
    ws = 0  # S follows the blocks
    for k in range(nbk):
        s = offsets[k + 1] - offsets[k]
        ws += s * s + 2 * s * m
    sm = work[ws:ws + m * m].reshape((m, m))
    for r in range(m):  # S = E
        for q in range(m):
            sm[r, q] = a[border[q] * n + border[r]]
    w0 = 0
    for k in range(nbk):
        o = offsets[k]
        s = offsets[k + 1] - o
        d, x, c, w1 = _views(work, offsets, m, k, w0)
        w0 = w1
        for j in range(s):  # gather D_k (row-major), B_k, C_k
            cj = idx[o + j] * n
            for i in range(s):
                d[i, j] = a[cj + idx[o + i]]
            for r in range(m):
                c[r, j] = a[cj + border[r]]
        for q in range(m):
            cq = border[q] * n
            for i in range(s):
                x[i, q] = a[cq + idx[o + i]]
        info = _lu_rows(d, s, piv, o)
        if info != 0:
            return o + info
        _lu_solve_rows_mat(d, s, piv, o, x, m)  # X_k = D_k^{-1} B_k
        for r in range(m):  # S -= C_k X_k
            for j in range(s):
                f = c[r, j]
                if f != 0.0:
                    for q in range(m):
                        sm[r, q] -= f * x[j, q]
    info = _lu_rows(sm, m, piv, idx.size)
    if info != 0:
        return idx.size + info
    nidx = idx.size
    xt = work[ws + m * m:ws + m * m + m * nidx].reshape((m, nidx))
    ct = work[ws + m * m + m * nidx:ws + m * m + 2 * m * nidx].reshape((nidx, m))
    w0 = 0
    for k in range(nbk):
        o = offsets[k]
        s = offsets[k + 1] - o
        d, x, c, w1 = _views(work, offsets, m, k, w0)
        w0 = w1
        for i in range(s):
            for q in range(m):
                xt[q, o + i] = x[i, q]
                ct[o + i, q] = c[q, i]
    return 0


@nb.njit(cache=True, nogil=True)
def solve(n, idx, offsets, border, piv, work, x, y):
    """Solve ``M z = x`` in place (``x`` flat, length N) with the factorisation of :func:`factor`.

    ``y`` (float64, length N): scratch.
    """
    nbk = offsets.size - 1
    m = border.size
    nidx = idx.size
    ws = work.size - m * m - 2 * m * nidx
    sm = work[ws:ws + m * m].reshape((m, m))
    xt = work[ws + m * m:ws + m * m + m * nidx].reshape((m, nidx))
    ct = work[ws + m * m + m * nidx:ws + m * m + 2 * m * nidx].reshape((nidx, m))
    yi = y[:nidx]
    zb = y[nidx:nidx + m]
    for i in range(nidx):
        yi[i] = x[idx[i]]
    for r in range(m):
        zb[r] = x[border[r]]
    w0 = 0
    for k in range(nbk):  # y_k = D_k^{-1} r_k
        o = offsets[k]
        s = offsets[k + 1] - o
        d = work[w0:w0 + s * s].reshape((s, s))
        w0 += s * s + 2 * s * m
        _lu_solve_rows(d, s, piv, o, yi[o:o + s])
    for i in range(nidx):  # r_b -= C y
        v = yi[i]
        if v != 0.0:
            for r in range(m):
                zb[r] -= ct[i, r] * v
    _lu_solve_rows(sm, m, piv, nidx, zb)  # S z_b = r_b - C y
    for q in range(m):  # z = y - X z_b
        v = zb[q]
        if v != 0.0:
            for i in range(nidx):
                yi[i] -= xt[q, i] * v
    for i in range(nidx):
        x[idx[i]] = yi[i]
    for r in range(m):
        x[border[r]] = zb[r]
    return 0


class ArrowheadLU:
    """Factorise a dense arrowhead matrix once, solve many right-hand sides (NumPy front end of the kernels)."""

    def __init__(self, structure: ArrowheadStructure):
        self.s = structure
        self.piv = np.zeros(structure.n, np.int64)
        self.work = np.zeros(work_size(structure))
        self.scratch = np.zeros(structure.n)
        self.ok = False

    def factor(self, M) -> "ArrowheadLU":
        M = np.asarray(M, dtype=float)
        if M.shape != (self.s.n, self.s.n):
            raise ValueError(f"matrix shape {M.shape}, structure of size {self.s.n}")
        a = np.ascontiguousarray(M.T).ravel()  # column-major flat
        info = factor(a, self.s.n, self.s.idx, self.s.offsets, self.s.border, self.piv, self.work)
        self.ok = info == 0
        if info:
            raise np.linalg.LinAlgError(f"zero pivot in the arrowhead factorisation (position {info})")
        return self

    def solve(self, b) -> np.ndarray:
        if not self.ok:
            raise RuntimeError("factor first")
        x = np.array(b, dtype=float, copy=True)
        solve(self.s.n, self.s.idx, self.s.offsets, self.s.border, self.piv, self.work, x, self.scratch)
        return x


# ------------------------------------------------------------------------------------ CVODE linear-solver hook
@intrinsic
def _as_ptr(typingctx, addr):
    """int64 address -> void* (for numba.carray inside the C callbacks)."""
    sig = types.voidptr(types.int64)

    def codegen(context, builder, signature, args):
        return builder.inttoptr(args[0], context.get_value_type(types.voidptr))

    return sig, codegen


# Content block that replaces the dense solver's content while the hook is installed (int64 words).  Words
# 0-2 keep the layout of SUNDIALS' dense content {N, pivots*, last_flag} so that its remaining operations
# (lastflag, space) still read sensible values.
_W_N, _W_PIV, _W_LAST, _W_MAGIC, _W_NB, _W_M, _W_OFFS, _W_IDX, _W_BORDER, _W_NPIVOFF, _W_WORK, _W_NWORK, \
    _W_SCRATCH, _W_MDATA, _W_VDATA, _HEADER = range(16)
_MAGIC = 0x4152524F57484431  # "ARROWHD1"


@nb.njit(cache=True, nogil=True)
def _content(ls):
    """The hook's content words of the linear solver ``ls`` (its first field is the content pointer)."""
    addr = nb.carray(ls, 1, dtype=np.int64)[0]
    head = nb.carray(_as_ptr(addr), _HEADER, dtype=np.int64)
    total = head[_W_NPIVOFF] + head[_W_N]
    return nb.carray(_as_ptr(addr), total, dtype=np.int64)


@nb.njit(cache=True, nogil=True)
def _data_ptr(obj, word, n):
    """Data array of a SUNDIALS dense matrix / serial vector: the pointer is 64-bit word ``word`` of its content
    ({M, N, data*, ...} / {length, own_data, data*}: word 1 with 32-bit ``sunindextype``, 2 with 64-bit)."""
    c = nb.carray(obj, 1, dtype=np.int64)[0]
    data = nb.carray(_as_ptr(c), 3, dtype=np.int64)[word]
    return nb.carray(_as_ptr(data), n, dtype=np.float64)


@nb.njit(cache=True, nogil=True)
def _structure(w):
    """The arrowhead structure stored in the hook's content words ``w``: (n, idx, offs, border, piv) -- the order,
    the block-ordered state indices with their block offsets, the border indices and the pivot rows (views)."""
    n = w[_W_N]
    nbk, m = w[_W_NB], w[_W_M]
    offs = w[w[_W_OFFS]:w[_W_OFFS] + nbk + 1]
    idx = w[w[_W_IDX]:w[_W_IDX] + offs[nbk]]
    border = w[w[_W_BORDER]:w[_W_BORDER] + m]
    piv = w[w[_W_NPIVOFF]:w[_W_NPIVOFF] + n]
    return n, idx, offs, border, piv


@nb.njit(cache=True, nogil=True)
def _hook_setup(ls, mat):
    w = _content(ls)
    if w[_W_MAGIC] != _MAGIC:
        return -1
    n, idx, offs, border, piv = _structure(w)
    work = nb.carray(_as_ptr(w[_W_WORK]), w[_W_NWORK], dtype=np.float64)
    info = factor(_data_ptr(mat, w[_W_MDATA], n * n), n, idx, offs, border, piv, work)
    w[_W_LAST] = info
    return LUFACT_FAIL if info > 0 else 0


@nb.njit(cache=True, nogil=True)
def _hook_solve(ls, mat, x, b):
    w = _content(ls)
    if w[_W_MAGIC] != _MAGIC:
        return -1
    n, idx, offs, border, piv = _structure(w)
    xs = _data_ptr(x, w[_W_VDATA], n)
    bs = _data_ptr(b, w[_W_VDATA], n)
    for i in range(n):
        xs[i] = bs[i]
    work = nb.carray(_as_ptr(w[_W_WORK]), w[_W_NWORK], dtype=np.float64)
    scratch = nb.carray(_as_ptr(w[_W_SCRATCH]), n, dtype=np.float64)
    solve(n, idx, offs, border, piv, work, xs, scratch)
    w[_W_LAST] = 0
    return 0


check_compile_cache(globals())  # before the C callbacks below are compiled (or loaded from numba's cache)


@nb.cfunc(types.intc(types.voidptr, types.voidptr), nogil=True, cache=True)
def _setup_cb(ls, mat):
    """C callback ``int setup(SUNLinearSolver, SUNMatrix)``."""
    return _hook_setup(ls, mat)


@nb.cfunc(types.intc(types.voidptr, types.voidptr, types.voidptr, types.voidptr, types.double), nogil=True, cache=True)
def _solve_cb(ls, mat, x, b, tol):
    """C callback ``int solve(SUNLinearSolver, SUNMatrix, N_Vector x, N_Vector b, sunrealtype tol)``."""
    return _hook_solve(ls, mat, x, b)


check_compile_cache(globals())  # after the last cached function (numba caches keyed on sources and constants)


def _callbacks():
    """The two C callbacks (compiled once, then loaded from numba's on-disk cache)."""
    return _setup_cb, _solve_cb


def _sundials_lib(stem: str):
    """ctypes handle of scikit-sundae's bundled SUNDIALS library ``libsundials_<stem>`` (or None)."""
    from sksundae import _cy_cvode

    site = os.path.dirname(os.path.dirname(os.path.abspath(_cy_cvode.__file__)))
    paths = sorted(glob.glob(os.path.join(site, "scikit_sundae.libs", f"libsundials_{stem}*.so*")))
    if len(paths) != 1:
        return None
    try:
        return ctypes.CDLL(paths[0])
    except OSError:
        return None


class HookError(RuntimeError):
    """The dense solver of this scikit-sundae build cannot be replaced safely (layout not as checked)."""


@dataclass
class _Installed:
    ops: int  #: address of the solver's ops table
    setup_slot: int
    solve_slot: int
    old_setup: int
    old_solve: int
    ls: int
    old_content: int
    words: np.ndarray  #: our content (kept alive while installed)
    work: np.ndarray  #: factorisation workspace
    scratch: np.ndarray
    structure: ArrowheadStructure


def install(ls_addr: int, mat_addr: int, vec_addr: int, structure: ArrowheadStructure) -> _Installed:
    """Replace setup and solve of the SUNDIALS dense linear solver at ``ls_addr`` by the arrowhead kernels.

    ``mat_addr``: the dense SUNMatrix that CVODE factors (``A``), ``vec_addr``: a serial N_Vector of the same
    solver (used to check the vector layout).  Every assumption is checked against the SUNDIALS libraries
    scikit-sundae loaded before anything is written, and :class:`HookError` raised otherwise:
    the ops table holds SUNDIALS' own ``SUNLinSolSetup_Dense`` / ``SUNLinSolSolve_Dense`` (found by value,
    not by offset), the matrix is dense N x N with ``SUNDenseMatrix_Data`` at the offset the callbacks read,
    the vector's data pointer is ``N_VGetArrayPointer``'s.  Call :func:`uninstall` before the solver is freed.
    """
    dense = _sundials_lib("sunlinsoldense")
    mat = _sundials_lib("sunmatrixdense")
    core = _sundials_lib("core")
    if dense is None or mat is None or core is None:
        raise HookError("SUNDIALS dense solver/matrix libraries of scikit-sundae not found")
    vp = ctypes.c_void_p
    for lib, name, res in ((dense, "SUNLinSolSetup_Dense", ctypes.c_int), (dense, "SUNLinSolSolve_Dense", ctypes.c_int),
                           (mat, "SUNDenseMatrix_Data", vp), (mat, "SUNDenseMatrix_Rows", ctypes.c_int64),
                           (mat, "SUNDenseMatrix_Columns", ctypes.c_int64), (core, "N_VGetArrayPointer", vp),
                           (core, "N_VGetLength", ctypes.c_int64)):
        fn = getattr(lib, name, None)
        if fn is None:
            raise HookError(f"{name} not exported")
        fn.restype = res
        fn.argtypes = [vp]
    n = structure.n
    if mat.SUNDenseMatrix_Rows(vp(mat_addr)) != n or mat.SUNDenseMatrix_Columns(vp(mat_addr)) != n:
        raise HookError(f"the solver's matrix is not dense {n} x {n}")
    # the data pointer's word in the content (after M, N / length, own_data: 32- or 64-bit sunindextype)
    mcontent = ctypes.c_void_p.from_address(mat_addr).value
    mwords = (ctypes.c_void_p * 3).from_address(mcontent)
    mdata = [k for k in (1, 2) if mwords[k] == mat.SUNDenseMatrix_Data(vp(mat_addr))]
    if core.N_VGetLength(vp(vec_addr)) != n:
        raise HookError("vector length differs from the structure size")
    vcontent = ctypes.c_void_p.from_address(vec_addr).value
    vwords = (ctypes.c_void_p * 3).from_address(vcontent)
    vdata = [k for k in (1, 2) if vwords[k] == core.N_VGetArrayPointer(vp(vec_addr))]
    if mdata != vdata or len(mdata) != 1:
        raise HookError("dense matrix / serial vector content layouts are not {M, N, data, ...} / {length, own, data}")
    idx_bytes = 4 if mdata[0] == 1 else 8
    idx_type = ctypes.c_int32 if idx_bytes == 4 else ctypes.c_int64
    if idx_type.from_address(mcontent).value != n or idx_type.from_address(mcontent + idx_bytes).value != n:
        raise HookError("dense matrix content does not start with M = N = structure size")
    setup_addr = ctypes.cast(dense.SUNLinSolSetup_Dense, vp).value
    solve_addr = ctypes.cast(dense.SUNLinSolSolve_Dense, vp).value
    # SUNLinearSolver = {content, ops, sunctx} (SUNDIALS <= 7.2) or {content, python, ops, sunctx} (7.3+): the
    # ops table is the word after content that holds SUNDIALS' dense setup and solve (found by value)
    lsw = (ctypes.c_void_p * 3).from_address(ls_addr)
    old_content = lsw[0]
    if not old_content:
        raise HookError("linear solver has no content")
    ops, slots = None, {}
    for k in (1, 2):
        if lsw[k]:
            table = (ctypes.c_void_p * 15).from_address(lsw[k])  # 15 slots (SUNDIALS 6-7)
            found = {table[j]: j for j in range(15) if table[j]}
            if setup_addr in found and solve_addr in found:
                ops, slots = lsw[k], found
                break
    if ops is None:
        raise HookError("the linear solver is not SUNDIALS' dense solver (setup/solve not found in its ops)")
    table = (ctypes.c_void_p * 15).from_address(ops)
    if idx_type.from_address(old_content).value != n:
        raise HookError("dense solver content N differs from the structure size")
    k_setup, k_solve = slots[setup_addr], slots[solve_addr]
    if k_solve != k_setup + 1:
        raise HookError("setup and solve are not adjacent in the ops table")
    s = structure
    nbk, m = s.nblocks, s.border.size
    o_offs = _HEADER
    o_idx = o_offs + nbk + 1
    o_border = o_idx + s.idx.size
    o_piv = o_border + m
    words = np.zeros(o_piv + n, np.int64)
    words[_W_N], words[_W_MAGIC], words[_W_NB], words[_W_M] = n, _MAGIC, nbk, m
    words[_W_OFFS], words[_W_IDX], words[_W_BORDER], words[_W_NPIVOFF] = o_offs, o_idx, o_border, o_piv
    words[o_offs:o_idx] = s.offsets
    words[o_idx:o_border] = s.idx
    words[o_border:o_piv] = s.border
    words[_W_PIV] = words.ctypes.data + 8 * o_piv
    work = np.zeros(work_size(s))
    scratch = np.zeros(n)
    words[_W_WORK], words[_W_NWORK], words[_W_SCRATCH] = work.ctypes.data, work.size, scratch.ctypes.data
    words[_W_MDATA] = words[_W_VDATA] = mdata[0]
    cb_setup, cb_solve = _callbacks()
    inst = _Installed(ops=ops, setup_slot=k_setup, solve_slot=k_solve, old_setup=setup_addr, old_solve=solve_addr,
                      ls=ls_addr, old_content=old_content, words=words, work=work, scratch=scratch,
                      structure=structure)
    ctypes.c_void_p.from_address(ls_addr).value = words.ctypes.data
    table[k_setup] = cb_setup.address
    table[k_solve] = cb_solve.address
    return inst


def uninstall(inst: _Installed) -> None:
    """Put SUNDIALS' dense setup/solve and content back (the solver can then be freed as usual)."""
    table = (ctypes.c_void_p * 15).from_address(inst.ops)
    table[inst.setup_slot] = inst.old_setup
    table[inst.solve_slot] = inst.old_solve
    ctypes.c_void_p.from_address(inst.ls).value = inst.old_content
