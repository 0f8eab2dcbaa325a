"""Where the points run: in this process, a local process pool (crash isolation, Ctrl-C) or a dask.distributed cluster."""

from __future__ import annotations

import contextlib
import multiprocessing
import os
import re
import signal
import sys
import threading
import time
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from pathlib import Path

from hsbearing.case import (
    CaseError,
)
from hsbearing.errors import ClusterLost
from hsbearing.workflows.sweeps.points import compute_point, worker_init

# ----------------------------------------------------------------------------- execution backends


class SerialBackend:
    """jobs=1: compute in the calling process."""

    name = "serial"

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def run(self, tasks, on_done):
        for key, args in tasks:
            on_done(key, *compute_point(*args))


class LocalPoolBackend:
    """Local worker processes; a crashed worker does not take the sweep down."""

    name = "processes"

    def __init__(self, jobs: int):
        self.jobs = jobs
        self.ctx = mp_context()
        self.ex: ProcessPoolExecutor | None = None

    def _new(self, n):
        return ProcessPoolExecutor(max_workers=n, mp_context=self.ctx, initializer=worker_init, initargs=(os.getpid(),))

    def __enter__(self):
        return self

    def __exit__(self, exc_type, *exc):
        if self.ex is not None:
            if exc_type is not None:  # interrupted: do not wait for running points
                _terminate(self.ex)
            self.ex.shutdown(wait=exc_type is None, cancel_futures=True)
            self.ex = None
        return False

    def run(self, tasks, on_done):
        tasks = list(tasks)
        if not tasks:
            return
        suspects = self._run_batch(tasks, on_done, min(self.jobs, len(tasks)))
        # Points that were in flight when a worker died: one at a time, to find the culprit.
        for key, args in suspects:
            again = self._run_batch([(key, args)], on_done, 1)
            for k, _ in again:
                on_done(k, {"status": "crashed", "error": "worker process died while computing this point "
                            "(segfault, out of memory or killed)", "summary": {}, "wall_time": float("nan")}, None)

    def _run_batch(self, tasks, on_done, n) -> list:
        pending = list(tasks)
        suspects: list = []
        self.ex = self._new(n)
        futs = {}
        try:
            while pending or futs:
                while pending and len(futs) < 2 * n:  # keep the queue short: cancellable, fair
                    key, args = pending.pop(0)
                    futs[self.ex.submit(compute_point, *args)] = (key, args)
                done, _ = wait(list(futs), timeout=_POLL, return_when=FIRST_COMPLETED)
                _check_interrupt()
                broken = False
                for f in done:
                    key, args = futs.pop(f)
                    try:
                        rec, ds = f.result()
                    except BrokenProcessPool:
                        suspects.append((key, args))
                        broken = True
                        continue
                    except Exception as exc:  # e.g. a point function that cannot be pickled
                        rec, ds = {"status": "error", "error": f"{type(exc).__name__}: {exc}", "summary": {},
                                   "wall_time": float("nan")}, None
                    on_done(key, rec, ds)
                if broken:
                    # every other in-flight point died with the pool: suspects too
                    for _f, (key, args) in futs.items():
                        suspects.append((key, args))
                    futs.clear()
                    self.ex.shutdown(wait=True, cancel_futures=True)
                    self.ex = self._new(n)
        except BaseException:
            _terminate(self.ex)
            self.ex.shutdown(wait=False, cancel_futures=True)
            self.ex = None
            raise
        self.ex.shutdown(wait=True)
        self.ex = None
        return suspects


#: Seconds between checks of a deferred Ctrl-C while waiting for points.
_POLL = 0.2
_INTERRUPTED = threading.Event()


def _check_interrupt() -> None:
    if _INTERRUPTED.is_set():
        _INTERRUPTED.clear()
        raise KeyboardInterrupt


@contextlib.contextmanager
def deferred_sweep_sigint():
    """Turn Ctrl-C into a flag checked between waits.

    A KeyboardInterrupt raised *inside* concurrent.futures (or distributed) internals can leave
    a future's lock held, and the executor's manager thread then blocks forever at exit
    (observed: `hsbearing sweep` hung after Ctrl-C).  The flag is checked at safe points
    (:func:`_check_interrupt`) and raises KeyboardInterrupt there.  Only in the main thread and
    only if Python's default handler is installed; otherwise nothing changes.
    """
    if threading.current_thread() is not threading.main_thread() or \
            signal.getsignal(signal.SIGINT) is not signal.default_int_handler:
        yield
        return
    _INTERRUPTED.clear()
    old = signal.signal(signal.SIGINT, lambda signum, frame: _INTERRUPTED.set())
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, old)
    _check_interrupt()  # a Ctrl-C during the last wait still interrupts


def mp_context():
    """``spawn``: every worker is a direct child of the sweep process, so it dies with it.

    (``forkserver`` starts workers ~0.3 s faster here, but its workers are children of the fork
    server: when the sweep process is SIGKILLed, the server and its idle workers were observed to
    stay alive as orphans.  ``HSBEARING_MP_START=forkserver`` still selects it.)

    ``spawn`` (and ``forkserver``) workers re-import the caller's ``__main__`` script.  When the sweep
    is started from a script's top level outside ``if __name__ == "__main__":`` (the README example
    saved as a file), that re-import would start the sweep again in every worker, and every point
    would die.  Then the workers are forked instead (Linux: ``fork`` does not
    re-run the script); where fork is not safe (macOS, Windows) a CaseError names the missing guard.
    """
    unguarded = unguarded_main_call()
    if unguarded is not None:
        if sys.platform.startswith("linux") and "fork" in multiprocessing.get_all_start_methods():
            return multiprocessing.get_context("fork")
        raise CaseError(unguarded, None, "hsbearing.sweep with jobs > 1 called outside an "
                        "'if __name__ == \"__main__\":' block: the worker processes re-import the script; "
                        "put the call under that guard (or pass jobs=1)")
    method = os.environ.get("HSBEARING_MP_START") or "spawn"
    ctx = multiprocessing.get_context(method)
    if method == "forkserver":
        ctx.set_forkserver_preload(["hsbearing.workflows.sweeps"])
    return ctx


def unguarded_main_call() -> str | None:
    """``"script.py:LINE"`` if the current call comes from the top-level code of a ``__main__`` script
    outside an ``if __name__ == "__main__":`` block (the statement that spawn workers would re-run), else None.

    Interactive sessions and ``python -c`` have no script file and are never re-run.  A script whose
    source cannot be read or parsed is assumed guarded.
    """
    import ast

    main = sys.modules.get("__main__")
    path = getattr(main, "__file__", None)
    if not path or main is None:
        return None
    frame = sys._getframe(1)
    while frame is not None and not (frame.f_globals is main.__dict__ and frame.f_code.co_name == "<module>"):
        frame = frame.f_back
    if frame is None:
        return None
    line = frame.f_lineno
    try:
        tree = ast.parse(Path(path).read_text(encoding="utf-8"), filename=str(path))
    except (OSError, SyntaxError, UnicodeDecodeError, ValueError):
        return None
    for node in tree.body:
        if node.lineno <= line <= (node.end_lineno or node.lineno):
            return None if isinstance(node, ast.If) and _is_main_guard(node.test) else f"{path}:{line}"
    return None


def _is_main_guard(test) -> bool:
    import ast

    if not (isinstance(test, ast.Compare) and len(test.ops) == 1 and isinstance(test.ops[0], ast.Eq)):
        return False
    sides = [test.left, test.comparators[0]]
    names = [x for x in sides if isinstance(x, ast.Name) and x.id == "__name__"]
    consts = [x for x in sides if isinstance(x, ast.Constant) and x.value == "__main__"]
    return len(names) == 1 and len(consts) == 1


#: Seconds a terminated worker gets to go before it is killed (SIGKILL); the sweep waits for every worker.
_REAP_GRACE = 3.0


def _terminate(ex: ProcessPoolExecutor | None) -> None:
    """Stop every worker of ``ex`` and wait until each is gone: SIGTERM, up to :data:`_REAP_GRACE` s, then
    SIGKILL.  A sweep, a map or a study that ends (error, Ctrl-C, a write that fails) leaves no process behind,
    also when the executor is not joined afterwards (shutdown(wait=False)) or a worker is slow to stop."""
    if ex is None:
        return
    procs = list((getattr(ex, "_processes", None) or {}).values())
    for p in procs:
        with contextlib.suppress(Exception):
            p.terminate()
    deadline = time.monotonic() + _REAP_GRACE
    for p in procs:
        with contextlib.suppress(Exception):
            p.join(max(0.0, deadline - time.monotonic()))
    for p in procs:
        with contextlib.suppress(Exception):
            if p.is_alive():
                p.kill()
                p.join(5.0)


_SCHEDULER_ADDRESS = re.compile(
    r"^(?:(?:tcp|tls|ws|wss|ucx)://)?(?:[A-Za-z0-9](?:[A-Za-z0-9.-]*[A-Za-z0-9])?|\[[0-9A-Fa-f:.]+\]):(\d{1,5})/?$")


def check_scheduler_address(address: str, *, in_process_ok: bool = False) -> str:
    """A dask.distributed scheduler address ``[tcp://]host:port`` (also tls/ws/wss/ucx, ``inproc://``);
    CaseError naming ``--scheduler`` otherwise, at once (the client would retry an unparseable
    address until its connect timeout)."""
    a = str(address).strip()
    proto = a.split("://", 1)[0].lower() if "://" in a else "tcp"
    if proto == "inproc":  # a scheduler living in this very process (a library caller's LocalCluster(processes=False))
        if not in_process_ok:
            raise CaseError("--scheduler", None, f"{address!r}: an inproc:// scheduler exists only inside the process "
                                                 "that started it; give its tcp://host:port address")
        if len(a) > len("inproc://"):
            return a
    if proto == "tls":
        raise CaseError("--scheduler", None, f"{address!r}: TLS schedulers need a security configuration (certificates) "
                                             "that hsbearing does not pass; use a tcp:// or ws:// address (e.g. over an "
                                             "SSH tunnel)")
    if proto == "ucx":
        import importlib.util

        if importlib.util.find_spec("ucp") is None and importlib.util.find_spec("distributed_ucxx") is None:
            raise CaseError("--scheduler", None, f"{address!r}: the ucx:// protocol needs ucx-py, which is not "
                                                 "installed; use a tcp:// address")
    m = _SCHEDULER_ADDRESS.match(a)
    if not m or not 0 < int(m.group(1)) < 65536:
        raise CaseError("--scheduler", None, f"{address!r} is not a scheduler address (expected [tcp://]host:port, "
                                             "e.g. tcp://127.0.0.1:8786)")
    return a


class DaskBackend:
    """Submit the points to an existing dask.distributed scheduler."""

    name = "dask"

    #: seconds to wait for the scheduler before reporting bad input
    CONNECT_TIMEOUT = 15.0

    def __init__(self, address: str, timeout: float | None = None):
        check_scheduler_address(address, in_process_ok=True)
        self.address = address
        self.timeout = self.CONNECT_TIMEOUT if timeout is None else timeout
        self.client = None

    def __enter__(self):
        try:
            from distributed import Client
        except ImportError:  # pragma: no cover - dask[distributed] is a dependency
            raise CaseError("--scheduler", None, "dask.distributed is not installed") from None
        try:
            self.client = Client(self.address, timeout=self.timeout, set_as_default=False)
            # a worker-less scheduler would queue forever: say so (the tasks still wait for workers)
            if not self.client.scheduler_info().get("workers"):
                print(f"hsbearing: the dask scheduler at {self.address} has no workers yet; tasks wait for one",
                      file=sys.stderr)
        except (OSError, TimeoutError) as exc:
            raise CaseError("--scheduler", None, f"cannot connect to the dask scheduler at {self.address} ({exc})") from None
        except (TypeError, ValueError, RuntimeError, ImportError) as exc:  # a protocol the client cannot set up
            raise CaseError("--scheduler", None, f"cannot connect to the dask scheduler at {self.address} "
                                                 f"({type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''})") from None
        return self

    def __exit__(self, exc_type, *exc):
        if self.client is not None:
            lost = str(getattr(self.client, "status", "running")) != "running"
            # a lost scheduler must not hold the exit, nor bury the one line that says so under the tracebacks
            # distributed logs while its reconnection attempt is cancelled
            if lost:
                import logging

                logging.disable(logging.CRITICAL)
            try:
                with contextlib.suppress(Exception):
                    self.client.close(timeout=10)
            finally:
                if lost:
                    logging.disable(logging.NOTSET)
            self.client = None
        return False

    def _check_scheduler(self, force: bool = False) -> None:
        """ClusterLost when the client has lost its scheduler (its futures are gone with it); ``force``: a
        future was cancelled by no one here, so the scheduler is taken as lost unless it answers at once."""
        status = str(getattr(self.client, "status", "running"))
        if status == "running" and force:
            try:
                self.client.scheduler_info()  # cached; a dead comm shows in the status right after
                status = str(self.client.status)
                if status == "running":
                    return
            except Exception:  # noqa: BLE001 - any failure to reach it is the same news
                status = "unreachable"
        if status != "running":
            raise ClusterLost(f"lost the dask scheduler at {self.address} (client {status})")

    def run(self, tasks, on_done):
        tasks = list(tasks)
        killed = self._run_batch(tasks, on_done)
        # Points whose worker died (KilledWorker): possibly innocent neighbours of the point that kills
        # its worker.  Re-run them one at a time, so the culprit is identified exactly.
        for key, args, _ in killed:
            for k, _, exc in self._run_batch([(key, args)], on_done):
                on_done(k, {"status": "crashed", "error": f"worker process died while computing this point "
                            f"({type(exc).__name__}: {exc})", "summary": {}, "wall_time": float("nan")}, None)

    def _run_batch(self, tasks, on_done) -> list:
        import uuid

        from distributed import as_completed

        futs = {}
        killed = []
        tag = uuid.uuid4().hex[:8]
        for key, args in tasks:
            point = args[0]
            name = f"hsbearing-point-{point.name if point is not None else 'x'}-{key}-{tag}"
            futs[self.client.submit(compute_point, *args, key=name, pure=False)] = (key, args)
        try:
            with self.client.as_current():
                finished = as_completed(list(futs))
            for f in _poll_iter(finished, self._check_scheduler):
                key, args = futs[f]
                try:
                    rec, ds = f.result()
                except Exception as exc:
                    if type(exc).__name__ == "KilledWorker":
                        killed.append((key, args, exc))
                        continue
                    if f.cancelled() or "Cancelled" in type(exc).__name__:
                        # not the point's doing: the scheduler forgot it (lost, restarted) -- never a record
                        self._check_scheduler(force=True)
                    rec, ds = {"status": "error", "error": f"{type(exc).__name__}: {exc}", "summary": {},
                               "wall_time": float("nan")}, None
                on_done(key, rec, ds)
        except BaseException:
            for f in futs:
                with contextlib.suppress(Exception):
                    f.cancel()
            raise
        return killed


def _poll_iter(ac, check=None):
    """Iterate a distributed.as_completed, checking for a deferred Ctrl-C (and ``check()``: the scheduler is
    still there) between results."""
    while True:
        batch = ac.next_batch(block=False) if hasattr(ac, "next_batch") else None
        if batch:
            yield from batch
            continue
        if ac.is_empty():
            return
        _check_interrupt()
        if check is not None:
            check()
        time.sleep(_POLL / 4)


def make_backend(jobs: int | None, scheduler: str | None):
    if scheduler:
        return DaskBackend(scheduler)
    jobs = (os.cpu_count() or 1) if jobs is None else int(jobs)
    if jobs < 1:
        raise CaseError("-j", None, f"jobs must be >= 1, got {jobs}")
    return SerialBackend() if jobs == 1 else LocalPoolBackend(jobs)
