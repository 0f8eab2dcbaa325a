"""
The default run
===============

The default case ``zhang2016`` (a 7206-size angular-contact bearing, 14000 r/min, 1 kN axial, oil 4109 at
130 degC) simulated for a short span: the cage speed and slip ratio against time. ``hsbearing run`` does the same
from the command line (0.7 s by default).
"""

import matplotlib.pyplot as plt

import hsbearing


def main(duration="0.02 s"):
    case = hsbearing.load_case("zhang2016")
    ds = hsbearing.simulate(case, duration=duration)
    print("status:", ds.attrs["status"])
    print(f"mean cage speed: {ds.cage_speed.mean().item() * 60 / (2 * 3.141592653589793):.0f} r/min")
    fig, ax = plt.subplots(figsize=(6, 3))
    (ds.cage_speed * 60 / (2 * 3.141592653589793)).plot(ax=ax)
    ax.set_ylabel("cage speed [r/min]")
    ax.set_xlabel("time [s]")
    fig.tight_layout()
    return ds


if __name__ == "__main__":
    main()
