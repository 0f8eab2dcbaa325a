"""No process outlives a sweep or a map, on any exit path: a write that fails (read-only directory: EROFS; disk
full: ENOSPC), an error raised while a point's result is handled, Ctrl-C.

Each fault is driven in a subprocess that leads its own process group (``start_new_session``); after it has
exited, every process still in that group is an orphan (the pool workers, the resource tracker and the
spawned helpers inherit the group).  The unwritable directory is a monkeypatched write raising
OSError(EROFS): as root, chmod does not stop a write, and neither a read-only bind mount nor ``chattr +i``
is available everywhere the tests run.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import psutil
import pytest

HERE = Path(__file__).resolve().parent

_DRIVER = textwrap.dedent(
    """
    import errno, os, sys
    sys.path.insert(0, {tests!r})
    import hsbearing, test_no_orphans
    import importlib
    ex = importlib.import_module("hsbearing.workflows.sweeps.execute")
    fault, what, out = {fault!r}, {what!r}, {out!r}
    orig, n = ex.write_point_archive, [0]

    def write(*a, **k):
        n[0] += 1
        if n[0] >= 2 and fault in ("erofs", "enospc", "error"):
            if fault == "error":
                raise RuntimeError("a bug while keeping a point (test)")
            code = errno.EROFS if fault == "erofs" else errno.ENOSPC
            raise OSError(code, os.strerror(code), str(a[2]))
        return orig(*a, **k)

    import os
    ex.write_point_archive = write
    loads = ",".join(str(x) for x in range(100, 2100, 100)) + "N"
    if what == "sweep":
        hsbearing.sweep("zhang2016", {{"axial_load": loads}}, out_dir=out, kind="quasistatic",
                        point_fn=test_no_orphans.stubborn_qs, jobs=2, progress=False)
    else:
        from hsbearing.workflows.maps import run_map
        run_map("zhang2016", x=("axial_load", "100,200,300,400,500N"), y=("radial_load", "0,100,200,300N"),
                out_dir=out, jobs=2, point_fn=test_no_orphans.stubborn_qs, figure=False, progress=False, stop=None)
    """
)


def stubborn_qs(case, duration):
    """A point whose worker does not stop on SIGTERM (a worker stuck where the signal does not reach it, or in
    a library that handles SIGTERM itself): a sweep that only terminates its workers leaves it running (or
    waits for it forever at exit)."""
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    if case.operating.axial_load > 200.0:  # a long point: the workers are busy when the fault comes
        time.sleep(600.0)
    import test_sweeps

    return test_sweeps.sleepy_qs(case, duration)


#: Seconds a process of the sweep's group that is already exiting at the sweep's exit has to be gone.
EXITING_GRACE = 3.0


def _what(p: psutil.Process) -> str:
    """Name, parent, state and age of a process left behind."""
    try:
        return f"{p.name()} ppid {p.ppid()} {p.status()} started {time.time() - p.create_time():.2f} s ago"
    except psutil.Error as exc:
        return f"gone ({type(exc).__name__})"


def _group(pgid: int) -> list[psutil.Process]:
    out = []
    for p in psutil.process_iter(["pid", "status"]):
        try:
            if os.getpgid(p.pid) == pgid and p.info["status"] != psutil.STATUS_ZOMBIE:
                out.append(p)
        except (ProcessLookupError, psutil.Error, OSError):
            continue
    return out


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="process groups and /proc: Linux")
@pytest.mark.parametrize("what, fault", [("sweep", "erofs"), ("sweep", "enospc"), ("sweep", "error"),
                                         ("sweep", "sigint"), ("map", "erofs"), ("map", "sigint")])
def test_no_process_outlives_a_failed_sweep_or_map(tmp_path, what, fault):
    out = tmp_path / "out"
    code = _DRIVER.format(tests=str(HERE), fault=fault, what=what, out=str(out))
    proc = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True, preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        if fault == "sigint":  # Ctrl-C once two points are kept and the workers are busy with the long ones
            deadline = time.time() + 120
            while time.time() < deadline and len(list(out.glob("zhang2016-*.nc"))) < 2 and proc.poll() is None:
                time.sleep(0.02)
            assert proc.poll() is None, proc.communicate()
            workers = [c.pid for c in psutil.Process(proc.pid).children(recursive=True)]
            assert workers  # there is something to leave behind
            proc.send_signal(signal.SIGINT)
        try:
            _, err = proc.communicate(timeout=90)
            hung = False
        except subprocess.TimeoutExpired:  # the sweep process waits for a worker that never stops
            hung = True
            err = ""
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    leftover = [(p.pid, " ".join(p.cmdline())[:120]) for p in _group(proc.pid) if p.is_running()]
    if hung:
        for p in _group(proc.pid):
            p.kill()
    assert not hung, f"the {what} did not end after {fault}: waiting for {leftover}"
    assert proc.returncode != 0, err[-800:]  # the fault was acted on
    if fault == "sigint":
        assert "KeyboardInterrupt" in err or "Interrupted" in err, err[-800:]
    else:
        assert ("RuntimeError" if fault == "error" else "OSError") in err, err[-800:]
    # the sweep process reaps its workers before it exits: at its exit, every process of the group is an orphan.
    # One that is still exiting at that instant (empty command line: its memory already released) is given up to
    # EXITING_GRACE s to be gone: under load multiprocessing's resource tracker, a child of the sweep in its group
    # that ends only once the sweep's end of its pipe is closed, was seen exiting just after the sweep (parent 1,
    # started with the pool). Anything still there after the grace is an orphan.
    deadline = time.monotonic() + EXITING_GRACE
    left = _group(proc.pid)
    while left and time.monotonic() < deadline:
        if any(p.is_running() and p.cmdline() for p in left):  # a live process with a command line: no waiting
            break
        time.sleep(0.05)
        left = _group(proc.pid)
    desc = [(p.pid, " ".join(p.cmdline())[:120], _what(p)) for p in left if p.is_running()]
    for p in left:  # leave nothing behind for the next test either
        try:
            p.kill()
        except psutil.Error:
            pass
    assert not desc, f"orphans after {what} {fault}: {desc}"
