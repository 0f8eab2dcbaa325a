"""
Deep-groove sliding friction (dgbb_prl) against SKF 2004
========================================================

The sliding-friction torque of a 6206 deep-groove bearing under 500 N axial load by the pure-rolling-line method
(spinning + differential sliding) next to the SKF 2004 catalogue model, over the speed. ``hsbearing friction
dgbb_6206 --speeds 500,5000,15000rpm`` prints the same table (torques in N mm).
"""

import matplotlib.pyplot as plt

import hsbearing
from hsbearing.systems.deep_groove.friction import friction_torque


def main():
    case = hsbearing.load_case("dgbb_6206")
    ds = friction_torque(case, "500,5000,15000rpm")
    n = ds["speed"].values * 60 / (2 * 3.141592653589793)
    print("n [r/min]  M_sl [N mm]  SKF M_sl [N mm]  SKF M [N mm]")
    for i in range(n.size):
        print(f"{n[i]:9.0f}  {float(ds.sliding_torque[i]) * 1e3:11.3f}  {float(ds.skf_sliding_torque[i]) * 1e3:15.3f}"
              f"  {float(ds.skf_total_torque[i]) * 1e3:12.3f}")
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(n, ds.sliding_torque * 1e3, "o-", label="sliding torque, pure-rolling-line method")
    ax.plot(n, ds.skf_sliding_torque * 1e3, "s--", label="SKF 2004 M_sl")
    ax.set_xlabel("inner-ring speed [r/min]")
    ax.set_ylabel("torque [N mm]")
    ax.legend()
    fig.tight_layout()
    return ds


if __name__ == "__main__":
    main()
