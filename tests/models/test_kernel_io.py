"""The kernel's parameters and outputs by name (hsbearing/models/ball_bearing/kernel_io.py), and the couplings the
Jacobian's cached columns rely on.

* Every declared parameter is read by the kernel source (``p.<group>.<name>``), every read one is declared,
  and every declared one is filled by ``build_model`` (``kernel_io.pack`` refuses a missing or unknown name).
* Every declared output column is written exactly once by name (``aux[j, AUX.<name>]``, ``gaux[GAUX.<name>]``)
  and no column is written by number; the Dataset variables the declaration names are registered; every
  dissipated-power column belongs to exactly one power-loss source of ``balances.SOURCES``.
* The Jacobian's reuse (kernel.jac_kernel): the ring columns reuse each ball's pocket wrench, so the pocket
  must not depend on ring states; the cage columns except the cage angle reuse gravity and the race
  contacts, so those must not depend on cage states other than the angle.  Checked bit for bit on loaded
  states; a failure names the state and the term it now couples.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

import hsbearing
from hsbearing.models.ball_bearing import kernel_io as kio

# the kernel and the traction-law kernels it hands its parameter record to (traction_coefficients_nb)
KERNEL_SRC = (Path(kio.__file__).parent / "kernel.py").read_text() + \
    (Path(kio.__file__).parents[1] / "traction" / "_kernels.py").read_text()


def test_every_declared_parameter_is_read_and_every_read_one_declared():
    read = set(re.findall(r"\bp\.(\w+)\.(\w+)\b", KERNEL_SRC))
    declared = {(g, n) for g, n, *_ in kio.PARAMETERS}
    assert not (declared - read), f"declared but never read by the kernel: {sorted(declared - read)}"
    assert not (read - declared), f"read by the kernel but not declared: {sorted(read - declared)}"
    assert "P[P_" not in KERNEL_SRC  # no positional parameter index left


def test_every_parameter_has_units_and_meaning():
    for g, n, t, units, meaning in kio.PARAMETERS:
        assert t in ("f8", "i8", "?") and units and meaning, n
    assert set(kio.GUIDANCE) == {"ball", "outer_ring", "inner_ring"}


def test_pack_refuses_missing_and_unknown_names():
    vals = {n: 0 for n in kio.PARAM_GROUP}
    P = kio.pack(vals)
    assert P.dtype == kio.PARAM_DTYPE and P.shape == (1,)
    with pytest.raises(KeyError, match="missing"):
        kio.pack({k: v for k, v in vals.items() if k != "h_min"})
    with pytest.raises(KeyError, match="unknown"):
        kio.pack(dict(vals, Rsq_c=1.0))


@pytest.fixture(scope="module")
def model():
    from hsbearing.systems.angular_contact.dynamics import build_model

    return build_model(hsbearing.load_case("zhang2016"))


def test_build_model_fills_every_parameter_by_name(model):
    d = kio.as_dict(model.P)
    assert set(d) == set(kio.PARAM_GROUP)
    assert d["guide"] == kio.GUIDE_OUTER_RING and d["friction"] is True and d["Z"] == model.layout.Z
    lands = model.info["guide_lands"]
    assert d["R_out_c"] == 0.5 * model.case.cage.outside_diameter == d["R_land"] == lands.radius
    assert d["R_bore_c"] == 0.5 * model.case.cage.bore_diameter
    for n, v in d.items():
        assert np.isfinite(v), n  # outer-ring guided case: every parameter defined


def test_every_output_column_is_written_once_by_name():
    assert not re.search(r"\baux\[j, \d", KERNEL_SRC) and not re.search(r"\bgaux\[\d", KERNEL_SRC)
    for name, *_ in kio.BALL_OUTPUTS:
        assert len(re.findall(rf"\baux\[j, AUX\.{name}\] =", KERNEL_SRC)) == 1, name
    for name, *_ in kio.GLOBAL_OUTPUTS:
        assert len(re.findall(rf"\bgaux\[GAUX\.{name}\] =", KERNEL_SRC)) == 1, name
    assert list(kio.AUX._fields) == [r[0] for r in kio.BALL_OUTPUTS] and list(kio.AUX) == list(range(kio.N_AUX))


def test_declared_dataset_variables_are_registered_and_power_columns_have_one_source():
    import hsbearing.systems.angular_contact.dynamics  # noqa: F401  (registers the run variables)
    import hsbearing.systems.angular_contact.quasistatic  # noqa: F401  (registers the shared ball/ring names)
    from hsbearing import results
    from hsbearing.systems.angular_contact import balances

    for var in list(kio.DATASET_BALL) + list(kio.DATASET_GLOBAL):
        assert var in results.VARIABLES, var
    for name, units, *_ in kio.BALL_OUTPUTS:
        if units == "W":
            owners = [s for s, (_d, cols, _g) in balances.SOURCES.items() if name in cols]
            assert len(owners) == 1, (name, owners)
    for name, units, *_ in kio.GLOBAL_OUTPUTS:
        if units == "W" and name != "P_drive":
            owners = [s for s, (_d, _c, g) in balances.SOURCES.items() if g == name]
            assert len(owners) == 1, (name, owners)


# ----------------------------------------------------------------------------- Jacobian reuse invariants
#: per-ball output columns of the race contacts (reused for the cage columns but the angle)
RACE_COLUMNS = ("Q_i", "Q_o", "alpha_i", "alpha_o", "T_roll_i", "T_trans_i", "T_roll_o", "T_trans_o", "S_i", "S_o",
                "U_i", "U_o", "F_R_i", "F_R_o", "spin_roll_i", "spin_roll_o", "P_trac_i", "P_trac_o", "P_ehl_i",
                "P_ehl_o", "P_damp_i", "P_damp_o", "tau_o")
#: per-ball output columns of the pocket wrench (reused for the ring columns)
POCKET_COLUMNS = ("Q_c", "P_S", "Q_film", "Q_solid", "P_pocket_film", "P_pocket_boundary")


def _ball_terms(model, y):
    from hsbearing.models.ball_bearing import kernel as K

    Z = model.layout.Z
    ydot = np.empty(y.size)
    contrib = np.zeros((Z, K.N_CONTRIB))
    aux = np.zeros((Z, kio.N_AUX))
    K.ball_loop(np.ascontiguousarray(y), model.P, model.qu, model.qw, ydot, contrib, aux, True)
    return contrib, aux


def _states(model):
    Z = model.layout.Z
    y1 = model.y0.copy()  # film and Hertz: balls from one pocket wall to the other, cage off-centre and tilted
    y1[2 * Z:3 * Z] = np.linspace(-1.25, 1.25, Z) * kio.get(model.P, "c_p") / (0.5 * kio.get(model.P, "dm"))
    y1[3 * Z:4 * Z] = 0.01
    cg = model.layout.cage0
    y1[cg + 1:cg + 3], y1[cg + 4:cg + 6] = (5e-6, -3e-6), (2e-5, -1e-5)
    y1[cg + 7:cg + 9], y1[cg + 10:cg + 12] = (0.02, -0.01), (0.5, 0.3)
    y2 = np.load(Path(__file__).resolve().parents[1] / "data" / "regression" / "kernel_rhs_states.npz")["y_default"][-1].copy()
    return {"film_and_hertz": y1, "trajectory": y2}


def test_jacobian_reuse_couplings_hold(model):
    """Perturb each state the Jacobian's cached terms claim not to depend on (by 1e-3 of its typical scale, far
    beyond a finite-difference step) and require the cached terms unchanged bit for bit."""
    from hsbearing.models.ball_bearing import kernel as K

    names = model.state_names
    cg, rg, N = model.layout.cage0, model.layout.ring0, model.layout.size
    A = kio.AUX_INDEX
    race = [A[c] for c in RACE_COLUMNS]
    pocket = [A[c] for c in POCKET_COLUMNS]
    ring_contrib = [K.C_RFX, K.C_RFY, K.C_RFZ, K.C_RMX, K.C_RMY, K.C_RMZ]
    cage_contrib = [K.C_CFX, K.C_CFY, K.C_CFZ, K.C_CMX, K.C_CMY, K.C_CMZ]
    for label, y in _states(model).items():
        c0, a0 = _ball_terms(model, y)
        assert np.abs(a0[:, A["Q_film"]]).max() > 0 and np.abs(a0[:, A["Q_i"]]).max() > 0, label
        for col in range(cg, N):
            yp = y.copy()
            yp[col] += 1e-3 * max(abs(y[col]), model.hscale[col])
            c1, a1 = _ball_terms(model, yp)
            if col >= rg:  # ring state: the ring columns reuse the pocket wrench
                assert np.array_equal(a1[:, pocket], a0[:, pocket]) and np.array_equal(c1[:, cage_contrib], c0[:, cage_contrib]), \
                    f"{label}: the pocket wrench now depends on the ring state {names[col]}: jac_kernel's ring columns " \
                    f"reuse it (pmode 2) and would be wrong"
            elif col != cg + 3:  # cage state but the angle: the cage columns reuse gravity and the race contacts
                assert np.array_equal(a1[:, race], a0[:, race]) and np.array_equal(c1[:, ring_contrib], c0[:, ring_contrib]), \
                    f"{label}: the race contacts now depend on the cage state {names[col]}: jac_kernel's cage columns " \
                    f"reuse them (rmode 2) and would be wrong"
