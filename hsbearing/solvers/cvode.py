"""SUNDIALS CVODE (BDF) through scikit-sundae: the only module that imports ``sksundae``.

Nothing here knows about bearings.  :func:`integrate` advances
``y' = f(t, y)`` with CVODE's variable-order BDF (the counterpart of ADAMS'
GSTIFF), returns the solution at requested output times and the solver
statistics, and never hides a failure: on error it returns what was computed
up to the failure with ``status = "failed at t = ...: <message>"``.

Two stepping modes take the same internal steps, so they give the same
trajectory bit for bit: CVODE's step-size and order selection does not depend
on the output times, both run with the stop time at the last output, and both
start with one internal step towards it (CVODE's initial-step estimate is
bounded by the distance to the first requested time):

``"normal"`` (default when available)
    one CVODE call per output interval in ``CV_NORMAL`` mode: CVODE takes all
    internal steps of the interval in C and returns its own dense
    interpolation (``CVodeGetDky``) at the output time.  Python runs once per
    output, never per internal step.  scikit-sundae 1.2 reports only the
    cumulative rhs and Jacobian counts, so the statistics (steps, error-test
    and nonlinear-convergence failures, Newton iterations, linear-solver
    setups, last order and step) are read from CVODE's own counters with
    ``CVodeGetIntegratorStats`` / ``CVodeGetNonlinSolvStats`` of the SUNDIALS
    library that scikit-sundae ships and loads (see :class:`_CvodeCounters`).
``"onestep"``
    the previous path: ``CV_ONE_STEP`` calls counted in Python (one Python
    round trip per internal step), outputs by a normal-mode call behind the
    current time.  Used when CVODE's counters cannot be read safely (another
    scikit-sundae build or version) and kept for comparison
    (``benchmarks/bench_dynamics.py``).  When the counters are readable this
    mode reports them too, with the Python count as ``python_counted_steps``
    (an independent check of the counter read, ``tests/solvers/test_cvode_stepping.py``).

Failure, wall-time limit and Ctrl-C: an exception raised inside the rhs or
Jacobian (``KeyboardInterrupt`` included) makes CVODE return, scikit-sundae
re-raises it, and :func:`integrate` keeps every output reached so far.  In
normal mode the wall-time limit is checked after each output interval.
"""

from __future__ import annotations

import ctypes
import functools
import glob
import math
import os
import time as _time
from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import sksundae as sun

__all__ = ["IntegrationResult", "integrate", "counters_available", "arrowhead_available"]


@dataclass
class IntegrationResult:
    """Trajectory and statistics of one integration."""

    t: np.ndarray  #: output times actually reached [s], shape (n,)
    y: np.ndarray  #: states at ``t``, shape (n, N)
    status: str  #: "ok" or "failed at t = ...: message"
    stats: dict = field(default_factory=dict)  #: steps, rhs_evals, jac_evals, wall_time, ...

    @property
    def success(self) -> bool:
        return self.status == "ok"


# --------------------------------------------------------------------------------------------------------------
# CVODE's own counters
# --------------------------------------------------------------------------------------------------------------
_C_LONG_P = ctypes.POINTER(ctypes.c_long)
_C_INT_P = ctypes.POINTER(ctypes.c_int)
_C_DBL_P = ctypes.POINTER(ctypes.c_double)
_LIB = None  # ctypes handle of scikit-sundae's libsundials_cvode, False when not found


def _cvode_library():
    """The SUNDIALS CVODE shared library that scikit-sundae's extension is linked against (or None)."""
    global _LIB
    if _LIB is None:
        _LIB = False
        from sksundae import _cy_cvode

        site = os.path.dirname(os.path.dirname(os.path.abspath(_cy_cvode.__file__)))
        patterns = [os.path.join(site, "scikit_sundae.libs", "libsundials_cvode*.so*"),  # manylinux (auditwheel)
                    os.path.join(site, "sksundae", ".dylibs", "libsundials_cvode*.dylib"),  # macOS (delocate)
                    os.path.join(site, "scikit_sundae.libs", "sundials_cvode*.dll")]  # Windows (delvewheel)
        paths = sorted(p for pat in patterns for p in glob.glob(pat))
        if len(paths) == 1:
            try:
                lib = ctypes.CDLL(paths[0])
                lib.CVodeGetIntegratorStats.argtypes = [ctypes.c_void_p, _C_LONG_P, _C_LONG_P, _C_LONG_P, _C_LONG_P,
                                                        _C_INT_P, _C_INT_P, _C_DBL_P, _C_DBL_P, _C_DBL_P, _C_DBL_P]
                lib.CVodeGetNonlinSolvStats.argtypes = [ctypes.c_void_p, _C_LONG_P, _C_LONG_P]
                for name in ("CVodeGetNumRhsEvals", "CVodeGetNumJacEvals", "CVodeGetNumStepSolveFails"):
                    getattr(lib, name).argtypes = [ctypes.c_void_p, _C_LONG_P]
                _LIB = lib
            except (OSError, AttributeError):
                _LIB = False
    return _LIB or None


class _CvodeCounters:
    """Read CVODE's statistics from the solver memory of a scikit-sundae ``CVODE`` object.

    scikit-sundae 1.2 keeps the ``void *cvode_mem`` pointer in a private Cython attribute.  Its extension type
    stores, after the object header and the Cython vtable pointer, ``mem`` then ``ctx`` (``_cy_cvode.pyx``,
    ``cdef class CVODE``).  The pointer is accepted only if (i) the scikit-sundae version is one whose layout
    was checked (1.2.x), (ii) CVODE's memory record starts with that same ``SUNContext`` followed by the unit
    roundoff (``CVodeMemRec`` in SUNDIALS 7: ``cv_sunctx``, ``cv_uround``), and (iii) after the first CVODE
    call, ``CVodeGetNumRhsEvals`` through this pointer equals the count scikit-sundae itself reports.  If (i) or
    (ii) fails, :func:`integrate` falls back to the one-step path, which counts steps in Python; if (iii) fails
    in normal mode it raises (a layout that passes (i)-(ii) but reads wrong counts is a bug to report, not to
    hide), in one-step mode the counters are dropped.
    """

    _HEADER = ctypes.sizeof(ctypes.c_ssize_t) + ctypes.sizeof(ctypes.c_void_p)  # PyObject_HEAD

    def __init__(self, mem: int, lib):
        self.mem = ctypes.c_void_p(mem)
        self.lib = lib

    @classmethod
    def locate(cls, solver) -> "_CvodeCounters | None":
        lib = _cvode_library()
        if lib is None or not sun.__version__.startswith("1.2.") or not str(sun.SUNDIALS_VERSION).startswith("7."):
            return None
        cy = getattr(solver, "_CVODE__CVODE", None)
        from sksundae import _cy_cvode

        if not isinstance(cy, _cy_cvode.CVODE) or type(cy).__basicsize__ < cls._HEADER + 4 * 8:
            return None
        words = (ctypes.c_void_p * 3).from_address(id(cy) + cls._HEADER)  # vtable, mem, ctx
        mem, ctx = words[1], words[2]
        if not mem or not ctx:
            return None
        head = (ctypes.c_void_p * 1).from_address(mem)
        uround = ctypes.c_double.from_address(mem + ctypes.sizeof(ctypes.c_void_p)).value
        if head[0] != ctx or uround != np.finfo(float).eps:
            return None
        return cls(mem, lib)

    def nfev(self) -> int:
        n = ctypes.c_long()
        self.lib.CVodeGetNumRhsEvals(self.mem, ctypes.byref(n))
        return n.value

    def read(self) -> dict:
        """CVODE's cumulative statistics (CVodeGetIntegratorStats, CVodeGetNonlinSolvStats, CVodeGetNumJacEvals)."""
        nst, nfe, nsetups, netf = (ctypes.c_long() for _ in range(4))
        qlast, qcur = ctypes.c_int(), ctypes.c_int()
        h0, hlast, hcur, tcur = (ctypes.c_double() for _ in range(4))
        self.lib.CVodeGetIntegratorStats(self.mem, *(ctypes.byref(v) for v in (
            nst, nfe, nsetups, netf, qlast, qcur, h0, hlast, hcur, tcur)))
        nni, nncf, nje, nssf = (ctypes.c_long() for _ in range(4))
        self.lib.CVodeGetNonlinSolvStats(self.mem, ctypes.byref(nni), ctypes.byref(nncf))
        self.lib.CVodeGetNumJacEvals(self.mem, ctypes.byref(nje))
        self.lib.CVodeGetNumStepSolveFails(self.mem, ctypes.byref(nssf))
        return {"steps": nst.value, "rhs_evals": nfe.value, "jac_evals": nje.value,
                "error_test_failures": netf.value, "nonlinear_iterations": nni.value,
                "nonlinear_convergence_failures": nncf.value, "step_solve_failures": nssf.value,
                "linear_solver_setups": nsetups.value, "last_order": qlast.value, "last_step": hlast.value,
                "initial_step": h0.value}


#: CVODE optional inputs that :func:`integrate` can set through ``cvode_settings`` (name -> C argument type)
CVODE_SETTINGS = {
    "LSetupFrequency": ctypes.c_long,  # msbp: max steps between linear-solver setups (LU), default 20
    "JacEvalFrequency": ctypes.c_long,  # msbj: max steps between Jacobian evaluations, default 51
    "DeltaGammaMaxLSetup": ctypes.c_double,  # dgmax_lsetup: |gamma/gamma_p - 1| forcing a setup, default 0.2
    "DeltaGammaMaxBadJac": ctypes.c_double,  # dgmax_jbad: gamma ratio beyond which J is judged bad, default 0.2
    "NonlinConvCoef": ctypes.c_double,  # Newton convergence coefficient, default 0.1
}


def _apply_settings(counters: "_CvodeCounters | None", settings: dict | None) -> None:
    if not settings:
        return
    if counters is None:
        raise RuntimeError("cvode_settings need CVODE's solver memory, which cannot be reached with "
                           f"scikit-sundae {sun.__version__}")
    for name, value in settings.items():
        if name not in CVODE_SETTINGS:
            raise ValueError(f"unknown CVODE setting {name!r}; known: {', '.join(CVODE_SETTINGS)}")
        fn = getattr(counters.lib, f"CVodeSet{name}")
        fn.argtypes = [ctypes.c_void_p, CVODE_SETTINGS[name]]
        flag = fn(counters.mem, CVODE_SETTINGS[name](value))
        if flag < 0:
            raise ValueError(f"CVodeSet{name}({value!r}) failed with flag {flag}")


@functools.lru_cache(maxsize=1)
def counters_available() -> bool:
    """True if CVODE's own counters (and ``cvode_settings``) can be reached (normal-mode stepping available)."""
    solver = sun.cvode.CVODE(lambda t, y, yp: None)
    solver.init_step(0.0, np.zeros(1))
    return _CvodeCounters.locate(solver) is not None


@functools.lru_cache(maxsize=1)
def arrowhead_available() -> bool:
    """True if ``linsolver="arrowhead"`` can be installed in this scikit-sundae build.

    Checked once per process on its own 3-state problem y' = -y (block {0, 1}, border {2}), integrated to 1 ms
    with the hook installed and compared with exp(-t); the hook is removed again before the solver is freed.
    """
    from hsbearing.solvers.arrowhead import ArrowheadStructure, HookError

    solver = sun.cvode.CVODE(lambda t, y, yd: yd.__setitem__(slice(None), -y), method="BDF", rtol=1e-8, atol=1e-12,
                             linsolver="dense", jacfn=lambda t, y, yd, JJ: JJ.__setitem__(slice(None), -np.eye(3)))
    if not solver.init_step(0.0, np.ones(3)).success:
        return False
    counters = _CvodeCounters.locate(solver)
    try:
        hook = _install_arrowhead(solver, counters, ArrowheadStructure.from_blocks(3, [[0, 1]], [2]))
    except (RuntimeError, HookError):
        return False
    try:
        r = solver.step(1e-3, method="normal", tstop=1e-3)
        ok = r.status >= 0 and float(np.max(np.abs(np.asarray(r.y) - math.exp(-1e-3)))) < 1e-7
    finally:
        from hsbearing.solvers.arrowhead import uninstall

        uninstall(hook)
    return bool(ok)


# --------------------------------------------------------------------------------------------------------------
@dataclass
class _Progress:
    """What the stepping loops have done so far (read by the failure and Ctrl-C handlers)."""

    k_done: int = 1  #: outputs filled
    t_cur: float = 0.0  #: time CVODE has reached [s]
    steps: int = 0  #: internal steps (one-step mode only)
    nfev: int = 0
    njev: int = 0


def integrate(
    rhs: Callable,
    y0,
    t_eval,
    *,
    rtol: float = 1e-5,
    atol=1e-8,
    jacfn: Callable | None = None,
    method: str = "BDF",
    max_step: float = 0.0,
    first_step: float = 0.0,
    max_order: int | None = None,
    max_num_steps: int = 100000,
    linsolver: str = "dense",
    progress: bool = False,
    progress_desc: str = "simulating",
    wall_limit: float | None = None,
    callback: Callable | None = None,
    stepping: str = "auto",
    cvode_settings: dict | None = None,
    structure=None,
) -> IntegrationResult:
    """Integrate ``rhs(t, y, ydot)`` (in place) from ``t_eval[0]`` through ``t_eval``.

    Parameters
    ----------
    rhs : callable ``rhs(t, y, ydot)`` writing ``ydot[:]`` in place.
    y0 : initial state, shape (N,).
    t_eval : increasing output times [s]; ``t_eval[0]`` is the initial time.
    rtol, atol : CVODE tolerances (``atol`` scalar or per-state array).
    jacfn : optional ``jacfn(t, y, ydot, JJ)`` filling the dense (N, N) Jacobian.
    max_step, first_step, max_order : CVODE options (0 = CVODE default).
    max_num_steps : internal steps per CVODE call (normal mode: a call that takes this many steps without reaching
        the output time is resumed while time advances, with the wall limit checked in between).
    linsolver : linear solver of the Newton iteration: "dense" (SUNDIALS' own dense LU), "lapackdense" (LAPACK),
        or "arrowhead": the dense matrix CVODE forms, factorised by the block LU + Schur complement of
        :mod:`hsbearing.solvers.arrowhead` (``structure`` required; zeros outside the structure are never read,
        so the Jacobian must have none there).  Needs CVODE's solver memory (as the counters do).
    structure : :class:`hsbearing.solvers.arrowhead.ArrowheadStructure` of the Jacobian, for "arrowhead".
    progress : show a tqdm bar of simulated time with ETA (stderr), updated at each output.
    wall_limit : stop (status "failed ... wall-time limit") after this many seconds; checked at each output in
        normal mode, at each internal step in one-step mode.
    callback : optional ``callback(t, y)`` called at each output; a true return value stops the integration there
        (status "ok", ``stats["stopped_by_callback"]`` = that time): the outputs so far are exactly the prefix of
        the full integration (the solver is not restarted).
    stepping : "normal" (one CVODE call per output interval, statistics from CVODE's counters), "onestep"
        (one Python round trip per internal step, steps counted in Python) or "auto" (normal when CVODE's
        counters can be read, else onestep).  Both take the same internal steps.
    cvode_settings : optional CVODE inputs scikit-sundae does not expose, ``{name: value}`` with names from
        :data:`CVODE_SETTINGS` (``CVodeSet<name>``), e.g. ``{"LSetupFrequency": 50}``; default: CVODE's defaults.
    """
    if stepping not in ("auto", "normal", "onestep"):
        raise ValueError(f"stepping must be 'auto', 'normal' or 'onestep', got {stepping!r}")
    t_eval = np.asarray(t_eval, dtype=float)
    y0 = np.ascontiguousarray(y0, dtype=float)
    ys = np.empty((t_eval.size, y0.size))
    ys[0] = y0
    if linsolver == "arrowhead":
        if structure is None or structure.n != y0.size:
            raise ValueError("linsolver='arrowhead' needs the arrowhead structure of the Jacobian (structure=), "
                             f"of size {y0.size}")
    options = dict(method=method, rtol=rtol, atol=atol, max_num_steps=max_num_steps,
                   linsolver="dense" if linsolver == "arrowhead" else linsolver)
    if jacfn is not None:
        options["jacfn"] = jacfn
    if max_step:
        options["max_step"] = max_step
    if first_step:
        options["first_step"] = first_step
    if max_order:
        options["max_order"] = max_order
    solver = sun.cvode.CVODE(rhs, **options)
    t0, t_end = float(t_eval[0]), float(t_eval[-1])
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=t_end - t0, desc=progress_desc, unit="s", unit_scale=True, leave=True,
                   bar_format="{l_bar}{bar}| {n:.4g}/{total:.4g} s simulated [{elapsed}<{remaining}]")
    wall0 = _time.perf_counter()
    status = "ok"
    pr = _Progress(t_cur=t0)
    counters = None
    normal = False
    stopped = None
    hook = None
    try:
        init = solver.init_step(t0, y0)
        if not init.success:
            raise _Failure(t0, init.message)
        counters = _CvodeCounters.locate(solver)
        if linsolver == "arrowhead":
            hook = _install_arrowhead(solver, counters, structure)
        if counters is None and stepping == "normal":
            raise RuntimeError("normal-mode stepping needs CVODE's counters, which cannot be read with "
                               f"scikit-sundae {sun.__version__}; use stepping='onestep'")
        _apply_settings(counters, cvode_settings)
        normal = counters is not None and stepping != "onestep"
        loop = _normal_loop if normal else _onestep_loop
        loop(solver, counters, t_eval, ys, pr, wall0, wall_limit, callback, bar)
    except _Stop as exc:
        stopped = exc.t
    except _Failure as exc:
        status = f"failed at t = {exc.t:.6g} s: {exc.message}"
    except KeyboardInterrupt:
        status = f"failed at t = {float(t_eval[pr.k_done - 1]):.6g} s: interrupted"
    finally:
        if hook is not None:
            from hsbearing.solvers.arrowhead import uninstall

            uninstall(hook)  # before scikit-sundae frees its dense solver
        if bar is not None:
            bar.close()
    wall = _time.perf_counter() - wall0
    stats = {
        "method": f"CVODE {method} (SUNDIALS {sun.SUNDIALS_VERSION}, scikit-sundae {sun.__version__})",
        "steps": pr.steps,
        "rhs_evals": pr.nfev,
        "jac_evals": pr.njev,
        "wall_time": wall,
        "rtol": rtol,
        "atol": float(np.min(atol)) if np.ndim(atol) else float(atol),
        "jacobian": "user" if jacfn is not None else "CVODE finite differences",
        "linear_solver": linsolver if hook is None else f"arrowhead block LU + Schur complement "
                                                          f"({structure.describe()}) in CVODE's dense interface",
    }
    if stopped is not None:
        stats["stopped_by_callback"] = float(stopped)
    if cvode_settings:
        stats["cvode_settings"] = ", ".join(f"{k}={v}" for k, v in cvode_settings.items())
    if counters is not None and not normal and pr.nfev and counters.nfev() != pr.nfev:
        counters = None  # (iii) of _CvodeCounters failed: keep only the Python count
    if counters is not None:
        if not normal:
            stats["python_counted_steps"] = pr.steps
        stats.update(counters.read())
    if normal:
        stats["stepping"] = "CVODE normal mode, one call per output interval; statistics from CVODE's counters"
    elif counters is not None:
        stats["stepping"] = "CVODE one-step mode (Python per internal step); statistics from CVODE's counters"
    else:
        stats["stepping"] = ("CVODE one-step mode, steps counted in Python; error-test and convergence failures "
                             "not available")
    k = pr.k_done
    return IntegrationResult(t=t_eval[:k].copy(), y=ys[:k].copy(), status=status, stats=stats)


def _install_arrowhead(solver, counters, structure):
    """Swap the arrowhead factorisation into the dense linear solver scikit-sundae attached (see arrowhead.install).

    The solver, its matrix and a state vector are read from scikit-sundae 1.2's ``CVODE`` extension object
    (fields ``mem, ctx, atol, constraints, yy, A, LS`` after the vtable, ``_cy_cvode.pyx``) only when the
    counters' checks of that layout passed; :func:`hsbearing.solvers.arrowhead.install` checks the rest against
    the SUNDIALS libraries before writing anything.
    """
    from hsbearing.solvers.arrowhead import HookError, install

    if counters is None:
        raise RuntimeError("linsolver='arrowhead' needs CVODE's solver memory, which cannot be reached with "
                           f"scikit-sundae {sun.__version__}")
    cy = solver._CVODE__CVODE  # the private Cython object (scikit-sundae mangles CVODE.__CVODE to this name)
    words = (ctypes.c_void_p * 8).from_address(id(cy) + _CvodeCounters._HEADER)
    if words[1] != counters.mem.value or not (words[5] and words[6] and words[7]):
        raise RuntimeError("linsolver='arrowhead': scikit-sundae's solver layout is not the one checked")
    try:
        return install(words[7], words[6], words[5], structure)
    except HookError as exc:
        raise RuntimeError(f"linsolver='arrowhead' cannot be installed: {exc}") from None


def _normal_loop(solver, counters, t_eval, ys, pr, wall0, wall_limit, callback, bar):
    """One ``CV_NORMAL`` call per output interval; no Python work per internal step."""
    t_end = float(t_eval[-1])
    if t_eval.size < 2:
        return
    # The first call is one internal step towards t_end, as in one-step mode: CVODE's initial step estimate
    # (cvHin) is bounded by the distance to the first tout, so starting with tout = t_eval[1] would choose a
    # different h0 and a different (equally valid) step sequence.  Later calls ask for the output times.
    r = solver.step(t_end, method="onestep", tstop=t_end)
    if counters.nfev() != int(r.nfev):  # (iii) of _CvodeCounters: the pointer reads scikit-sundae's counts
        raise RuntimeError("CVODE counters read through the solver memory disagree with scikit-sundae's "
                           f"({counters.nfev()} vs {int(r.nfev)} rhs evaluations): use stepping='onestep'")
    if r.status < 0 or not np.isfinite(r.t):
        raise _Failure(pr.t_cur, r.message)
    pr.t_cur = float(r.t)
    for k in range(1, t_eval.size):
        t_out = float(t_eval[k])
        r = solver.step(t_out, method="normal", tstop=t_end)
        # CV_TOO_MUCH_WORK: max_num_steps internal steps without reaching t_out.  Resume while time advances (the
        # one-step path has no per-interval limit either; the same steps follow); the wall limit is checked at
        # every resumption, so a long output interval is not an unchecked stretch.
        while r.status == _CV_TOO_MUCH_WORK and np.isfinite(r.t) and float(r.t) > pr.t_cur:
            pr.t_cur = float(r.t)
            if wall_limit is not None and _time.perf_counter() - wall0 > wall_limit:
                raise _Failure(pr.t_cur, f"wall-time limit of {wall_limit:g} s reached")
            r = solver.step(t_out, method="normal", tstop=t_end)
        if r.status < 0 or not np.isfinite(r.t):
            raise _Failure(float(r.t) if np.isfinite(r.t) else pr.t_cur, r.message)
        pr.t_cur = float(r.t)
        if pr.t_cur != t_out:  # CVODE returns exactly tout (interpolated) or tstop = t_end
            raise _Failure(pr.t_cur, f"CVODE returned at t = {pr.t_cur!r} instead of the output time {t_out!r}")
        ys[k] = r.y
        _accept_output(k, t_eval, ys, pr, callback, bar)
        if wall_limit is not None and _time.perf_counter() - wall0 > wall_limit:
            raise _Failure(t_out, f"wall-time limit of {wall_limit:g} s reached")


def _accept_output(k, t_eval, ys, pr, callback, bar):
    """Output k is stored in ys[k]: check it is finite, count it, report it (callback, progress bar)."""
    t_out = float(t_eval[k])
    if not math.isfinite(ys[k].sum()):  # one reduction (a third of np.all(np.isfinite()))
        raise _Failure(t_out, "non-finite state")
    pr.k_done = k + 1
    stop = callback is not None and callback(t_out, ys[k])
    if bar is not None:
        bar.update(t_out - float(t_eval[k - 1]))
    if stop:
        raise _Stop(t_out)


def _onestep_loop(solver, counters, t_eval, ys, pr, wall0, wall_limit, callback, bar):
    """``CV_ONE_STEP`` calls counted in Python (one Python round trip per internal step)."""
    t_end = float(t_eval[-1])
    r = None
    for k in range(1, t_eval.size):
        t_out = float(t_eval[k])
        while pr.t_cur < t_out:
            r = solver.step(t_end, method="onestep", tstop=t_end)
            if r.status < 0 or not np.isfinite(r.t):
                raise _Failure(pr.t_cur, r.message)
            if r.t > pr.t_cur:  # after a dense-output call the next one-step call may return in place
                pr.steps += 1
            pr.t_cur = float(r.t)
            pr.nfev, pr.njev = int(r.nfev), int(r.njev)
            if wall_limit is not None and _time.perf_counter() - wall0 > wall_limit:
                raise _Failure(pr.t_cur, f"wall-time limit of {wall_limit:g} s reached")
        if t_out == pr.t_cur:
            ys[k] = r.y
        else:
            ro = solver.step(t_out)  # dense output inside the last step
            if ro.status < 0:
                raise _Failure(pr.t_cur, ro.message)
            ys[k] = ro.y
        _accept_output(k, t_eval, ys, pr, callback, bar)


_CV_TOO_MUCH_WORK = -1  # CVODE return flag (cvode.h)


class _Failure(Exception):
    def __init__(self, t: float, message: str):
        super().__init__(message)
        self.t = t
        self.message = message


class _Stop(Exception):
    """The output callback asked to stop at ``t`` (not a failure)."""

    def __init__(self, t: float):
        super().__init__(f"stopped at t = {t}")
        self.t = t
