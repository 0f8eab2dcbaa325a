"""Ctrl-C at any moment of an hsbearing command (``quasistatic`` in the default tier, ``run`` in the slow tier): exit status 130 (or 0 when the status was already decided), never
death by the signal (-2), and either a complete archive or none (no temporary file left).

SIGINT is sent at random times over the command's whole life, from the moment hsbearing's first statement holds
Ctrl-C (before it the Python runtime itself, not hsbearing, decides: ``site``, the import machinery; see
hsbearing/_interrupt.py) through the imports, the case, the integration, the save and the figures, to the
interpreter's exit.  A handful of times in the default tier, more in the slow tier.  No residual form is accepted.
The one that remained -- the handled line, then death by SIGINT under ``python -m`` -- is reproduced
deterministically below (a KeyboardInterrupt out of string-exec'd code sets CPython's unhandled-interrupt flag).
"""

from __future__ import annotations

import os
import random
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from hsbearing import open_run

ROOT = Path(__file__).resolve().parents[2]
QS = ["quasistatic", "zhang2016"]
RUN = ["run", "zhang2016", "--duration", "0.3 ms", "-q"]


def _sigint_caught(pid: int) -> bool:
    try:
        for line in Path(f"/proc/{pid}/status").read_text().splitlines():
            if line.startswith("SigCgt:"):
                return bool(int(line.split()[1], 16) & (1 << (signal.SIGINT - 1)))
    except (OSError, ValueError):
        return False
    return False


def _hsbearing_started(pid: int) -> bool:
    """hsbearing/__init__ has run its first statements (the Ctrl-C guard): it then imports numpy, whose compiled core
    appears in the process's mappings.  Nothing before that (site, the .pth files, runpy) imports numpy."""
    try:
        return "_multiarray_umath" in Path(f"/proc/{pid}/maps").read_text()
    except OSError:
        return False


def _start(out: Path, cmd):
    # faulthandler on: a command that hangs is sent SIGABRT by _communicate, which then prints every thread's stack
    env = dict(os.environ, PYTHONPATH=str(ROOT), PYTHONFAULTHANDLER="1")
    proc = subprocess.Popen([sys.executable, "-m", "hsbearing.cli", *cmd, "-o", str(out)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=env, cwd=str(out.parent),
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    t0 = time.monotonic()
    while proc.poll() is None and not (_sigint_caught(proc.pid) and _hsbearing_started(proc.pid)) \
            and time.monotonic() - t0 < 60:
        time.sleep(0.001)
    return proc, time.monotonic()


def _check(out: Path, rc: int, err: str):
    assert rc in (0, 130), (rc, err[-600:])  # -2 = killed by SIGINT: the documented 130 was not given
    left = [p.name for p in out.parent.iterdir() if p.name.endswith(".tmp")]
    assert not left, left
    if out.exists():  # complete, or absent
        ds = open_run(out)
        assert ds.attrs["status"] == "ok" or ds.attrs["status"].startswith("interrupted"), ds.attrs["status"]
        assert ds.data_vars
    if rc == 0:
        assert out.exists() and open_run(out).attrs["status"] == "ok"
    else:
        lines = [ln for ln in err.splitlines() if ln.startswith("hsbearing:")]
        assert lines and "interrupted" in lines[-1], err[-600:]
        assert "Traceback" not in err, err[-1500:]


def test_handled_interrupt_out_of_string_exec_code_exits_130_under_python_m(tmp_path):
    """The residual once accepted here (one run in six under load): "hsbearing: interrupted", then status -2.
    Python >= 3.8 marks a KeyboardInterrupt leaving string-exec'd code as unhandled even when it is caught, and
    ``python -m`` then kills itself with SIGINT at exit; main() clears the mark (_interrupt.forget_handled_interrupt).
    Without the fix this exits -2 every time (checked by reverting it)."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), str(Path(__file__).parent)]))
    p = subprocess.run([sys.executable, "-m", "_interrupt_in_string_exec"], capture_output=True, text=True,
                       env=env, cwd=str(tmp_path), timeout=120)
    assert p.returncode == 130, (p.returncode, p.stderr[-600:])
    assert p.stderr.strip().splitlines()[-1] == "hsbearing: interrupted", p.stderr[-600:]
    assert "Traceback" not in p.stderr


def _communicate(proc, timeout: float = 300.0):
    """proc.communicate; a command still running after ``timeout`` s is aborted (SIGABRT: with faulthandler on it
    prints the stack of every thread) and the test fails with that dump, so that a hang says where it hung."""
    try:
        return proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.send_signal(signal.SIGABRT)
        try:
            _, err = proc.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            proc.kill()
            _, err = proc.communicate()
        pytest.fail(f"{' '.join(proc.args[3:])} still running {timeout:g} s after start/SIGINT; stacks:\n{err[-6000:]}")


def _campaign(tmp_path, n: int, seed: int, cmd):
    # the command's life, from the second of two uninterrupted runs: the first may load or compile caches (numba,
    # bytecode) and live longer than every later run, which would then end before most signals were sent
    for k in range(2):
        ref_dir = tmp_path / f"ref{k}"
        ref_dir.mkdir(parents=True)
        proc, t_ready = _start(ref_dir / "run.nc", cmd)
        _, err = _communicate(proc)
        life = time.monotonic() - t_ready
        assert proc.returncode == 0, err[-600:]
    rng = random.Random(seed)
    codes = []
    for i in range(n):
        d = tmp_path / f"c{i}"
        d.mkdir(parents=True)
        out = d / "run.nc"
        delay = rng.uniform(0.0, 1.05 * life)  # over the whole life, a little past it
        proc, t_ready = _start(out, cmd)
        try:
            time.sleep(max(0.0, t_ready + delay - time.monotonic()))
            if proc.poll() is None:
                proc.send_signal(signal.SIGINT)
            _, err = _communicate(proc)
        finally:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
        _check(out, proc.returncode, err)
        codes.append((round(delay / life, 2), proc.returncode))
    return codes


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc/PID/status")
def test_ctrl_c_at_random_times_gives_130_and_a_complete_archive_or_none(tmp_path):
    codes = _campaign(tmp_path, 6, seed=1, cmd=QS)
    print("(delay / life, exit status):", codes)  # shown with pytest -rA
    assert any(rc == 130 for _, rc in codes), codes  # the signal was acted on


@pytest.mark.slow
@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc/PID/status")
def test_ctrl_c_at_random_times_many(tmp_path):
    codes = _campaign(tmp_path, 20, seed=2, cmd=QS) + _campaign(tmp_path / "run", 10, seed=3, cmd=RUN)
    print("(delay / life, exit status):", codes)  # shown with pytest -rA
    assert sum(rc == 130 for _, rc in codes) >= 15, codes
