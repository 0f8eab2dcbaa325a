"""
An axial-load sweep
===================

A sweep of ``kind="quasistatic"`` (fractions of a second per point) of the default bearing over the axial load:
the contact angles and the cage speed. ``hsbearing sweep zhang2016 --kind quasistatic --vary
axial_load=250,500,1000,2000N -o DIR`` does the same and draws ``DIR/sweep.png``; without ``--kind`` each point is
a dynamic run.
"""

import math
import tempfile

import matplotlib.pyplot as plt

import hsbearing


def main():
    out = tempfile.mkdtemp(prefix="hsbearing-sweep-")
    sw = hsbearing.sweep("zhang2016", {"operating.axial_load": ["250 N", "500 N", "1 kN", "2 kN"]},
                         kind="quasistatic", jobs=1, out_dir=out, progress=False)
    fa = sw["axial_load"].values
    print("axial load [N]  alpha_i [deg]  alpha_o [deg]  cage speed [r/min]")
    rows = []
    for i, f in enumerate(fa):
        qs = hsbearing.open_run(f"{out}/{sw['archive'].values[i]}")
        ai = math.degrees(float(qs.inner_contact_angle.mean()))
        ao = math.degrees(float(qs.outer_contact_angle.mean()))
        nc = float(qs.cage_speed) * 60 / (2 * math.pi)
        rows.append((float(f), ai, ao, nc))
        print(f"{float(f):14.0f}  {ai:13.2f}  {ao:13.2f}  {nc:18.1f}")
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot([r[0] for r in rows], [r[1] for r in rows], "o-", label="inner contact")
    ax.plot([r[0] for r in rows], [r[2] for r in rows], "s-", label="outer contact")
    ax.set_xlabel("axial load [N]")
    ax.set_ylabel("contact angle [deg]")
    ax.legend()
    fig.tight_layout()
    return rows


if __name__ == "__main__":
    main()
