"""The compare page in a real browser: Debian's headless ``chromium`` opens ``DIR/index.html`` from the file system
(offline), every ``<img>`` has loaded (``naturalWidth > 0``) and there is no console error, no uncaught exception and
no failed resource load.

The browser is driven through the DevTools protocol over ``--remote-debugging-pipe`` (file descriptors 3 and 4,
NUL-separated JSON messages): standard library only, no websocket client, no driver.  Where no ``chromium`` is on
the PATH the test runs the project's ``make browser`` (Debian's package, needs root and apt) and skips, naming why,
only when that cannot install one.  Slow tier: starting the browser and a comparison take ~1 min on 2 cores.
"""

from __future__ import annotations

import fcntl
import json
import os
import shutil
import subprocess
import time
from pathlib import Path

import pytest

from hsbearing.cli import main

ROOT = Path(__file__).resolve().parents[2]

pytestmark = pytest.mark.slow


def _chromium() -> str:
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    if exe:
        return exe
    if shutil.which("make") is None:
        pytest.skip("no chromium on the PATH and no make to run 'make browser' (Debian's chromium package)")
    r = subprocess.run(["make", "-s", "-C", str(ROOT), "browser"], capture_output=True, text=True, timeout=1200)
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    if not exe:
        why = (r.stderr or r.stdout).strip().splitlines()[-1:] or ["no output"]
        pytest.skip(f"no chromium and 'make browser' could not install Debian's package (exit {r.returncode}: {why[0]})")
    return exe


class DevTools:
    """A minimal DevTools-protocol client over Chromium's --remote-debugging-pipe."""

    def __init__(self, exe: str, profile: Path):
        to_chrome_r, self._w = os.pipe()
        self._r, from_chrome_w = os.pipe()
        # the browser's ends above 9, so that dup2 onto 3 and 4 cannot overwrite one with the other
        to_chrome_r, from_chrome_w = (self._high(fd) for fd in (to_chrome_r, from_chrome_w))

        profile.mkdir(parents=True, exist_ok=True)
        self._log = open(profile / "stderr.log", "wb")  # noqa: SIM115 - closed in close()

        def fds():  # the browser reads commands on fd 3 and writes answers on fd 4
            os.dup2(to_chrome_r, 3)
            os.dup2(from_chrome_w, 4)

        # close_fds=False: subprocess would close fds 3 and 4 after preexec_fn otherwise; Python's own descriptors
        # are not inheritable (O_CLOEXEC), so the browser gets only these two besides stdio
        self.proc = subprocess.Popen(
            [exe, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-extensions",
             "--disable-background-networking", "--remote-debugging-pipe", f"--user-data-dir={profile}",
             "about:blank"],
            preexec_fn=fds, close_fds=False, stdout=subprocess.DEVNULL, stderr=self._log)
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        self._buf = b""
        self._id = 0
        self.events: list[dict] = []

    @staticmethod
    def _high(fd: int) -> int:
        new = fcntl.fcntl(fd, fcntl.F_DUPFD_CLOEXEC, 10)
        os.close(fd)
        return new

    def close(self):
        for fd in (self._w, self._r):
            try:
                os.close(fd)
            except OSError:
                pass
        self.proc.terminate()
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        self._log.close()

    def _read(self, deadline: float) -> dict:
        while b"\0" not in self._buf:
            if time.monotonic() > deadline:
                raise TimeoutError("no answer from chromium")
            chunk = os.read(self._r, 1 << 16)
            if not chunk:
                self._log.flush()
                err = Path(self._log.name).read_text(errors="replace")
                raise RuntimeError(f"chromium closed the pipe (exit {self.proc.returncode}): {err[-2000:]}")
            self._buf += chunk
        msg, _, self._buf = self._buf.partition(b"\0")
        return json.loads(msg)

    def send(self, method: str, params: dict | None = None, session: str | None = None, timeout: float = 60.0) -> dict:
        self._id += 1
        msg = {"id": self._id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        os.write(self._w, json.dumps(msg).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            m = self._read(deadline)
            if m.get("id") == self._id:
                if "error" in m:
                    raise RuntimeError(f"{method}: {m['error']}")
                return m.get("result", {})
            self.events.append(m)

    def wait_event(self, method: str, timeout: float = 60.0) -> dict:
        deadline = time.monotonic() + timeout
        for m in self.events:
            if m.get("method") == method:
                return m
        while True:
            m = self._read(deadline)
            self.events.append(m)
            if m.get("method") == method:
                return m


def test_compare_page_renders_offline_with_every_figure_and_no_console_error(tmp_path):
    exe = _chromium()
    out = tmp_path / "page"
    oil = tmp_path / "vg32.toml"
    oil.write_text('name = "VG 32 sheet"\nviscosity = [["40 degC", "32 mm^2/s"], ["100 degC", "5.4 mm^2/s"]]\n'
                   'density = "0.86 g/cm^3"\n')
    assert main(["compare", "zhang2016", "--oils", f"4109,{oil}", "--no-dynamics", "-j", "1", "-q", "-o", str(out)]) == 0
    page = out / "index.html"
    dt = DevTools(exe, tmp_path / "profile")
    try:
        target = dt.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = dt.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        for domain in ("Page", "Runtime", "Log", "Network"):
            dt.send(f"{domain}.enable", session=session)
        dt.send("Page.navigate", {"url": page.as_uri()}, session=session)
        dt.wait_event("Page.loadEventFired")
        res = dt.send("Runtime.evaluate", {"expression": "JSON.stringify(Array.from(document.images).map("
                                                         "i => [i.getAttribute('src'), i.complete, i.naturalWidth]))",
                                           "returnByValue": True}, session=session)
        images = json.loads(res["result"]["value"])
        title = dt.send("Runtime.evaluate", {"expression": "document.title", "returnByValue": True},
                        session=session)["result"]["value"]
        dt.send("Runtime.evaluate", {"expression": "1"}, session=session)  # drain the events queued meanwhile
    finally:
        dt.close()
    assert title == "hsbearing: lubricant comparison"
    assert len(images) >= 4, images  # criteria, power by source, the quasi-static and thermal sweep figures
    for src, complete, width in images:
        assert complete and width > 0, f"image {src} did not load (naturalWidth {width})"
    errors = []
    for m in dt.events:
        meth, p = m.get("method"), m.get("params", {})
        if meth == "Runtime.exceptionThrown":
            errors.append(p["exceptionDetails"].get("text", "exception"))
        elif meth == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
            errors.append(str(p.get("args")))
        elif meth == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
            errors.append(p["entry"].get("text", ""))
        elif meth == "Network.loadingFailed":
            errors.append(f"failed load: {p.get('errorText')}")
        elif meth == "Network.requestWillBeSent":
            url = p.get("request", {}).get("url", "")
            if not url.startswith(("file://", "about:", "data:")):
                errors.append(f"network request: {url}")  # the page must open offline
    assert not errors, errors
