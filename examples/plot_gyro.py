"""
The gyroscope ribbon-cage bearing (jiang2014)
=============================================

The 4 x 9 mm gyroscope bearing of Jiang et al. (2014) at 1 N axial load and 5 r/min: the friction moment and its
parts (hysteresis M_E, differential sliding M_D, spin M_S, lubricant M_L, cage impacts M_C). ``hsbearing run
jiang2014_gyro`` prints SFMC and RFMC; ``--set mode=oscillation --duration 20.3s`` adds the reversals (SFMO).
"""

import matplotlib.pyplot as plt

import hsbearing


def main(duration="0.5 s"):
    ds = hsbearing.simulate("jiang2014_gyro", duration=duration)
    print("status:", ds.attrs["status"])
    print(f"SFMC = {float(ds.sfmc) * 1e6:.3f} uN m, RFMC = {float(ds.rfmc) * 1e6:.3f} uN m")
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(ds.time, ds.friction_moment_total * 1e6, label="M (total)")
    ax.plot(ds.time, ds.friction_moment_cage * 1e6, label="M_C (cage)")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("friction moment [uN m]")
    ax.legend()
    fig.tight_layout()
    return ds


if __name__ == "__main__":
    main()
