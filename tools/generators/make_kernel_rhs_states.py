"""REGRESSION data of the compiled right-hand side: trajectory states and the kernel's rhs at them.

``tests/models/test_kernel_cost.py::test_rhs_within_roundoff_of_kernel_before_libm_changes`` compares today's kernel
with ``tests/data/regression/kernel_rhs_states.npz`` (our own output, not validation).  The test never
rewrites the file; regenerate it here, only after a deliberate physics change, and commit it with the reason:

    .venv/bin/python tools/generators/make_kernel_rhs_states.py

Default case: every 80th of 4001 states over 20 ms; table-5 case (1000 N radial, 130 degC, 1000 N axial):
every 80th of 2001 states over 20 ms.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

import hsbearing
from hsbearing.models.ball_bearing import kernel as K
from hsbearing.systems.angular_contact.dynamics import build_model

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data" / "regression" / "kernel_rhs_states.npz"
T5 = {"operating.radial_load": "1000 N", "lubricant.temperature": "130 degC", "operating.axial_load": "1000 N"}


def rhs(model, y):
    """The compiled right-hand side at state ``y`` (no auxiliary outputs)."""
    Z = model.layout.Z
    out = np.empty(y.size)
    K.rhs_kernel(y, model.P, model.qu, model.qw, out, np.empty((Z, K.N_CONTRIB)), np.empty((1, 1)), False,
                 np.empty(K.N_CONTRIB), np.empty(K.N_GAUX))
    return out


def main() -> None:
    from hsbearing.solvers.cvode import integrate

    out = {}
    for name, case, span, n, take in (("default", hsbearing.load_case("zhang2016"), 0.02, 4001, 80),
                                      ("t5", hsbearing.load_case("zhang2016", **T5), 0.02, 2001, 80)):
        m = build_model(case, drag_coefficient=0.5)  # the stored data's C_D (before C_D(Re), issue 29 session 7)
        sim = case.simulation
        res = integrate(m.rhs, m.y0, np.linspace(0.0, span, n), rtol=float(sim.rtol),
                        atol=m.layout.atol(float(sim.atol)), jacfn=m.jac)
        Y = np.asarray(res.y)[::take]
        out["y_" + name] = Y
        out["f_" + name] = np.array([rhs(m, y) for y in Y])
    DATA.parent.mkdir(parents=True, exist_ok=True)
    np.savez_compressed(DATA, **out)
    print(f"wrote {DATA.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
