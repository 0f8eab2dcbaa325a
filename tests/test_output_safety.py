"""Issue 27, class 1-2: an output path can neither destroy what it points at nor lose a computed result.

Through the command line (``hsbearing.cli.main`` in-process where the process does not matter; a real
subprocess for the file-size limit and the full disk): exit 2 and one stderr line before any compute for an
``-o`` that is a device node, FIFO or socket, a derived path (``out.png``, ``DIR/sweep.nc``) that cannot be
written, or a name too long; a symbolic link is written through (the link stays a link); a final write that
fails after the compute (a full tmpfs, ``ulimit -f``, a directory remounted read-only) exits 1 with one line
saying where the result went, leaves no temporary file and keeps the result in a fallback file.
"""

from __future__ import annotations

import contextlib
import os
import re
import resource
import signal
import socket
import stat
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from _cli_checks import one_error_line as _one_error_line

import hsbearing
from hsbearing import cli
from hsbearing.errors import OutputWriteError
from hsbearing.results import open_run, write_netcdf

ROOT = Path(__file__).resolve().parents[1]

#: the attributes every hsbearing archive carries (results.standard_attrs): open_run reads only such files
OURS = {"title": "hsbearing result", "hsbearing_version": "test"}


def _files(d: Path) -> set[str]:
    return {str(p.relative_to(d)) for p in d.rglob("*")}


@pytest.fixture
def work(tmp_path, monkeypatch):
    """cwd = tmp_path; computing fails the test (bad output paths are refused before any compute)."""
    monkeypatch.chdir(tmp_path)

    def boom(*a, **k):
        raise AssertionError("computation started although the output path is bad")

    monkeypatch.setattr(hsbearing, "simulate", boom)
    monkeypatch.setattr(hsbearing, "quasi_static", boom)
    return tmp_path


def _make_special(d: Path, kind: str) -> Path:
    p = d / f"{kind}.nc"
    if kind == "fifo":
        os.mkfifo(p)
    elif kind == "chardev":
        try:
            os.mknod(p, 0o666 | stat.S_IFCHR, os.makedev(1, 3))  # a copy of /dev/null
        except PermissionError:
            pytest.skip("mknod of a character device needs root (CAP_MKNOD) on this platform")
    elif kind == "socket":
        s = socket.socket(socket.AF_UNIX)
        s.bind(str(p))
        s.close()
    return p


@contextlib.contextmanager
def _tmpfs(path, size):
    """Mount a tmpfs of ``size`` (e.g. "64k") on ``path`` for the block (the test is skipped where mounting is not
    allowed), unmounted afterwards whatever happens."""
    m = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(path)], capture_output=True, text=True)
    if m.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs of {size} here ({m.stderr.strip()})")
    try:
        yield path
    finally:
        subprocess.run(["umount", str(path)], check=False)


@pytest.mark.parametrize("kind", ["fifo", "chardev", "socket"])
@pytest.mark.parametrize("command", [["quasistatic", "zhang2016"], ["run", "-q", "--no-plot"], ["friction", "dgbb_6206"]])
def test_special_file_output_refused(kind, command, work, capsys):
    node = _make_special(work, kind)
    mode = node.lstat().st_mode
    before = _files(work)
    rc = cli.main([*command, "-o", str(node)])
    _one_error_line(capsys, rc, re.escape(f"-o {node}: is a"), "not a regular file")
    assert _files(work) == before and node.lstat().st_mode == mode  # the node is still the node


def test_symlink_output_written_through(tmp_path, capsys):
    """Policy (docs/output.md): -o LINK writes the archive to the link's target (temp file next to the target,
    renamed onto it); the link stays a link; a stale target is replaced, nothing else appears."""
    (tmp_path / "real").mkdir()
    target = tmp_path / "real" / "target.nc"
    target.write_text("stale")
    link = tmp_path / "link.nc"
    link.symlink_to(Path("real") / "target.nc")
    assert cli.main(["quasistatic", "zhang2016", "-o", str(link)]) == 0
    assert link.is_symlink() and os.readlink(link) == str(Path("real") / "target.nc")
    ds = open_run(target)
    assert ds.attrs["case_name"] == "zhang2016" and "inner_contact_load" in ds
    assert _files(tmp_path) == {"real", "real/target.nc", "link.nc"}  # no temporary anywhere


def test_symlink_to_a_device_refused(work, capsys):
    dev = _make_special(work, "fifo")
    link = work / "link.nc"
    link.symlink_to(dev.name)
    rc = cli.main(["quasistatic", "zhang2016", "-o", str(link)])
    _one_error_line(capsys, rc, "FIFO")
    assert link.is_symlink() and stat.S_ISFIFO(dev.stat().st_mode)


def test_long_output_name_fits_its_temporary(tmp_path, capsys):
    """A 252-byte final name (+ '.nc' = 255, NAME_MAX) is written: the temporary name is short."""
    out = tmp_path / ("a" * 252 + ".nc")
    assert cli.main(["quasistatic", "zhang2016", "-o", str(out)]) == 0
    assert out.is_file() and _files(tmp_path) == {out.name}
    too_long = tmp_path / ("b" * 253 + ".nc")
    capsys.readouterr()
    rc = cli.main(["quasistatic", "zhang2016", "-o", str(too_long)])
    _one_error_line(capsys, rc, "longer than 255 bytes")
    assert _files(tmp_path) == {out.name}


def test_derived_paths_checked_before_compute(work, capsys):
    (work / "out.png").mkdir()
    rc = cli.main(["run", "-q", "-o", "out.nc"])
    _one_error_line(capsys, rc, r"-o out.nc \(derived output out.png\): is a directory")
    (work / "a_power.png").mkdir()  # the second figure of a run
    rc = cli.main(["run", "-q", "-o", "a.nc"])
    _one_error_line(capsys, rc, r"derived output a_power.png")
    (work / "sw" / "sweep.nc").mkdir(parents=True)
    rc = cli.main(["sweep", "--vary", "axial_load=100,200N", "--kind", "quasistatic", "-o", "sw"])
    _one_error_line(capsys, rc, r"derived output sw/sweep.nc\): is a directory")
    assert _files(work / "sw") == {"sweep.nc"}


def test_run_no_plot_does_not_check_figures(tmp_path, monkeypatch, capsys):
    """With --no-plot a directory named out.png is not in the way (the compute starts: stubbed here)."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "out.png").mkdir()

    class Reached(Exception):
        pass

    def reached(*a, **k):
        raise Reached

    monkeypatch.setattr(hsbearing, "simulate", reached)
    with pytest.raises(Reached):
        cli.main(["run", "-q", "--no-plot", "-o", "out.nc"])


def test_empty_output_name_refused(work, capsys):
    rc = cli.main(["quasistatic", "zhang2016", "-o", ""])
    _one_error_line(capsys, rc, "not a file name")
    assert _files(work) == set()


def test_plot_unsupported_format_refused(tmp_path, capsys):
    nc = tmp_path / "q.nc"
    assert cli.main(["quasistatic", "zhang2016", "-o", str(nc)]) == 0
    capsys.readouterr()
    rc = cli.main(["plot", str(nc), "-o", str(tmp_path / "fig.txt")])
    _one_error_line(capsys, rc, r"figure format 'txt' is not supported")
    assert _files(tmp_path) == {"q.nc"}


# ----------------------------------------------------------------------------- a failed final write


def _cli_subprocess(args, cwd, tmpdir, preexec_fn=None):
    env = dict(os.environ, TMPDIR=str(tmpdir), PYTHONPATH=str(ROOT))
    return subprocess.run([sys.executable, "-c", "import sys; from hsbearing.cli import main; sys.exit(main())",
                           *args], cwd=cwd, env=env, capture_output=True, text=True, timeout=300,
                          preexec_fn=preexec_fn)


def _fsize_limit(nbytes):
    def f():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # EFBIG instead of death by SIGXFSZ
        resource.setrlimit(resource.RLIMIT_FSIZE, (nbytes, nbytes))
    return f


def test_file_size_limit_one_line_nothing_left(tmp_path):
    """``ulimit -f 40`` (40 kB; the archive is ~116 kB): the write fails, and so does every fallback (the limit is
    the process's): exit 1, one line, no traceback, no temporary or half file anywhere; the summary is printed."""
    out, fb = tmp_path / "out", tmp_path / "fallback"
    out.mkdir()
    fb.mkdir()
    r = _cli_subprocess(["quasistatic", "zhang2016", "-o", str(out / "q.nc")], cwd=out, tmpdir=fb,
                        preexec_fn=_fsize_limit(40_000))
    _one_error_line(r.stderr, r.returncode, re.escape(f"cannot write {out / 'q.nc'}"), "ulimit -f",
                    "no fallback place", code=1)
    assert "residual:" in r.stdout  # the numbers were printed before the write
    assert _files(out) == set() and _files(fb) == set()


def test_file_size_limit_fallback_keeps_result(tmp_path):
    """The limit lets the fallback through when the output directory cannot take the file but another can:
    here the output directory is a 64 kB tmpfs (disk full), the fallback TMPDIR an ordinary directory."""
    out, fb = tmp_path / "small", tmp_path / "fallback"
    out.mkdir()
    fb.mkdir()
    with _tmpfs(out, "64k"):
        r = _cli_subprocess(["quasistatic", "zhang2016", "-o", str(out / "q.nc")], cwd=tmp_path, tmpdir=fb)
        line = _one_error_line(r.stderr, r.returncode, re.escape(f"cannot write {out / 'q.nc'}"), "disk full",
                               "the result was saved to", code=1)
        saved = Path(line.rsplit("saved to ", 1)[1].removesuffix(" instead"))
        assert saved.parent == fb and saved.name.startswith("hsbearing-rescued-q-")
        assert _files(out) == set()  # no half file, no temporary on the full disk
        ds = open_run(saved)
        ref = hsbearing.quasi_static(hsbearing.load_case("zhang2016"))
        np.testing.assert_allclose(ds.inner_contact_load.values, ref.inner_contact_load.values, rtol=1e-9)


def test_read_only_directory_after_compute_keeps_result(tmp_path, monkeypatch):
    """The output directory becomes read-only between the check and the write (remounted read-only, which stops
    root too): write_netcdf raises OutputWriteError naming the fallback file, which holds the Dataset."""
    import xarray as xr

    d, fb = tmp_path / "ro", tmp_path / "fb"
    d.mkdir()
    fb.mkdir()
    with _tmpfs(d, "1m"):
        subprocess.run(["mount", "-o", "remount,ro", str(d)], check=True)
        monkeypatch.setenv("TMPDIR", str(fb))
        import tempfile

        monkeypatch.setattr(tempfile, "tempdir", None)  # re-read TMPDIR
        ds = xr.Dataset({"a": ("t", np.arange(5.0))}, attrs={"status": "ok", **OURS})
        with pytest.raises(OutputWriteError) as ei:
            write_netcdf(ds, d / "x.nc")
        assert "Read-only file system" in str(ei.value)
        saved = Path(ei.value.saved_to)
        assert saved.parent == fb
        np.testing.assert_array_equal(open_run(saved)["a"].values, np.arange(5.0))
        assert _files(d) == set()


# ----------------------------------------------------------------------------- a second Ctrl-C during the save


def test_second_ctrl_c_during_the_save_keeps_the_partial_run(tmp_path, monkeypatch, capsys):
    """First Ctrl-C stops the run; two more SIGINTs (real signals to this process) arrive while the partial
    run is being written: the archive is still written complete, exit 130, one line naming it."""
    import xarray as xr

    from hsbearing.errors import Interrupted

    t = np.linspace(0.0, 1e-3, 11)
    partial = xr.Dataset({"cage_speed": ("time", np.full(11, 600.0))}, coords={"time": t},
                         attrs={"status": "failed at t = 0.001 s: interrupted", **OURS})

    def interrupted(*a, **k):
        raise Interrupted(partial=partial)

    real_to_netcdf = xr.Dataset.to_netcdf

    def to_netcdf_with_ctrl_c(self, *a, **k):
        os.kill(os.getpid(), signal.SIGINT)  # the second and third Ctrl-C, during the save
        os.kill(os.getpid(), signal.SIGINT)
        sum(range(1000))  # give the interpreter bytecodes at which a handler runs
        return real_to_netcdf(self, *a, **k)

    # a process started in the background without job control inherits SIGINT ignored (then Python installs no
    # KeyboardInterrupt handler and the signals below would do nothing): run under Python's own handler
    # wherever the suite is started, and put the inherited disposition back afterwards
    inherited = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        monkeypatch.setattr(hsbearing, "simulate", interrupted)
        monkeypatch.setattr(xr.Dataset, "to_netcdf", to_netcdf_with_ctrl_c)
        out = tmp_path / "part.nc"
        rc = cli.main(["run", "-q", "--no-plot", "-o", str(out)])
        handler_after = signal.getsignal(signal.SIGINT)
    finally:
        signal.signal(signal.SIGINT, inherited)
    monkeypatch.setattr(xr.Dataset, "to_netcdf", real_to_netcdf)
    line = _one_error_line(capsys, rc, "interrupted at t = 0.001 s", re.escape(str(out)), code=130)
    assert "partial run in" in line
    ds = open_run(out)
    assert ds.sizes["time"] == 11 and ds.attrs["status"].startswith("interrupted at t = 0.001")
    assert handler_after is signal.default_int_handler  # the handler in place before the run is restored
    assert _files(tmp_path) == {"part.nc"}


def test_map_derived_paths_checked_before_compute(work, capsys):
    (work / "m" / "map.nc").mkdir(parents=True)
    rc = cli.main(["map", "--x", "axial_load=100,200N", "--y", "oil=4109,4106", "-o", "m"])
    _one_error_line(capsys, rc, r"derived output m/map.nc\): is a directory")


def test_disk_full_mid_sweep_keeps_the_point(tmp_path, monkeypatch):
    """A sweep whose output disk fills up after the first archive (a 1 MB tmpfs filled by another writer): the
    second archive cannot be written; the sweep stops with OutputWriteError naming the fallback file that holds
    that point's result, the first archive is intact, no temporary is left (before: 'NetCDF: HDF error'
    traceback, the point lost).  The directory made read-only mid-write is test_read_only_directory_... (a
    remount is refused while the sweep holds its lock file open)."""
    import tempfile

    out, fb = tmp_path / "out", tmp_path / "fb"
    out.mkdir()
    fb.mkdir()
    with _tmpfs(out, "1m"):
        monkeypatch.setenv("TMPDIR", str(fb))
        monkeypatch.setattr(tempfile, "tempdir", None)
        calls = []
        real = hsbearing.quasi_static

        def point(case, duration):
            if calls:  # another writer fills the disk
                with open(out / "filler", "wb") as fh:
                    try:
                        while True:
                            fh.write(b"\0" * 65536)
                            fh.flush()
                    except OSError:
                        pass
            calls.append(case.operating.axial_load)
            return real(case)

        with pytest.raises(OutputWriteError) as ei:
            hsbearing.sweep("zhang2016", {"axial_load": "100,200N"}, out_dir=out, kind="quasistatic", jobs=1,
                            progress=False, point_fn=point)
        assert "disk full" in str(ei.value)
        saved = Path(ei.value.saved_to)
        assert saved.parent == fb
        assert "200" in open_run(saved).attrs["sweep_overrides"]
        archives = [p for p in out.iterdir() if p.suffix == ".nc"]
        assert len(archives) == 1 and open_run(archives[0]).attrs["status"] == "ok"
        assert not [p for p in out.iterdir() if p.name.endswith(".tmp")]


def test_run_disk_full_after_integrating_keeps_the_run(tmp_path):
    """`hsbearing run` whose output disk is full once the integration is done: the summary is printed, the run
    goes to the fallback file, one line says where, exit 1, nothing half-written on the full disk."""
    out, fb = tmp_path / "small", tmp_path / "fallback"
    out.mkdir()
    fb.mkdir()
    with _tmpfs(out, "64k"):
        r = _cli_subprocess(["run", "--duration", "0.002s", "-q", "--no-plot", "-o", str(out / "r.nc")],
                            cwd=tmp_path, tmpdir=fb)
        line = _one_error_line(r.stderr, r.returncode, re.escape(f"cannot write {out / 'r.nc'}"),
                               "the result was saved to", code=1)
        assert re.search(r"^status: ok$", r.stdout, re.M) and "mean_cage_speed:" in r.stdout
        saved = Path(line.rsplit("saved to ", 1)[1].removesuffix(" instead"))
        ds = open_run(saved)
        assert float(ds.time[-1]) == pytest.approx(0.002) and "final_state" in ds
        assert _files(out) == set()
