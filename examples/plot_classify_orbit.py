"""
Classifying a measured cage orbit
=================================

The classifier of ``hsbearing run`` works on any cage-centre record: here a "measured" orbit is made up (a whirl at
0.98 x the cage speed with a ball-pass ripple and sensor noise) and ``classify_motion`` reads it on the section
transverse to the flow. Replace ``t``, ``y``, ``z`` by your own displacement-probe record (SI units).
"""

import math

import matplotlib.pyplot as plt
import numpy as np

from hsbearing.analysis.whirl import classify_motion


def main():
    rng = np.random.default_rng(1)
    f_cage = 5784 / 60.0  # cage speed [rev/s]
    t = np.arange(0.0, 0.4, 2e-5)  # 0.4 s sampled at 50 kHz [s]
    w = 2 * math.pi * 0.98 * f_cage  # whirl at 0.98 x the cage speed [rad/s]
    r = 150e-6 * (1 + 0.01 * np.sin(2 * math.pi * 11 * f_cage * t))  # 150 um radius + 1 % ball-pass ripple [m]
    y = r * np.cos(w * t) + 0.5e-6 * rng.standard_normal(t.size)
    z = r * np.sin(w * t) + 0.5e-6 * rng.standard_normal(t.size)
    label, confidence, details = classify_motion(t, y, z, clearance=200e-6)
    print(f"classification: {label} (confidence {confidence:.2f})")
    fig, ax = plt.subplots(figsize=(4, 4))
    ax.plot(y * 1e6, z * 1e6, lw=0.3)
    ax.set_aspect("equal")
    ax.set_xlabel("cage centre y [um]")
    ax.set_ylabel("cage centre z [um]")
    ax.set_title(label)
    fig.tight_layout()
    return label


if __name__ == "__main__":
    main()
