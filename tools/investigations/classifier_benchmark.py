"""Run the synthetic classifier benchmark (hsbearing.analysis.benchmark) and print expected vs obtained labels.

Usage: python tools/investigations/classifier_benchmark.py [--markdown] [--clock] [--positions-only]
--clock adds the labels under the cage-revolution (stroboscopic) section for comparison.
--positions-only drops the velocities (a probe record; hsbearing.analysis.derivative estimates them) and adds the
2 % probe noise level.
"""
from __future__ import annotations

import argparse
import time

from hsbearing.analysis import benchmark as B
from hsbearing.analysis.whirl import classify_motion


def run(m, section, positions_only=False):
    vy, vz = (None, None) if positions_only else (m.vy, m.vz)
    lab, conf, det = classify_motion(m.t, m.y, m.z, vy, vz, m.phi, clearance=B.CLEARANCE, section=section)
    return lab, conf, det


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--markdown", action="store_true")
    ap.add_argument("--clock", action="store_true")
    ap.add_argument("--positions-only", action="store_true")
    a = ap.parse_args()
    rows = []
    t0 = time.perf_counter()
    for length in ("short", "long"):
        for noise in (0.0,) + B.NOISE_LEVELS + ((B.PROBE_NOISE,) if a.positions_only else ()):
            for m in B.cases(length, noise):
                lab, conf, det = run(m, "transverse", a.positions_only)
                ok = m.accepts(lab) and (not m.kind or det.get("kind") == m.kind or lab != "undetermined" or m.kind == "irregular")
                clock = run(m, "cage_revolution", a.positions_only)[0] if a.clock else ""
                rows.append((length, noise, m.name.split(", noise")[0], m.expected + (" / " + "/".join(m.also) if m.also else ""),
                             lab, det.get("kind", ""), det.get("n_points", 0), "ok" if ok else "MISS", clock))
    if a.markdown:
        print("| length | noise | motion | expected | obtained (transverse) | reading | points | | cage-revolution section |")
        print("|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            print(f"| {r[0]} | {100 * r[1]:g} % | {r[2]} | {r[3]} | {r[4]} | {r[5]} | {r[6]} | {r[7]} | {r[8]} |")
    else:
        for r in rows:
            print(f"{r[0]:5s} {100 * r[1]:4.1f}% {r[2]:34s} exp {r[3]:28s} got {r[4]:16s} {r[5]:16s} n={r[6]:4d} {r[7]:4s} {r[8]}")
    print(f"{sum(r[7] == 'ok' for r in rows)} of {len(rows)} as expected; {time.perf_counter() - t0:.1f} s")


if __name__ == "__main__":
    main()
