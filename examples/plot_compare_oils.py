"""
Comparing lubricants with a user oil
====================================

A lubricant file (TOML; format in the user guide, "Lubricant files and comparing oils") describes any oil by its
viscosity points, density and pressure-viscosity coefficient, and names the traction law it borrows. Here a user
ester is written next to the bundled oils and the default bearing is solved quasi-statically with each: the central
film thickness at the inner contact and the cage speed. ``hsbearing oils`` lists the bundled files.
"""

import math
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

import hsbearing

USER_OIL = """
name = "my ester"
class = "MIL-PRF-23699 class polyol ester (example values)"
viscosity = [["40 degC", "25 mm^2/s"], ["100 degC", "5.0 mm^2/s"]]
density = "1000 kg/m^3"
density_temperature = "15 degC"
pressure_viscosity_coefficient = "1.7e-8 1/Pa"

[traction]
model = "zhang2016"
oil = "4106"
law = "default"
"""


def main():
    path = Path(tempfile.mkdtemp(prefix="hsbearing-oil-")) / "my_ester.toml"
    path.write_text(USER_OIL)
    oils = ["4109", "4106", "mobil_jet_oil_ii", str(path)]
    rows = []
    print("oil                  h_c inner [nm]  cage speed [r/min]")
    for oil in oils:
        case = hsbearing.load_case("zhang2016", **{"lubricant.oil": oil})
        qs = hsbearing.quasi_static(case)
        h = float(qs.inner_film_thickness_central.mean()) * 1e9
        nc = float(qs.cage_speed) * 60 / (2 * math.pi)
        name = Path(oil).stem
        rows.append((name, h, nc))
        print(f"{name:20s} {h:14.1f}  {nc:18.1f}")
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.bar([r[0] for r in rows], [r[1] for r in rows])
    ax.set_ylabel("central film thickness, inner contact [nm]")
    ax.set_title("zhang2016 case, 130 degC")
    fig.tight_layout()
    return rows


if __name__ == "__main__":
    main()
