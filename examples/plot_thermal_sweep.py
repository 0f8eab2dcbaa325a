"""
A thermal sweep over speed and oil flow
=======================================

The steady thermal network (rings, balls, cage, oil, housing, shaft) at the bearing's own power loss, iterated with
the lubricant temperature, over the inner-ring speed and the oil flow rate (a sweep of ``kind="thermal"``). The
command line: ``hsbearing sweep zhang2016 --kind thermal --vary inner_speed=6000,14000rpm
--vary oil_flow_rate=0.5,2L/min -o DIR``.
"""

import tempfile

import matplotlib.pyplot as plt

import hsbearing


def main():
    out = tempfile.mkdtemp(prefix="hsbearing-thermal-")
    ds = hsbearing.sweep("zhang2016", {"inner_speed": "6000,14000rpm", "oil_flow_rate": "0.5,2L/min"},
                         kind="thermal", jobs=1, out_dir=out, progress=False)
    T = ds["outer_ring_temperature"] - 273.15
    print("outer-ring temperature [degC] (rows: inner speed, columns: oil flow)")
    print(T.to_pandas().round(1) if hasattr(T, "to_pandas") else T.values)
    fig, ax = plt.subplots(figsize=(6, 3.5))
    for j in range(ds.sizes["oil_flow_rate"]):
        q = ds["oil_flow_rate"].values[j]
        ax.plot(ds["inner_speed"].values * 60 / (2 * 3.141592653589793), T.isel(oil_flow_rate=j).values, "o-",
                label=f"oil flow {float(q) * 6e4:g} L/min")
    ax.set_xlabel("inner-ring speed [r/min]")
    ax.set_ylabel("outer-ring temperature [degC]")
    ax.legend()
    fig.tight_layout()
    return ds


if __name__ == "__main__":
    main()
