"""Mutation check: every plausible one-line bug must be caught by a named validation test.

For each mutation (a plausible one-line bug), copy the package and the tests to a temporary directory, apply
the mutation by text replacement (the pattern must occur exactly once), and run the VALIDATION tests that cover
the mutated file (the mutation's ``tests``: independent solutions, closed forms, literature tables -- never a
regression archive or a stored number of our own) against the copy in a subprocess (``PYTHONPATH`` = the
copy, a fresh ``NUMBA_CACHE_DIR``: no stale compiled code; a run that reaches the kernel compiles it, 0.5-2
min of CPU).  The unmutated copy must pass every test named in the table; every mutation must make at least
one of its tests fail.

    python tools/investigations/mutation_check.py                 # baseline + all mutations, one after the other
    python tools/investigations/mutation_check.py --only land_speed_sign
    python tools/investigations/mutation_check.py --list
    make mutation                                                 # the same as the first line

Prints one line per run: mutation, verdict, pytest exit status, failed/total tests, the failing tests, and
(for the assembly reference) the terms the failing assertions name with their worst relative difference.
The table of docs/testing.md ("Mutation check") is this script's output.
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

ASM = "tests/validation/test_assembly_reference.py"
LEAF = "tests/validation/test_leaf_laws.py"
TNET = "tests/validation/test_thermal_network.py"
TREF = "tests/validation/test_thermal_reference.py"

#: name -> (file in the package, pattern, replacement, description, validation tests that cover the file);
#: EXPECTED_TERM: a term the failing assertions of the assembly reference must name
#: (tests/validation/test_assembly_reference.py::test_mutation_check_catches_the_three_mutations)
EXPECTED_TERM = {"slide_roll_half": "aux T_roll_i", "pocket_entrainment": "aux Q_film",
                 "land_speed_sign": "land force (F_cy, F_cz)"}
POCKET = "tests/models/test_pocket.py::"
WHIRL = "tests/models/test_cage_whirl.py::"
#: the quasi-static solver's validation tests (closed forms, Harris's equations, Hertz; not its regression numbers)
QS = tuple("tests/systems/angular_contact/test_quasistatic.py::" + t for t in (
    "test_contact_stiffness_table_matches_exact_hertz", "test_pure_axial_static_matches_closed_form",
    "test_ball_equations_in_harris_form", "test_race_control_closed_forms_both_races", "test_equilibrium_recomputed_from_dataset"))
K = "hsbearing/models/ball_bearing/"
TH = "hsbearing/systems/angular_contact/thermal.py"
MUTATIONS = {
    # ---- the kernel (assembly of Zhang et al. 2016, Eqs. 5-21)
    "slide_roll_half": (
        K + "kernel.py", "traction_mu_nb(p.traction.law_id, tc, sreg * iU, qu[k])",
        "traction_mu_nb(p.traction.law_id, tc, 0.5 * sreg * iU, qu[k])",
        "kernel: halve the slide-roll ratio the kernel passes to the traction law", (ASM,)),
    "land_speed_sign": (
        K + "kernel.py", "guide_land_forces(eps, ed / cl, phd + wl,", "guide_land_forces(eps, ed / cl, phd - wl,",
        "kernel: sign of the land's own speed in the kernel's land call (phd + wl -> phd - wl)", (ASM,)),
    "ball_coriolis_half": (
        K + "ball.py", "thdd = (Ft / m - 2.0 * rdot * thetadot) / r", "thdd = (Ft / m - rdot * thetadot) / r",
        "ball equations of motion: Coriolis term 2 r' theta' -> r' theta' (Eq. 7)", (ASM,)),
    # ---- leaf laws
    "pocket_entrainment": (
        K + "pocket.py", "Ue = dUu - 2.0 * vr", "Ue = dUu - vr",
        "pocket film entrainment velocity Ue = dUu - 2 vr -> dUu - vr", (ASM,)),
    "pocket_station_wedge": (
        K + "pocket.py", "A = 6.0 * eta * U_e", "A = 12.0 * eta * U_e",
        "pocket station film: Reynolds wedge term 6 eta U -> 12 eta U", (POCKET + "test_station_martin_rigid_cylinder",
                                                                       POCKET + "test_station_closed_form_against_quadrature")),
    "pocket_station_source_rupture": (
        K + "pocket.py", "        gamma = -(A * H2 + beta * x2)\n", "        gamma = -(A * H2 + beta)\n",
        "pocket station film (station_film): Reynolds exit constant with a source, -(A H2 + beta xi2) -> -(A H2 + beta)",
        (LEAF + "::test_pocket_station_film_against_a_reynolds_grid_at_the_run_states", "tests/models/test_pocket.py")),
    "pocket_boundary_regularisation": (
        K + "pocket.py", "v_slide / math.sqrt(v_slide * v_slide + v0 * v0)", "v_slide / math.sqrt(v_slide * v_slide + v0)",
        "pocket boundary friction: regularisation sqrt(v^2 + v0^2) -> sqrt(v^2 + v0)", (LEAF,)),
    "land_torque_eccentricity": (
        K + "cage.py", "(c * math.sqrt(1.0 - eps * eps))", "(c * (1.0 - eps * eps))",
        "guide-land torque: eccentricity factor 1/sqrt(1 - eps^2) -> 1/(1 - eps^2)", (LEAF,)),
    "land_force_whirl": (
        K + "cage.py", "a = 0.5 * eps * (omega_sum - 2.0 * whirl)", "a = 0.5 * eps * (omega_sum - whirl)",
        "guide-land force: wedge minus whirl omega_sum - 2 phi' -> omega_sum - phi'",
        (WHIRL + "test_land_film_matches_numerical_short_bearing_in_every_regime", WHIRL + "test_half_frequency_whirl_is_force_free")),
    "ehl_rolling_ellipticity": (
        K + "ball.py", "k**0.348", "k**0.48",
        "EHL rolling force: ellipticity exponent 0.348 -> 0.48", (LEAF,)),
    "hertz_load_exponent": (
        K + "ball.py", "Q = K * delta * math.sqrt(delta) + c_damp", "Q = K * delta * delta ** 0.4 + c_damp",
        "Hertz normal load of the kernel: K delta^1.5 -> K delta^1.4", (LEAF,)),
    "drag_frontal_area": (
        K + "drag.py", "-0.5 * C_D * rho_e * 0.25 * math.pi * D * D * v * va", "-0.5 * C_D * rho_e * math.pi * D * D * v * va",
        "ball drag: frontal area pi D^2/4 -> pi D^2", (LEAF, "tests/models/test_drag_law.py::test_drag_force_is_unit_system_independent")),
    "drag_coefficient_table": (
        K + "drag.py", "24.0 / Re * (1.0 + 0.1935 * Re**0.6305)", "24.0 / Re * (1.0 + 0.1935 * Re**0.6035)",
        "sphere drag coefficient: exponent 0.6305 -> 0.6035 (Re 20-260; transposed digits)",
        ("tests/models/test_drag_coefficient.py::test_standard_curve_against_roos_willmarth_1971",
         "tests/models/test_drag_coefficient.py::test_stokes_limit_and_continuity")),
    "hertz_reduced_modulus": (
        "hsbearing/models/hertz.py", "return 2.0 / ((1.0 - np.square(nu1)) / E1 + (1.0 - np.square(nu2)) / E2)",
        "return 1.0 / ((1.0 - np.square(nu1)) / E1 + (1.0 - np.square(nu2)) / E2)",
        "reduced modulus E' = 2/(...) -> 1/(...)", ("tests/models/test_hertz.py", LEAF)),
    "ehl_film_speed_exponent": (
        "hsbearing/models/ehl.py", "2.69 * U**0.67 * G**0.53", "2.69 * U**0.76 * G**0.53",
        "Hamrock-Dowson central film: speed exponent 0.67 -> 0.76", ("tests/models/test_ehl.py",)),
    # ---- traction models
    "traction_zhang2016_decay": (
        "hsbearing/models/traction/zhang2016.py", "np.sign(S) * (A * np.expm1(-C * s) + B * s * e)",
        "np.sign(S) * (A * np.expm1(-C * s) + B * s)",
        "zhang2016 traction law Eq. 1: drop the e^(-C|S|) of the B term", ("tests/models/test_traction.py", LEAF)),
    "traction_eyring_weight": (
        "hsbearing/models/traction/eyring.py", "den += w * pi_", "den += w",
        "Eyring traction: the load weight of the strip quadrature p/p0 -> 1", ("tests/models/test_traction_eyring.py",)),
    # ---- viscosity
    "walther_offset": (
        "hsbearing/models/viscosity.py", "WALTHER_OFFSET = 0.7", "WALTHER_OFFSET = 0.6",
        "Walther (ASTM D341) offset 0.7 -> 0.6", ("tests/models/test_viscosity.py", LEAF)),
    "viscosity_exponential_sign": (
        "hsbearing/models/viscosity.py", "np.exp(-np.asarray(beta, dtype=float) * (np.asarray(T, dtype=float) - T_ref))",
        "np.exp(-np.asarray(beta, dtype=float) * (T_ref - np.asarray(T, dtype=float)))",
        "Table 1 exponential viscosity law: exp(-beta (T - T_ref)) -> exp(-beta (T_ref - T))",
        ("tests/models/test_viscosity.py", LEAF)),
    # ---- the quasi-static solver
    "qs_centrifugal_sign": (
        K + "quasistatic.py", "- Fi * sin_ai - Fo * sin_ao + Fc", "- Fi * sin_ai - Fo * sin_ao - Fc",
        "quasi-static ball radial balance: + F_c -> - F_c (Eq. 3.15)", QS),
    "qs_outer_curvature": (
        K + "quasistatic.py", "delta_o = L_o - (fo - 0.5) * D", "delta_o = L_o - (fo - 0.5) * D * 0.999",
        "quasi-static outer approach: (f_o - 0.5) D -> 0.999 (f_o - 0.5) D (Eq. 3.11)",
        QS),
    # ---- the thermal network
    "thermal_housing_parallel": (
        TH, '1.0 / (R_or + R_h), "conduction"', '1.0 / R_or + 1.0 / R_h, "conduction"',
        "thermal network: outer ring and housing walls in parallel instead of in series", (TNET, TREF)),
    "thermal_ball_oil_speed": (
        TH, 'f_ball = 2.0 * w_rel["balls"] / omega', 'f_ball = w_rel["balls"] / omega',
        "thermal network: ball-to-oil convection at half the ball's speed relative to the oil", (TNET, TREF)),
    "thermal_inner_ring_radius": (
        TH, 'cylinder_resistance(0.5 * g["d"], 0.5 * (g["dm"] - g["D"]), g["B"], ks)',
        'cylinder_resistance(0.5 * g["d"], 0.5 * g["dm"], g["B"], ks)',
        "thermal network: inner ring wall to the pitch circle instead of the race", (TNET, TREF)),
    "thermal_oil_speed_unit": (
        TH, "n = abs(omega) * 30.0 / math.pi", "n = abs(omega)",
        "thermal network: ring-to-oil correlation read with omega in rad/s instead of n in r/min", (TNET, TREF)),
    "thermal_constriction": (
        TH, "_ellipk(1.0 - (b1 / a1) ** 2) / (2.0 * math.pi * k * a1)", "_ellipk(1.0 - (b1 / a1) ** 2) / (4.0 * k * a1)",
        "thermal network: elliptic constriction K(m)/(2 pi k a) -> K(m)/(4 k a)", (TNET, TREF)),
    # ---- the cage-motion classifier
    "classifier_rotation_fold": (
        "hsbearing/analysis/periods.py", "return float(min(rho, 1.0 - rho))", "return float(rho)",
        "classifier: rotation number not folded to [0, 1/2]",
        ("tests/analysis/test_classify_benchmark.py",)),
    "classifier_cluster_tolerance": (
        "hsbearing/analysis/periods.py", "tol=0.02,  # cluster radius", "tol=0.2,  # cluster radius",
        "classifier: cluster radius 2 % -> 20 % of the attractor size",
        ("tests/analysis/test_classify_benchmark.py",)),
}


def make_copy(dest: Path, mutation: str | None) -> None:
    """The package, the tests, the docs (some tests read them) and pyproject.toml in ``dest``, mutated."""
    ign = shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc")
    for d in ("hsbearing", "tests", "docs"):
        shutil.copytree(ROOT / d, dest / d, ignore=ign)
    os.symlink("hsbearing/cases", dest / "cases")
    shutil.copy2(ROOT / "pyproject.toml", dest / "pyproject.toml")
    if mutation is None:
        return
    rel, pat, rep = MUTATIONS[mutation][:3]
    path = dest / rel
    text = path.read_text()
    n = text.count(pat)
    assert n == 1, f"{mutation}: pattern {pat!r} found {n} times in {rel} (expected exactly once)"
    path.write_text(text.replace(pat, rep))


def tests_of(mutation: str | None) -> list[str]:
    """The validation tests a run executes: the mutation's own, or for the baseline the union of all."""
    if mutation is not None:
        return list(MUTATIONS[mutation][4])
    return sorted({t for m in MUTATIONS.values() for t in m[4]})


def check_patterns() -> list[str]:
    """Every pattern occurs exactly once in its file of this checkout (problems as lines)."""
    bad = []
    for name, (rel, pat, rep, _desc, tests) in MUTATIONS.items():
        n = (ROOT / rel).read_text().count(pat)
        if n != 1:
            bad.append(f"{name}: pattern found {n} times in {rel}")
        if pat == rep:
            bad.append(f"{name}: the replacement equals the pattern")
        for t in tests:
            if not (ROOT / t.split("::")[0]).exists():
                bad.append(f"{name}: test {t} does not exist")
            if "regression" in t:
                bad.append(f"{name}: {t} is a regression test, not a validation test")
    return bad


def failed_terms(xml_path: Path):
    """(failed, total, {term: worst relative difference}, failing tests) from the junit report of the run."""
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
        tests.append(f"{case.get('classname', '').rsplit('.', 1)[-1]}::{case.get('name')}")
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


def run(mutation: str | None, python: str, keep: bool = False, tests: list[str] | None = None) -> dict:
    """Copy, mutate, run ``tests`` (default :func:`tests_of`) in a subprocess; the outcome as a dict."""
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
                               *(tests or tests_of(mutation))], cwd=tmp, env=env, capture_output=True, text=True)
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
        names = sorted({re.sub(r"\[.*\]$", "", t) for t in res["tests"]})
        print(f"  failing tests: {', '.join(names)}")
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
    ap.add_argument("--check", action="store_true", help="only check that every pattern occurs once and every test exists")
    a = ap.parse_args(argv)
    bad = check_patterns()
    if bad or a.check:
        print("\n".join(bad) or f"{len(MUTATIONS)} mutations: every pattern occurs once, every test file exists")
        return 1 if bad else 0
    if a.list:
        for k, v in MUTATIONS.items():
            print(f"{k}: {v[3]} ({v[0]}: {v[1]!r} -> {v[2]!r}); tests: {' '.join(v[4])}")
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
