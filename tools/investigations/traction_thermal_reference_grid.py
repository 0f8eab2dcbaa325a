"""The thermal traction law "physical" against the finite-volume reference over the whole grid of the slow test.

One line per case (oil 4106): U [m/s], W [N], T [degC], S, mu of the law and of the reference, their relative
difference, the largest film temperature rise of each [K], and whether the tolerances of docs/traction.md hold.
Run: PYTHONPATH=. .venv/bin/python tools/investigations/traction_thermal_reference_grid.py  (about 5 minutes)
"""

import itertools
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "validation"))
sys.path.insert(0, str(ROOT / "tests" / "helpers"))

import test_traction_thermal_reference as t  # noqa: E402


def main():
    for U, W, T_C, S in itertools.product([1.0, 16.3, 100.0], [100.0, 5000.0], [27.0, 230.0],
                                          [1e-4, -1e-3, 0.01, -0.05, 0.3, -0.3]):
        c = t._contact("4106", W, U, T_C)
        c["U"] = U
        mu, mr, dT, dTr = t._compare(c, S)
        ok = abs(mu - mr) <= t.REL * abs(mr) + t.ABS and abs(dT - dTr) <= t.T_REL * abs(dTr) + t.T_ABS
        print(f"{U:6.1f} {W:6.0f} {T_C:5.0f} {S:8.4f} law {mu:9.5f} ref {mr:9.5f} rel {mu / mr - 1:7.3f} "
              f"dT {dT:8.1f} ref {dTr:8.1f} {'ok' if ok else 'FAIL'}", flush=True)


if __name__ == "__main__":
    main()
