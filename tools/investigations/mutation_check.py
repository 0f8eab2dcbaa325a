"""Mutation check of the independent assembly test.

For each plausible one-line bug, copy the package to a temporary directory, apply the mutation by text
replacement (the pattern must occur exactly once), and run tests/validation/test_assembly_reference.py against the
copy in a subprocess (``PYTHONPATH`` = the copy, a fresh ``NUMBA_CACHE_DIR``: no stale compiled code; each
run compiles the kernel, ~2 min).  The unmutated copy must pass; every mutation must make the test fail.

    python tools/investigations/mutation_check.py                 # baseline + all mutations, one after the other
    python tools/investigations/mutation_check.py --only land_speed_sign
    python tools/investigations/mutation_check.py --list

Prints one line per run: mutation, expected outcome, pytest exit status, failed/total tests, and the terms
the failing assertions name with their worst relative difference.
"""

from __future__ import annotations

import argparse
import ast
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TEST_FILES = ("tests/validation/test_assembly_reference.py", "tests/helpers/reference_assembly.py")

#: name -> (file in the package, pattern, replacement, description); EXPECTED_TERM: a term the failing
#: assertions must name (tests/validation/test_assembly_reference.py::test_mutation_check_catches_the_three_mutations)
EXPECTED_TERM = {"slide_roll_half": "aux T_roll_i", "pocket_entrainment": "aux Q_film",
                 "land_speed_sign": "land force (F_cy, F_cz)"}
MUTATIONS = {
    "slide_roll_half": (
        "hsbearing/models/ball_bearing/kernel.py", "traction_mu_nb(p.traction.law_id, tc, sreg * iU, qu[k])",
        "traction_mu_nb(p.traction.law_id, tc, 0.5 * sreg * iU, qu[k])",
        "halve the slide-roll ratio the kernel passes to the traction law"),
    "pocket_entrainment": (
        "hsbearing/models/ball_bearing/pocket.py", "Ue = dUu - 2.0 * vr", "Ue = dUu - vr",
        "pocket film entrainment velocity Ue = dUu - 2 vr -> dUu - vr"),
    "land_speed_sign": (
        "hsbearing/models/ball_bearing/kernel.py", "guide_land_forces(eps, ed / cl, phd + wl,", "guide_land_forces(eps, ed / cl, phd - wl,",
        "sign of the land's own speed in the kernel's land call (phd + wl -> phd - wl)"),
}


def make_copy(dest: Path, mutation: str | None) -> None:
    shutil.copytree(ROOT / "hsbearing", dest / "hsbearing", ignore=shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc"))
    (dest / "tests").mkdir()
    for f in TEST_FILES:
        shutil.copy2(ROOT / f, dest / f)
    shutil.copy2(ROOT / "pyproject.toml", dest / "pyproject.toml")
    if mutation is None:
        return
    rel, pat, rep, _ = MUTATIONS[mutation]
    path = dest / rel
    text = path.read_text()
    n = text.count(pat)
    assert n == 1, f"{mutation}: pattern {pat!r} found {n} times in {rel} (expected exactly once)"
    path.write_text(text.replace(pat, rep))


def failed_terms(xml_path: Path):
    """(failed, total, {term: worst relative difference}) from the junit report of the run."""
    root = ET.parse(xml_path).getroot()
    suite = root if root.tag == "testsuite" else root.find("testsuite")
    total = int(suite.get("tests", 0))
    failed = 0
    terms: dict[str, float] = {}
    tests: list[str] = []
    for case in suite.iter("testcase"):
        fail = case.find("failure")
        if fail is None:
            fail = case.find("error")
        if fail is None:
            continue
        failed += 1
        tests.append(case.get("name"))
        # the assertion message names the terms: {term: (|diff|, scale, relative)}; pytest shortens the junit
        # "message" attribute, the element text holds the full line
        pat = r"AssertionError:[^\n]*scale: (\{[^\n]*\})"
        m = re.search(pat, fail.text or "") or re.search(pat, fail.get("message", ""))
        if m:
            try:
                bad = ast.literal_eval(m.group(1))
            except (ValueError, SyntaxError):
                continue
            for k, v in bad.items():
                terms[k] = max(terms.get(k, 0.0), float(v[2]))
    return failed, total, terms, tests


def run(mutation: str | None, python: str, keep: bool = False) -> dict:
    tmp = Path(tempfile.mkdtemp(prefix=f"hsb_mut_{mutation or 'none'}_"))
    try:
        make_copy(tmp, mutation)
        env = dict(os.environ, PYTHONPATH=str(tmp), NUMBA_CACHE_DIR=str(tmp / "numba_cache"))
        env.pop("PYTHONDONTWRITEBYTECODE", None)
        where = subprocess.run([python, "-c", "import hsbearing; print(hsbearing.__file__)"], cwd=tmp, env=env,
                               capture_output=True, text=True, check=True).stdout.strip()
        assert where.startswith(str(tmp)), f"the subprocess imports {where}, not the copy in {tmp}"
        xml = tmp / "report.xml"
        t0 = time.time()
        proc = subprocess.run([python, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-m", "not slow", "--junitxml", str(xml),
                               "tests/validation/test_assembly_reference.py"], cwd=tmp, env=env, capture_output=True, text=True)
        dt = time.time() - t0
        failed, total, terms, tests = failed_terms(xml) if xml.exists() else (-1, -1, {}, [])
        return dict(mutation=mutation or "(none)", rc=proc.returncode, failed=failed, total=total, terms=terms,
                    tests=tests, seconds=dt, tail=proc.stdout.strip().splitlines()[-1:] if proc.stdout else [])
    finally:
        if not keep:
            shutil.rmtree(tmp, ignore_errors=True)


def report(res: dict) -> bool:
    expect_fail = res["mutation"] != "(none)"
    ok = (res["rc"] != 0 and res["failed"] > 0) if expect_fail else res["rc"] == 0
    verdict = ("CAUGHT" if ok else "NOT CAUGHT") if expect_fail else ("PASS" if ok else "FAIL (baseline must pass)")
    print(f"{res['mutation']}: {verdict}; pytest exit {res['rc']}, {res['failed']}/{res['total']} tests failed, "
          f"{res['seconds']:.0f} s; {' '.join(res['tail'])}")
    if res["tests"]:
        regimes = sorted({re.sub(r"-\d+\]$", "", t.split("[", 1)[-1]) if "[" in t else t for t in res["tests"]})
        print(f"  failing tests by regime: {', '.join(regimes)}")
    for k, v in sorted(res["terms"].items(), key=lambda kv: -kv[1]):
        print(f"  {k}: worst relative difference {v:.3g}")
    sys.stdout.flush()
    return ok


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", nargs="*", help="mutations to run (names of --list; 'none' = the unmutated copy)")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--python", default=sys.executable)
    ap.add_argument("--keep", action="store_true", help="keep the temporary copies")
    a = ap.parse_args(argv)
    if a.list:
        for k, v in MUTATIONS.items():
            print(f"{k}: {v[3]} ({v[0]}: {v[1]!r} -> {v[2]!r})")
        return 0
    names = a.only if a.only else ["none", *MUTATIONS]
    ok = True
    for name in names:
        if name != "none" and name not in MUTATIONS:
            ap.error(f"unknown mutation {name!r}")
        ok &= report(run(None if name == "none" else name, a.python, a.keep))
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
