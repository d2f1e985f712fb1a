#!/usr/bin/python3
"""Two interfaces in one run report their results each under its own name (examples/two_planes.toml).

Usage: check_two_planes.py RUPTURE CASE WORKDIR -- [--set ...]
Runs CASE as given and with its two [interface] tables swapped in the file, then checks:
- run.json "cracks" holds one summary per interface, named, in input order; "crack" is the first;
- crack_tip_NAME.csv, crack_stretches_NAME.csv and rupture_time_NAME.csv exist for each, on the
  interface's own line (y), and crack_tip.csv is the first interface's;
- interface profiles: interface/NAME_*.csv for every interface, and interface/interface_*.csv
  for the first too (the same bytes);
- the impact below the lower plane cracks it (initiation near the reference 10.6 us at 1 mm)
  while the upper plane, 10 mm above, stays intact: the two summaries differ;
- swapping the tables changes the order of the reports, not their content.
"""
import csv
import json
import os
import re
import subprocess
import sys

rupture, case, work = sys.argv[1:4]
extra = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
ok = True


def check(cond, what):
    global ok
    print(("ok   " if cond else "FAIL ") + what)
    ok = ok and cond


def run(case_path, out):
    p = subprocess.run([rupture, "run", case_path, "-o", out, "--overwrite", "--quiet"] + extra,
                       capture_output=True, text=True)
    if p.returncode != 0:
        print(p.stdout, p.stderr)
        sys.exit(1)
    return json.load(open(os.path.join(out, "run.json")))


def rows(path):
    return list(csv.DictReader(open(path)))


os.makedirs(work, exist_ok=True)
text = open(case).read()
# The two [interface.*] tables, each up to the next table header that is not its own.
blocks = list(re.finditer(r"^\[interface\.(\w+)\]\n(?:(?!^\[).*\n|\n)*", text, re.M))
check(len(blocks) == 2, f"{len(blocks)} interface tables in {case}")
names = [b.group(1) for b in blocks]
swapped = text[:blocks[0].start()] + blocks[1].group(0) + blocks[0].group(0) + text[blocks[1].end():]
swapped_case = os.path.join(work, "swapped.toml")
open(swapped_case, "w").write(swapped)

d1, d2 = os.path.join(work, "as_given"), os.path.join(work, "swapped")
r1, r2 = run(case, d1), run(swapped_case, d2)
y_of = {n: json.load(open(os.path.join(d1, "run.json")))["input"]["interface"][n]["y"] for n in names}

check([c["interface"] for c in r1["cracks"]] == names, f"cracks in input order: {[c['interface'] for c in r1['cracks']]}")
check([c["interface"] for c in r2["cracks"]] == names[::-1],
      f"swapped input, cracks in its order: {[c['interface'] for c in r2['cracks']]}")
check(r1["crack"] == r1["cracks"][0], "crack = cracks[0]")
by_name = {c["interface"]: c for c in r1["cracks"]}
lower, upper = by_name["lower_plane"], by_name["upper_plane"]
check(lower["initiated"] and abs(lower["initiation_time"] - 10.6e-6) < 0.3e-6,
      f"lower plane initiates at {lower['initiation_time'] * 1e6:.3f} us (reference 10.6 us at 1 mm, +-0.3)")
check(not upper["initiated"] and upper["regime"] == "none" and upper["final_tip"] == 0.025,
      f"upper plane intact: initiated {upper['initiated']}, regime {upper['regime']}, tip {upper['final_tip']}")
for c in r2["cracks"]:
    same = all(c[k] == by_name[c["interface"]][k] for k in c)
    check(same, f"{c['interface']}: the same summary whatever the input order")

tip = {n: rows(os.path.join(d1, f"crack_tip_{n}.csv")) for n in names}
check(rows(os.path.join(d1, "crack_tip.csv")) == tip[names[0]], "crack_tip.csv is the first interface's")
for n in names:
    for f in (f"crack_stretches_{n}.csv", f"rupture_time_{n}.csv"):
        check(os.path.exists(os.path.join(d1, f)), f"{f} written")
    check(len(tip[n]) > 100 and all(abs(float(r["tip_y"]) - y_of[n]) < 1e-12 for r in tip[n]),
          f"crack_tip_{n}.csv: {len(tip[n])} samples, tip on y = {y_of[n]}")
    rt = rows(os.path.join(d1, f"rupture_time_{n}.csv"))
    cracked = sum(float(r["crack_time"]) >= 0 for r in rt)
    check(all(abs(float(r["y"]) - y_of[n]) < 1e-12 for r in rt), f"rupture_time_{n}.csv on y = {y_of[n]}, "
          f"{cracked} of {len(rt)} nodes cracked")
    check((cracked > 0) == by_name[n]["initiated"], f"{n}: cracked nodes agree with the summary")
    for prefix in (["interface", n] if n == names[0] else [n]):
        profiles = sorted(f for f in os.listdir(os.path.join(d1, "interface")) if re.fullmatch(prefix + r"_\d+\.csv", f))
        ys = {float(r["y"]) for r in rows(os.path.join(d1, "interface", profiles[-1]))} if profiles else set()
        check(len(profiles) > 0 and ys == {y_of[n]}, f"interface/{prefix}_*.csv: {len(profiles)} profiles on y = {ys}")
    if n == names[0]:
        same = all(open(os.path.join(d1, "interface", f"interface_{k}"), "rb").read() ==
                   open(os.path.join(d1, "interface", f"{n}_{k}"), "rb").read()
                   for k in (f.split("_")[-1] for f in os.listdir(os.path.join(d1, "interface"))
                             if f.startswith("interface_")))
        check(same, f"interface/interface_*.csv and interface/{n}_*.csv hold the same profiles")
check(tip[names[0]][-1]["tip_s"] != tip[names[1]][-1]["tip_s"], "the two tips differ at the end")
sys.exit(0 if ok else 1)
