"""Independent assembly check: the compiled right-hand side against a plain-Python
reference of Zhang et al. 2016, Eqs. 5-21, built from the leaf laws only (tests/helpers/reference_assembly.py).

Random states in five regimes (both rotation senses, outer- and inner-ring guidance, a turning guide ring,
cage and ring tilts and rates, radial load and moments, balls loaded against their pocket walls, the cage
on and beyond its land clearance).  Compared term by term, each on its own scale:

* inner race on each ball: the kernel's per-ball ring contribution (force, moment about the ring centre);
* pocket on each ball: the kernel's per-ball cage contribution (force, moment about the cage centre);
* outer race on each ball: what the kernel's ball rows imply once the other terms are removed (and the
  kernel's own outer-race moment output tau_o);
* gravity on each ball: the change of the kernel's ball rows when gravity is switched off;
* per-ball scalar outputs (loads, traction components, slide-roll ratios, rolling speeds, F_R, drag, pocket
  film / solid loads, boundary friction);
* guide-land force and moment (global outputs), and every row of ydot (balls, cage, ring).

Tolerance: the reference uses the same discretisations as documented (5 Gauss nodes across the ellipse,
16 conformal stations around the pocket), so the two differ by round-off, by the kernel's numba twin of
the traction law and fastmath pocket sum, and by one kinematic detail (the radial part of the contact
centre's orbital velocity, which the kernel drops: measured 2e-7 of the rolling speed U under radial load,
bounded by its own test; compared here with the kernel's convention, ``reference_assembly.KERNEL_CONVENTIONS``).  Measured worst
difference over the 40 states: 2.2e-11 of the term's scale (docs/testing.md, "Independent assembly check");
``RTOL`` = 1e-8 is ~450 times that, and 4.7e4 times below the smallest effect of a mutation of
tools/investigations/mutation_check.py on a state it affects (4.7e-4, pocket entrainment).
"""

from __future__ import annotations

import math
import sys
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest

import hsbearing
from hsbearing.models.ball_bearing import kernel as K
from hsbearing.models.ball_bearing import kernel_io as kio
from hsbearing.systems.angular_contact.dynamics import build_model

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
import reference_assembly as ref  # noqa: E402

#: relative tolerance of every comparison, on the scale of its own term (see module docstring)
RTOL = 1e-8

REGIMES = {
    # default: outer-ring guided, inner ring at +14000 r/min, outer ring fixed, 1 kN axial
    "outer_guided": {},
    # the other rotation sense
    "reverse": {"operating.inner_speed": "-14000 rpm"},
    # a turning guide ring: the land speed enters the land film (omega_sum) and the outer race kinematics
    "turning_outer": {"operating.outer_speed": "-4000 rpm"},
    # inner-ring guidance (land centre and speed = the inner ring's; the ring takes the land reaction)
    "inner_guided": {"cage.guidance": "inner_ring", "bearing.inner_land_diameter": "44.0 mm",
                     "operating.outer_speed": "2000 rpm"},
    # radial load and moments: displaced, tilted ring, unequal ball loads
    "radial_tilt": {"operating.radial_load": "800 N", "operating.radial_load_z": "-300 N",
                    "operating.moment_y": "3 N m"},
}
N_STATES = 8  # random states per regime


@lru_cache(maxsize=None)
def model_of(regime):
    return build_model(hsbearing.load_case("zhang2016", **REGIMES[regime]))


def random_state(model, rng, k):
    """A state near the model's start with every body perturbed; state k = 0 puts the cage beyond its land
    clearance (rub), the others spread the land eccentricity over 0.2-0.9; ball k mod Z is pressed into its
    pocket wall, the others sit at random offsets in their pockets; in state 1 one ball's outer contact is open."""
    y = model.y0.copy()
    Z = model.layout.Z
    cg, rg = model.layout.cage0, model.layout.ring0
    P = model.P
    dm, cp = kio.get(P, "dm"), kio.get(P, "c_p")
    cl = kio.get(P, "c_land")
    if not math.isfinite(cl):  # ball-piloted cage (no land): move its centre on the scale of the pocket clearance
        cl = cp
    # inner ring: displacement, tilt, rates
    y[rg:rg + 3] += rng.normal(0.0, [0.2e-6, 0.5e-6, 0.5e-6])  # (contact deflections are ~4 um)
    y[rg + 3:rg + 5] += rng.normal(0.0, 3e-5, 2)
    y[rg + 5:rg + 10] = rng.normal(0.0, [2e-3, 5e-3, 5e-3, 0.5, 0.5])
    # cage: centre at a chosen land eccentricity (relative to the land centre), tilts, rates
    ecc = 1.003 if k == 0 else rng.uniform(0.2, 0.9)
    ang = rng.uniform(0.0, 2.0 * math.pi)
    land_c = y[rg + 1:rg + 3] if kio.get(model.P, "guide") == kio.GUIDE_INNER_RING else np.zeros(2)
    y[cg + 1:cg + 3] = land_c + ecc * cl * np.array([math.cos(ang), math.sin(ang)])
    y[cg] += rng.normal(0.0, 2e-6)
    y[cg + 3] += rng.normal(0.0, 0.01)  # (the balls keep their azimuths: radial load sets u_b, x_b by azimuth)
    y[cg + 4:cg + 6] += rng.normal(0.0, 5e-5, 2)
    wc = y[cg + 9]
    y[cg + 6:cg + 9] = rng.normal(0.0, [2e-3, 0.05, 0.05])
    y[cg + 9] = wc * (1.0 + rng.normal(0.0, 0.02))
    y[cg + 10:cg + 12] = rng.normal(0.0, 2.0, 2)
    # balls: positions, rates, spins; each ball placed at a chosen offset in its (moved) pocket
    y[0:Z] += rng.normal(0.0, 0.5e-6, Z)
    y[Z:2 * Z] += rng.normal(0.0, 0.5e-6, Z)
    if k == 1:  # one ball moved 8 um towards the axis: its outer contact opens (the Q = 0 branch)
        y[Z + (k + 3) % Z] -= 8e-6
    # each ball at a chosen circumferential offset in its (moved, tilted) pocket: a few Newton steps on theta_rel
    prm = ref.params_of(model)
    for j in range(Z):
        target = cp * rng.uniform(-0.9, 0.9)
        if j == k % Z:  # one ball pressed into its pocket wall (Hertz part and boundary friction)
            target = 1.003 * cp * math.copysign(1.0, target)
        for _ in range(4):
            et = pocket_offset(y, prm, j)[2]
            y[2 * Z + j] += (target - et) / (0.5 * dm + y[Z + j])
    y[3 * Z:4 * Z] = rng.normal(0.0, 0.01, Z)
    y[4 * Z:5 * Z] = rng.normal(0.0, 0.03, Z)  # radial speed relative to the pocket (pocket entrainment)
    y[5 * Z:6 * Z] = y[cg + 9] * (1.0 + rng.normal(0.0, 0.01, Z))
    for q in range(6, 9):
        w = y[q * Z:(q + 1) * Z]
        y[q * Z:(q + 1) * Z] = w * (1.0 + rng.normal(0.0, 0.02, Z)) + rng.normal(0.0, 0.01 * np.max(np.abs(w)), Z)
    return y


def pocket_offset(y, prm, j):
    """Ball j's centre relative to its pocket centre in the pocket axes (x: cage axis, r: pocket axis, t)."""
    bod = ref.unpack(y, prm)
    Rc, pj = bod.cage["R"], 2.0 * math.pi * j / bod.Z
    e_r = Rc @ np.array([0.0, math.cos(pj), math.sin(pj)])
    e_t = Rc @ np.array([0.0, -math.sin(pj), math.cos(pj)])
    d = bod.balls[j]["b"] - bod.cage["pos"] - 0.5 * prm.dm * e_r
    return float(d @ (Rc @ ref.EX)), float(d @ e_r), float(d @ e_t)


def kernel_eval(model, y):
    Z = model.layout.Z
    ydot = np.empty_like(y)
    contrib = np.zeros((Z, K.N_CONTRIB))
    aux = np.zeros((Z, K.N_AUX))
    gaux = np.zeros(K.N_GAUX)
    K.rhs_kernel(np.ascontiguousarray(y), model.P, model.qu, model.qw, ydot, contrib, aux, True,
                 np.zeros(K.N_CONTRIB), gaux)
    return ydot, contrib, aux, gaux


def kernel_ball_wrench(model, y, ydot, j, bod):
    """Resultant force and moment on ball j (inertial) implied by the kernel's ball rows (Eqs. 5-10 inverted)."""
    Z = model.layout.Z
    P = model.P
    m, Ib = kio.get(P, "m_b"), kio.get(P, "I_b")
    ball = bod.balls[j]
    r, vr, thd = ball["r"], ball["vr"], ball["thd"]
    wx, wy, wz = ball["wf"]
    xdd, rdd, thdd, wxd, wyd, wzd = (ydot[q * Z + j] for q in range(3, 9))
    Fb = m * np.array([xdd, rdd - r * thd * thd, r * thdd + 2.0 * vr * thd])
    Mb = Ib * np.array([wxd, wyd - thd * wz, wzd + thd * wy])
    B = np.array(ball["basis"])
    return B.T @ Fb, B.T @ Mb


def state_of(regime, k):
    model = model_of(regime)
    rng = np.random.default_rng(1000 * (list(REGIMES).index(regime) + 1) + k)
    return model, random_state(model, rng, k)


def compare(regime, k, conventions=ref.KERNEL_CONVENTIONS, model=None, y=None):
    """All term-by-term differences at random state k of a regime: {name: (max |diff|, scale)}."""
    if model is None:
        model, y = state_of(regime, k)
    yd_k, contrib, aux, gaux = kernel_eval(model, y)
    yd_r, terms = ref.evaluate(model, y, conventions)
    bod = terms["bodies"]
    Z = model.layout.Z
    A = K.AUX_INDEX
    out = {}

    def add(name, kern, refv, floor):
        kern, refv = np.asarray(kern, float), np.asarray(refv, float)
        d = float(np.max(np.abs(kern - refv)))
        s = float(max(float(np.max(np.abs(refv))), float(np.max(np.abs(kern))), floor))
        prev = out.get(name)
        if prev is None or d / s > prev[0] / prev[1]:
            out[name] = (d, s)

    ring_F, ring_M, cage_F, cage_M, outer_F, outer_M = ([] for _ in range(6))
    r_ring_F, r_ring_M, r_cage_F, r_cage_M, r_outer_F, r_outer_M = ([] for _ in range(6))
    for j in range(Z):
        t = terms["balls"][j]
        ball = bod.balls[j]
        cF = contrib[j, [K.C_RFX, K.C_RFY, K.C_RFZ]]
        cM = contrib[j, [K.C_RMX, K.C_RMY, K.C_RMZ]]
        pF = contrib[j, [K.C_CFX, K.C_CFY, K.C_CFZ]]
        pM = contrib[j, [K.C_CMX, K.C_CMY, K.C_CMZ]]
        ring_F.append(cF)
        ring_M.append(cM)
        cage_F.append(pF)
        cage_M.append(pM)
        r_ring_F.append(t["ring_F"])
        r_ring_M.append(t["ring_M"])
        r_cage_F.append(t["cage_F"])
        r_cage_M.append(t["cage_M"])
        # the kernel's outer-race term: resultant minus its own inner, pocket, drag and gravity terms
        Ft, Mt = kernel_ball_wrench(model, y, yd_k, j, bod)
        Fi_k, Fp_k = -cF, -pF
        Mi_k = -cM - np.cross(ball["b"] - bod.ring["pos"], Fi_k)
        Mp_k = -pM - np.cross(ball["b"] - bod.cage["pos"], Fp_k)
        drag_k = aux[j, A["F_D"]] * ball["basis"][2]
        outer_F.append(Ft - Fi_k - Fp_k - drag_k - t["gravity"])
        outer_M.append(Mt - Mi_k - Mp_k)
        r_outer_F.append(t["outer"]["F"])
        r_outer_M.append(t["outer"]["M"])
    # forces: floor 1e-3 N; moments about ring/cage centres 1e-5 N m; about the ball centre 1e-6 N m
    add("inner race force (ring contribution)", ring_F, r_ring_F, 1e-3)
    add("inner race moment about the ring centre", ring_M, r_ring_M, 1e-5)
    add("pocket force (cage contribution)", cage_F, r_cage_F, 1e-3)
    add("pocket moment about the cage centre", cage_M, r_cage_M, 1e-5)
    add("outer race force (from the ball rows)", outer_F, r_outer_F, 1e-3)
    add("outer race moment (from the ball rows)", outer_M, r_outer_M, 1e-6)
    tb = terms["balls"]
    scal = {
        "Q_i": [x["inner"]["Q"] for x in tb], "Q_o": [x["outer"]["Q"] for x in tb],
        "T_roll_i": [x["inner"]["T1"] for x in tb], "T_trans_i": [x["inner"]["T2"] for x in tb],
        "T_roll_o": [x["outer"]["T1"] for x in tb], "T_trans_o": [x["outer"]["T2"] for x in tb],
        "S_i": [x["inner"]["S0"] for x in tb], "S_o": [x["outer"]["S0"] for x in tb],
        "U_i": [x["inner"]["U"] for x in tb], "U_o": [x["outer"]["U"] for x in tb],
        "F_R_i": [x["inner"]["FR"] for x in tb], "F_R_o": [x["outer"]["FR"] for x in tb],
        "F_D": [x["FD"] for x in tb], "Q_film": [x["pocket"]["Q_film"] for x in tb],
        "Q_solid": [x["pocket"]["Q_solid"] for x in tb], "Q_c": [x["pocket"]["Q_c"] for x in tb],
        "P_S": [x["pocket"]["P_S"] for x in tb],
    }
    floors = {"S_i": 1e-4, "S_o": 1e-4, "U_i": 1e-2, "U_o": 1e-2}
    for name, v in scal.items():
        add(f"aux {name}", aux[:, A[name]], v, floors.get(name, 1e-3))
    # gravity by difference: the kernel without gravity changes the ball rows by the weight only (Eqs. 5-7)
    Pg = model.P.copy()
    kio.set_value(Pg, "grav", 0.0)
    yd_0 = np.empty_like(y)
    K.rhs_kernel(np.ascontiguousarray(y), Pg, model.qu, model.qw, yd_0, np.zeros((Z, K.N_CONTRIB)),
                 np.zeros((Z, K.N_AUX)), False, np.zeros(K.N_CONTRIB), np.zeros(K.N_GAUX))
    m_b = kio.get(model.P, "m_b")
    grav_k = []
    for j in range(Z):
        ball = bod.balls[j]
        a_x, a_r, a_t = (yd_k[q * Z + j] - yd_0[q * Z + j] for q in (3, 4, 5))
        grav_k.append(np.array(ball["basis"]).T @ (m_b * np.array([a_x, a_r, ball["r"] * a_t])))
    add("gravity on the balls (by difference)", grav_k, [x["gravity"] for x in tb], 1e-6)
    # moment about X through the origin of the outer-race actions on the ball (the kernel's own output)
    add("aux tau_o", aux[:, A["tau_o"]],
        [float((np.cross(bod.balls[j]["b"], tb[j]["outer"]["F"]) + tb[j]["outer"]["M"])[0]) for j in range(Z)], 1e-5)
    land = terms["land"]
    G = K.GAUX_INDEX
    add("land force (F_cy, F_cz)", [gaux[G["F_cy"]], gaux[G["F_cz"]]], land["F"][1:], 1e-3)
    cpos = bod.cage["pos"]
    add("land moment about X (land_torque_x)", gaux[G["land_torque_x"]],
        float((np.cross(cpos, land["F"]) + land["M"])[0]), 1e-5)
    # every row of ydot: ball rows by block (scale: the block's largest value); cage and ring rows on the
    # scale of the loads that make them up (sum of the magnitudes of the terms, over the mass or inertia), so
    # that a row where large terms cancel is not judged on its small remainder
    for q, name in enumerate(hsbearing.models.ball_bearing.state.BALL_STATES):
        sl = slice(q * Z, (q + 1) * Z)
        add(f"ydot {name}", yd_k[sl], yd_r[sl], 1e-9)
    cg, rg = model.layout.cage0, model.layout.ring0
    P = model.P
    g = kio.get(P, "grav")
    land = terms["land"]
    fc = (sum(np.linalg.norm(x["cage_F"]) for x in tb) + np.linalg.norm(land["F"]) + kio.get(P, "m_c") * g)
    mc = sum(np.linalg.norm(x["cage_M"]) for x in tb) + np.linalg.norm(land["M"])
    fr = (sum(np.linalg.norm(x["ring_F"]) for x in tb) + np.linalg.norm(land["F"]) + kio.get(P, "m_i") * g
          + np.linalg.norm([kio.get(P, n) for n in ("F_x", "F_y", "F_z")]))
    mr = sum(np.linalg.norm(x["ring_M"]) for x in tb) + np.linalg.norm([kio.get(P, "M_y"), kio.get(P, "M_z")])
    load_scale = ([0.0] * 6 + [fc / kio.get(P, "m_c")] * 3 + [mc / kio.get(P, "Ip_c")] + [mc / kio.get(P, "Id_c")] * 2
                  + [0.0] * 5 + [fr / kio.get(P, "m_i")] * 3 + [mr / kio.get(P, "Id_i")] * 2)
    names = model.state_names
    for i in range(cg, rg + 10):
        add(f"ydot {names[i]}", yd_k[i], yd_r[i], max(load_scale[i - cg], 1e-9))
    return out, dict(y=y, terms=terms, yd_k=yd_k, yd_r=yd_r, aux=aux, gaux=gaux, contrib=contrib)


CASES = [(reg, k) for reg in REGIMES for k in range(N_STATES)]


@pytest.mark.parametrize("regime,k", CASES, ids=[f"{r}-{k}" for r, k in CASES])
def test_kernel_matches_reference_term_by_term(regime, k):
    out, _ = compare(regime, k)
    bad = {n: (float(d), float(s), float(d / s)) for n, (d, s) in out.items() if not d <= RTOL * s}
    assert not bad, f"{regime} state {k}: kernel vs reference beyond {RTOL:g} of the term's scale: {bad}"


def test_states_exercise_every_term():
    """The random states load what the comparisons are meant to check (a comparison of zeros proves nothing):
    traction at both races, pocket films with a radial ball speed in the pocket, a ball on its pocket wall,
    land films with the land turning (turning outer ring, inner guidance), the cage rubbing its land."""
    A, G = K.AUX_INDEX, K.GAUX_INDEX
    for regime in REGIMES:
        model = model_of(regime)
        P = model.P
        wl = kio.get(P, "omega_i") if kio.get(P, "guide") == kio.GUIDE_INNER_RING else kio.get(P, "omega_o")
        if regime in ("turning_outer", "inner_guided"):
            assert abs(wl) > 200.0, regime  # the land turns: omega_sum = cage + land speed
        land = []
        for k in range(N_STATES):
            model, y = state_of(regime, k)
            yd, contrib, aux, gaux = kernel_eval(model, y)
            Z = model.layout.Z
            assert np.count_nonzero(aux[:, A["Q_i"]] > 1.0) >= Z - 1, (regime, k)
            assert np.count_nonzero(aux[:, A["Q_o"]] > 1.0) >= (Z - 1 if k == 1 else Z), (regime, k)
            if k == 1:
                assert np.count_nonzero(aux[:, A["Q_o"]] == 0.0) >= 1, (regime, k)  # an open contact
            assert np.max(np.abs(aux[:, A["T_roll_i"]])) > 0.1 and np.max(np.abs(aux[:, A["T_trans_o"]])) > 0.01
            assert np.count_nonzero(aux[:, A["Q_solid"]] > 0.0) >= 1, (regime, k)  # one ball on its pocket wall
            assert np.max(np.abs(y[4 * Z:5 * Z])) > 0.01  # radial ball speeds: the pocket entrainment term
            assert np.median(aux[:, A["Q_film"]]) > 1e-3, (regime, k)
            land.append(math.hypot(gaux[G["F_cy"]], gaux[G["F_cz"]]))
        assert np.count_nonzero(np.array(land) > 3e-3) >= N_STATES // 2, (regime, land)  # loaded land films
        _, y0 = state_of(regime, 0)
        cg, rg = model.layout.cage0, model.layout.ring0
        land_c = y0[rg + 1:rg + 3] if kio.get(P, "guide") == kio.GUIDE_INNER_RING else np.zeros(2)
        assert np.hypot(*(y0[cg + 1:cg + 3] - land_c)) > kio.get(P, "c_land")  # state 0: the cage rubs its land


def test_contact_centre_velocity_simplification_is_negligible():
    """The kernel moves the contact centre with (r + rho_r) theta' e_t only; the ball frame's orbital rotation
    also gives it -theta' rho_t e_r (rho = -(D/2) n).  Bounded: < 1e-5 of the rolling speed and of every term
    (measured 2e-7, radial_tilt, where the displaced ring gives the normal its largest circumferential part)."""
    for regime in ("radial_tilt", "outer_guided"):
        for k in range(2):
            out, _ = compare(regime, k, conventions=dict(ref.KERNEL_CONVENTIONS, orbit_radial=True))
            worst = max(d / s for d, s in out.values())
            assert worst < 1e-5, (regime, k, worst)


def test_inner_guided_pocket_film_has_the_cage_outside_radius():
    """docs/pocket.md: the pocket wall runs from the cage bore to the cage outside cylinder, whatever the guidance."""
    for k in range(2):
        out, _ = compare("inner_guided", k, conventions=dict(ref.KERNEL_CONVENTIONS, pocket_outer_radius="case"))
        bad = {n: d / s for n, (d, s) in out.items() if not d <= RTOL * s}
        assert not bad, bad


def test_ball_guided_rhs_is_finite_and_matches_the_reference():
    model = build_model(hsbearing.load_case("zhang2016", **{"cage.guidance": "ball"}))
    rng = np.random.default_rng(7)
    y = random_state(model, rng, 1)
    out, _ = compare("ball", 1, conventions=dict(ref.KERNEL_CONVENTIONS, pocket_outer_radius="case"), model=model, y=y)
    bad = {n: d / s for n, (d, s) in out.items() if not d <= RTOL * s}
    assert not bad, bad


@pytest.mark.slow
def test_mutation_check_catches_the_three_mutations():
    """tools/investigations/mutation_check.py: the unmutated copy passes; halving the slide-roll ratio into the traction law,
    the pocket entrainment velocity dUu - vr and the land speed sign phd - wl each fail this file, on the term
    they corrupt (4 subprocess runs, each compiling the kernel into a fresh numba cache: ~0.5-2 min each)."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools" / "investigations"))
    import mutation_check as M

    base = M.run(None, sys.executable, tests=[M.ASM])
    assert base["rc"] == 0 and base["failed"] == 0, base
    for name in M.EXPECTED_TERM:
        res = M.run(name, sys.executable, tests=[M.ASM])
        assert res["rc"] == 1 and res["failed"] >= 16, (name, res["failed"], res["tail"])
        assert M.EXPECTED_TERM[name] in res["terms"], (name, sorted(res["terms"]))
