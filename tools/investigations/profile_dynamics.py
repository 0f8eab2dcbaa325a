"""Where the wall time of one dynamic run goes: py-spy samples split by cost category.

Record (py-spy is in the lock's bench extra; ``--native`` sees into SUNDIALS, numba and numpy)::

    .venv/bin/py-spy record --native -r 500 -f raw -o prof.txt -- \\
        .venv/bin/python tools/investigations/profile_dynamics.py run --stepping normal --span 0.1
    .venv/bin/python tools/investigations/profile_dynamics.py split prof.txt

``run`` builds the default case, warms up (compile/cache load, 2 ms run) and then times one
``hsbearing.simulate`` of ``--span`` seconds (the whole user-visible call: integration, outputs, dataset
assembly and analysis) with CVODE in ``--stepping`` mode.  ``split`` attributes every sample of that call to
one category by the frames on its stack (first match, in the order printed):

- dataset assembly: ``to_dataset`` (auxiliary outputs re-evaluated at each output time, xarray, analysis);
- Jacobian: our compiled arrowhead Jacobian (``DynamicModel.jac``) and its copy into the SUNDIALS matrix;
- rhs kernel: the compiled right-hand side (``DynamicModel.rhs`` and below), with numba's dispatch;
- rhs callback wrapper: scikit-sundae's ``_rhsfn_wrapper`` around it (N_Vector -> ndarray views, Python call);
- linear algebra: SUNDIALS dense LU (``denseGETRF``), back-solve (``denseGETRS``), ``M = I - gamma J``;
- CVODE internals: the rest of ``CVode`` (vector operations, error test, Newton bookkeeping);
- Python per output / per step: ``integrate`` and scikit-sundae's ``step`` outside ``CVode`` (result objects,
  copies, checks), by source line.

py-spy samples wall-clock stacks: on a loaded machine a descheduled process is still sampled, so the split is
a split of wall time that assumes descheduling hits every category alike.
"""

from __future__ import annotations

import argparse
import collections
import re
import time

CATEGORIES = [
    ("dataset assembly (to_dataset: outputs re-evaluated, xarray, analysis)", ("to_dataset", "annotate")),
    ("Jacobian (compiled arrowhead FD + copy into SUNMatrix)", ("DynamicModel.jac", "jac_kernel", "np2smat")),
    ("rhs: compiled kernel + numba dispatch", ("DynamicModel.rhs", "rhs_kernel")),
    ("rhs: scikit-sundae callback wrapper (ndarray views, Python call)", ("_rhsfn_wrapper",)),
    ("linear algebra: dense LU (GETRF)", ("denseGETRF", "DenseGETRF", "dgetrf")),
    ("linear algebra: back-solve (GETRS)", ("denseGETRS", "DenseGETRS", "dgetrs")),
    ("linear algebra: M = I - gamma J, copies", ("SUNMatCopy", "SUNMatScaleAddI", "SUNLinSol")),
    ("CVODE internals (vector ops, error test, Newton bookkeeping)", ("CVode (",)),
]


def timed_run(span: float, stepping: str) -> None:
    import hsbearing as h
    import hsbearing.solvers.cvode as cv
    from hsbearing.systems.angular_contact import dynamics as dy

    cv.integrate.__kwdefaults__["stepping"] = stepping  # simulate() calls cv.integrate with the defaults
    case = h.load_case("zhang2016")
    m = dy.build_model(case)
    h.simulate(case, duration=0.002, model=m)  # warm-up: compile / cache load of every specialisation
    t0, c0 = time.perf_counter(), time.process_time()
    ds = measured(h, case, span, m)
    print(f"simulate {span:g} s ({stepping}): wall {time.perf_counter() - t0:.2f} s, CPU {time.process_time() - c0:.2f} s; "
          f"steps {ds.attrs['solver_steps']}, rhs {ds.attrs['solver_rhs_evals']}, Jacobians {ds.attrs['solver_jac_evals']}")


def measured(h, case, span, m):
    """The sampled call (``split`` keeps the stacks through this frame)."""
    return h.simulate(case, duration=span, model=m)


def split(path: str, verbose: bool = False) -> None:
    cats: collections.Counter = collections.Counter()
    leaves: dict = collections.defaultdict(collections.Counter)
    total = 0
    for line in open(path):
        line = line.rstrip("\n")
        if "measured (" not in line or "simulate (hsbearing/systems/angular_contact/dynamics.py" not in line:
            continue
        stack, n = line.rsplit(" ", 1)
        n = int(n)
        total += n
        cat = None
        for name, keys in CATEGORIES:
            if any(k in stack for k in keys):
                cat = name
                break
        if cat is None:
            m2 = re.findall(r"\((hsbearing/solvers/cvode.py):(\d+)\)", stack)
            if m2:
                cat = f"Python per output/step: cvode.py line {m2[-1][1]} and below"
            else:
                cat = "other (simulate set-up)"
        cats[cat] += n
        leaves[cat][stack.split(";")[-1]] += n
    print(f"{total} samples in the timed simulate call")
    for name, n in cats.most_common():
        print(f"{100 * n / max(total, 1):5.1f} %  {name}")
        if verbose:
            for leaf, k in leaves[name].most_common(4):
                print(f"           {k:6d}  {leaf[:120]}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("--span", type=float, default=0.1)
    r.add_argument("--stepping", default="normal", choices=["normal", "onestep"])
    s = sub.add_parser("split")
    s.add_argument("path")
    s.add_argument("-v", "--verbose", action="store_true")
    a = ap.parse_args(argv)
    if a.cmd == "run":
        timed_run(a.span, a.stepping)
    else:
        split(a.path, a.verbose)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
