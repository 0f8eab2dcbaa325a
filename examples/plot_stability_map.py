"""
A cage-stability map (tiny)
===========================

``run_map`` runs a two-key grid of dynamic runs and writes the cage-motion class of each cell and an instability
indicator (``map.nc``, ``map.png``). This one is 2 x 2 cells of 5 ms each so that it runs in about a minute; a real
map needs ~1 s of simulated time per cell (``hsbearing map zhang2016 --x ... --y ... -j 2 -o DIR``), and with
5 ms most cells are "undetermined" (too few Poincare points): the point here is the workflow.
"""

import tempfile

import hsbearing  # noqa: F401  (the package the map runs)
from hsbearing.workflows.maps import run_map


def main(duration="5 ms"):
    out = tempfile.mkdtemp(prefix="hsbearing-map-")
    ds = run_map("zhang2016", "bearing.outer_land_diameter=52.3,52.5mm", "cage.pocket_diameter=9.6,9.7mm",
                 out_dir=out, jobs=1, duration=duration, progress=False, stop=None)
    print(f"map written to {out}/map.nc and {out}/map.png")
    print(ds["classification"].to_pandas() if "classification" in ds else ds)
    return ds


if __name__ == "__main__":
    main()
