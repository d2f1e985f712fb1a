#!/usr/bin/python3
"""Same answers: a fixed set of short runs gives the outputs recorded before a refactoring.

The set covers every shape the time step takes: one uniform grid (MUSL, USL, USF), the graded
grid, nested levels (MUSL, USL, per-level steps), distributed runs on 2 and 3 ranks, a
slip-weakening fault with absorbing edges and stations, [loads] velocity regions, and a run
stopped and resumed from its checkpoint (compared with the uninterrupted run's files); and the
2D fracture and fault features: cracks that grow (Kalthoff-Winkler, the inclined centre crack
kinking), branch (the branching plate), read K and J over time (the centre crack), follow ties
into a bond (a crack growing into a bonded interface), and a rate-and-state fault (TPV101-2D,
coarse). For each run the written crack_tip*.csv, crack_path_*.csv, stress_intensity_*.csv,
rupture_time_*.csv, history.csv and station files are compared with the recorded ones in
tests/data/same_answers/<run>/ (gzip).

Bound (stated once): the files print 10 significant digits. Two values agree when they are the
same text, or differ by at most 1e-12 of their column's largest magnitude in the reference
(a column such as cohesive_dissipated is round-off, 1e-18, beside its later 0.18 J/m, until the
crack opens; a sum's order changes only that round-off), or by one unit of the tenth
significant digit (a change of 1e-12 can move a value across a rounding boundary of the
printing). Anything else is a difference, printed with its file, row, column and both values.
The references were recorded on the machine and compiler named in tests/data/same_answers/
machine.json; on another CPU vendor or compiler (other vector widths and libm paths give other
round-off) the bound is 1e-9 of the column's largest magnitude, and the script says so.

  same_answers.py record RUPTURE MPIEXEC WORKDIR           run all, write the references
  same_answers.py check  RUPTURE MPIEXEC WORKDIR RUN...    run these, compare (exit 1 on a difference)
"""
import csv
import gzip
import io
import json
import math
import os
import platform
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DATA = os.path.join(ROOT, "tests", "data", "same_answers")
EX = os.path.join(ROOT, "examples")

# The reference problem cropped (as the benchmark tests), without snapshots or profiles.
CROP = ["--set", "grid.min=[0.0,-0.06]", "--set", "grid.max=[0.075,0.04]",
        "--set", "bodies.upper.max=[0.075,0.04]", "--set", "bodies.lower.min=[0.0,-0.06]",
        "--set", "bodies.lower.max=[0.075,0.0]", "--set", "interface.weak_plane.bonded_to=0.075",
        "--set", "output.snapshot_interval=0", "--set", "output.interface_interval=0"]
ROSAKIS = [os.path.join(EX, "rosakis1999.toml")] + CROP
UNIFORM = ROSAKIS + ["--set", "grid.coarse_cell_size=0", "--set", "grid.cell_size=1e-3",
                     "--set", "time.end=13e-6"]
# Each realization named, and the example's boxes as they were recorded: refined grids default
# to nested levels with per-level steps where verified (input/case_toml.cpp set_default_subcycling),
# and the example's level-2 box now reaches down the impacted edge; these references predate both.
BOXES = ["--set", "grid.cell_size=0.5e-3", "--set", "time.end=11e-6", "--set", "grid.refine.level2.min=[0.0,-0.03]"]
REFINED = ROSAKIS + BOXES + ["--set", 'grid.refinement="graded"']
NESTED = ROSAKIS + BOXES + ["--set", 'grid.refinement="nested"', "--set", 'time.subcycling="none"']
FAULT = [os.path.join(EX, "tpv205_2d.toml"), "--set", "grid.cell_size=400",
         "--set", "interface.fault.segments=100", "--set", "time.end=3"]
LOADS = [os.path.join(ROOT, "tests", "inputs", "velocity_regions.toml")]
# The fracture runs (whole examples of a few seconds, no snapshots or profiles).
QUIET = ["--set", "output.snapshot_interval=0", "--set", "output.interface_interval=0"]
KALTHOFF = [os.path.join(EX, "kalthoff_winkler.toml")] + QUIET
BRANCHING = [os.path.join(EX, "dynamic_branching.toml")] + QUIET
CENTRE = [os.path.join(EX, "centre_crack_tension.toml"), "--set", "time.end=300e-6"] + QUIET
# The inclined centre crack (30 degrees) kinking by max_hoop (as e2e_mpi_growth_kink).
KINK = [os.path.join(EX, "centre_crack_tension.toml"),
        "--set", "interface.crack.points=[[-0.008660254037844387,-0.0049],[0.008660254037844387,0.0051]]",
        "--set", 'interface.crack.growth="max_hoop"', "--set", "interface.crack.toughness=935738.96",
        "--set", "loads.top.rise_time=150e-6", "--set", "loads.bottom.rise_time=150e-6",
        "--set", "time.end=115e-6", "--set", "output.crack_sample_interval=5e-6"] + QUIET
TIES = [os.path.join(EX, "crack_into_bond.toml")] + QUIET
RATE_STATE = [os.path.join(EX, "tpv101_2d.toml"), "--set", "grid.cell_size=400", "--set", "time.end=4"] + QUIET

# name: (case arguments, ranks, how: "run" or "resume" (stopped after 100 steps, resumed),
#        the run whose references it is compared with)
RUNS = {
    "uniform_musl": (UNIFORM, 1, "run", None),
    "uniform_usl": (UNIFORM + ["--set", 'solver.scheme="USL"', "--set", "time.end=11e-6"], 1, "run", None),
    "uniform_usf": (UNIFORM + ["--set", 'solver.scheme="USF"', "--set", "time.end=11e-6"], 1, "run", None),
    "graded": (REFINED, 1, "run", None),
    "nested": (NESTED, 1, "run", None),
    "nested_usl": (NESTED + ["--set", 'solver.scheme="USL"'], 1, "run", None),
    "nested_subcycled": (NESTED[:-2] + ["--set", 'time.subcycling="levels"'], 1, "run", None),
    "mpi2_nested": (NESTED, 2, "run", None),
    "mpi3_uniform": (UNIFORM, 3, "run", None),
    "fault": (FAULT, 1, "run", None),
    "loads": (LOADS, 1, "run", None),
    "resumed": (UNIFORM, 1, "resume", "uniform_musl"),
    "growth_kalthoff": (KALTHOFF, 1, "run", None),
    "growth_branching": (BRANCHING, 1, "run", None),
    "centre_crack_k": (CENTRE, 1, "run", None),
    "growth_kink": (KINK, 1, "run", None),
    "ties_into_bond": (TIES, 1, "run", None),
    "rate_state": (RATE_STATE, 1, "run", None),
}


def outputs(run_dir):
    """The compared files of a run directory, relative paths."""
    prefixes = ("crack_tip", "crack_path_", "stress_intensity_", "rupture_time_")
    names = sorted(f for f in os.listdir(run_dir) if f.endswith(".csv") and f.startswith(prefixes))
    names += [f for f in ("history.csv",) if os.path.exists(os.path.join(run_dir, f))]
    st = os.path.join(run_dir, "stations")
    if os.path.isdir(st):
        names += sorted(os.path.join("stations", f) for f in os.listdir(st) if f.endswith(".csv"))
    return names


def machine():
    vendor = ""
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("vendor_id"):
                vendor = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return {"cpu_vendor": vendor, "machine": platform.machine()}


def execute(rupture, mpiexec, work, name):
    args, ranks, how, _ = RUNS[name]
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    prefix = [] if ranks == 1 else [mpiexec, "--oversubscribe", "-n", str(ranks)]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    first = prefix + [rupture, "run", args[0], "-o", out, "--quiet"] + args[1:]
    if how == "resume":
        first += ["--stop-after-steps", "100"]
    r = subprocess.run(first, env=env, capture_output=True, text=True)
    expected = 4 if how == "resume" else 0
    if r.returncode != expected:
        sys.exit(f"{name}: {' '.join(first)} exited {r.returncode} (expected {expected}):\n{r.stderr[-3000:]}")
    if how == "resume":
        again = prefix + [rupture, "resume", out, "--quiet"]
        r = subprocess.run(again, env=env, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"{name}: {' '.join(again)} exited {r.returncode}:\n{r.stderr[-3000:]}")
    return out


def read_rows(text):
    return list(csv.reader(io.StringIO(text)))


def last_digit_apart(a, b, sa, sb):
    """Whether two printed values differ by one unit of their last printed digit."""
    if "e" not in sa.lower() or "e" not in sb.lower():
        return False
    ma, ea = sa.lower().split("e")
    mb, eb = sb.lower().split("e")
    if ea != eb:
        return abs(a - b) <= 1.5 * 10.0 ** (int(ea) - len(ma.split(".")[-1]))
    unit = 10.0 ** (int(ea) - len(ma.split(".")[-1]))
    return abs(a - b) <= 1.5 * unit


def compare_file(label, ref_text, new_text, strict):
    ref, new = read_rows(ref_text), read_rows(new_text)
    problems = []
    if len(ref) != len(new):
        problems.append(f"{label}: {len(new)} rows, the reference has {len(ref)}")
    if ref and new and ref[0] != new[0]:
        problems.append(f"{label}: header {new[0]} differs from the reference's {ref[0]}")
        return problems, 0, 0
    columns = len(ref[0]) if ref else 0
    scale = [0.0] * columns
    for row in ref[1:]:
        for c, v in enumerate(row[:columns]):
            try:
                x = float(v)
                if math.isfinite(x):
                    scale[c] = max(scale[c], abs(x))
            except ValueError:
                pass
    same = flips = 0
    for i, (ra, rb) in enumerate(zip(ref[1:], new[1:]), start=2):
        if len(ra) != len(rb):
            problems.append(f"{label}: row {i} has {len(rb)} fields, the reference {len(ra)}")
            continue
        for c, (sa, sb) in enumerate(zip(ra, rb)):
            if sa == sb:
                same += 1
                continue
            try:
                a, b = float(sa), float(sb)
            except ValueError:
                problems.append(f"{label}: row {i}, {ref[0][c]}: '{sb}' vs reference '{sa}'")
                continue
            if strict:
                ok = abs(a - b) <= 1e-12 * scale[c] or last_digit_apart(a, b, sa, sb)
            else:
                ok = abs(a - b) <= 1e-9 * scale[c]
            if ok:
                flips += 1
            else:
                problems.append(f"{label}: row {i}, column {ref[0][c]}: {sb} vs reference {sa} "
                                f"(difference {abs(a - b):.3g}, column's largest {scale[c]:.3g})")
    return problems, same, flips


def record(rupture, mpiexec, work):
    os.makedirs(DATA, exist_ok=True)
    for name, (_, _, _, against) in RUNS.items():
        out = execute(rupture, mpiexec, work, name)
        if against:
            continue
        dest = os.path.join(DATA, name)
        shutil.rmtree(dest, ignore_errors=True)
        for f in outputs(out):
            os.makedirs(os.path.dirname(os.path.join(dest, f)), exist_ok=True)
            with open(os.path.join(out, f), "rb") as src, gzip.open(os.path.join(dest, f + ".gz"), "wb", 9) as dst:
                dst.write(src.read())
        print(f"{name}: recorded {', '.join(outputs(out))}")
    with open(os.path.join(DATA, "machine.json"), "w") as f:
        json.dump(machine(), f, indent=1)


def check(rupture, mpiexec, work, names):
    recorded = json.load(open(os.path.join(DATA, "machine.json")))
    strict = recorded == machine()
    if not strict:
        print(f"references recorded on {recorded}, this is {machine()}: bound 1e-9 of each column's largest value")
    failed = False
    for name in names:
        out = execute(rupture, mpiexec, work, name)
        ref_dir = os.path.join(DATA, RUNS[name][3] or name)
        ref_files = sorted(os.path.relpath(os.path.join(d, f), ref_dir)[:-3]
                           for d, _, fs in os.walk(ref_dir) for f in fs if f.endswith(".gz"))
        if sorted(outputs(out)) != ref_files:
            print(f"{name}: wrote {sorted(outputs(out))}, the references are {ref_files}")
            failed = True
        for f in ref_files:
            if not os.path.exists(os.path.join(out, f)):
                continue
            with gzip.open(os.path.join(ref_dir, f + ".gz"), "rt") as g:
                ref_text = g.read()
            problems, same, flips = compare_file(f"{name}/{f}", ref_text, open(os.path.join(out, f)).read(), strict)
            print(f"{name}/{f}: {same} values identical, {flips} within the bound, {len(problems)} differences")
            for p in problems[:10]:
                print("  " + p)
            failed = failed or bool(problems)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    if len(sys.argv) < 5 or sys.argv[1] not in ("record", "check"):
        sys.exit(__doc__)
    rupture, mpiexec, work = sys.argv[2:5]
    if sys.argv[1] == "record":
        record(rupture, mpiexec, work)
    else:
        check(rupture, mpiexec, work, sys.argv[5:] or list(RUNS))
