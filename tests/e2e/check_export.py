#!/usr/bin/python3
"""`rupture export RUN --format scec` against the format's description (the SCEC/USGS
code-verification uploads; python/rupture_export.py): every station of the case gets
RUN/scec/NAME.txt with the header lines in the format's order (# problem=, # author=, # date=,
# code=, # code_version=, # element_size=, # time_step=, # num_time_steps=, # location=, the
# Column #k lines), the field-name line, and one row per sample of the station's CSV whose
numbers are that CSV's (slip, slip rate, shear and normal traction in MPa; body: ux, vx, uy, vy)
to the 7 digits of E15.7 (a rate-and-state fault adds psi, the state column, as the ninth);
the rupture-time contour file has the j k t line and one row per
node, 1e9 where the node never ruptured. Nothing is written outside RUN/scec/.
Usage: check_export.py RUPTURE RUN [PROBLEM]"""
import csv
import os
import subprocess
import sys

rupture, run = sys.argv[1], sys.argv[2]
problem = sys.argv[3] if len(sys.argv) > 3 else "TEST"
before = {os.path.join(d, f) for d, _, fs in os.walk(run) for f in fs}
out = subprocess.run([rupture, "export", run, "--format", "scec", "--problem", problem, "--author", "ci"],
                     capture_output=True, text=True)
print(out.stdout, out.stderr)
assert out.returncode == 0
after = {os.path.join(d, f) for d, _, fs in os.walk(run) for f in fs}
new = after - before
assert all(os.path.dirname(p) == os.path.join(run, "scec") for p in new), new


def columns(path):
    rows = list(csv.reader(open(path)))
    return {k: [float(r[i]) for r in rows[1:]] for i, k in enumerate(rows[0])}


def n_cols_text(text):
    return [l for l in text if l.startswith("# Column #")]


def close(a, b, scale):
    return abs(a - b) <= 1e-6 * max(abs(b), scale)


keys = ["problem", "author", "date", "code", "code_version", "element_size", "time_step",
        "num_time_steps", "location"]
stations = sorted(f[:-4] for f in os.listdir(os.path.join(run, "stations")) if f.endswith(".csv"))
assert stations
for name in stations:
    text = open(os.path.join(run, "scec", name + ".txt")).read().splitlines()
    head = [l for l in text if l.startswith("# ") and "=" in l and not l.startswith("# Column")]
    assert [l[2:].split("=")[0] for l in head] == keys, head
    assert head[0] == f"# problem={problem}" and head[1] == "# author=ci" and head[3] == "# code=rupture"
    c = columns(os.path.join(run, "stations", name + ".csv"))
    fault = "slip" in c
    names = ("t h-slip h-slip-rate h-shear-stress v-slip v-slip-rate v-shear-stress n-stress" if fault
             else "t h-disp h-vel v-disp v-vel n-disp n-vel").split()
    if "state" in c:
        names.append("psi")
        assert n_cols_text(text)[-1] == "# Column #9 = state variable psi (dimensionless)"
    n_cols = [l for l in text if l.startswith("# Column #")]
    assert len(n_cols) == len(names), n_cols
    at = text.index(" ".join(names))
    data = [list(map(float, l.split())) for l in text[at + 1:] if not l.startswith("#")]
    assert int(head[7].split("=")[1]) == len(data) == len(c["time"])
    want = ([(c["slip"], 1), (c["slip_rate"], 2), ([v / 1e6 for v in c["shear_traction"]], 3),
             ([v / 1e6 for v in c["normal_traction"]], 7)] if fault else
            [(c["ux"], 1), (c["vx"], 2), (c["uy"], 5), (c["vy"], 6)])
    if "state" in c:
        want.append((c["state"], 8))
    for k, row in enumerate(data):
        assert len(row) == len(names)
        assert close(row[0], c["time"][k], 1e-300)
        for series, col in want:
            scale = max(abs(v) for v in series) * 1e-9 + 1e-300
            assert close(row[col], series[k], scale), (name, k, col, row[col], series[k])
        zero = (4, 5, 6) if fault else (3, 4)
        assert all(row[j] == 0.0 for j in zero)
    print(f"{name}.txt: {len(data)} rows, {'fault' if fault else 'body'} station"
          f"{' with psi' if 'state' in c else ''}, numbers as in the CSV")
profiles = sorted(f for f in os.listdir(run) if f.startswith("rupture_time_") and f.endswith(".csv"))
for prof in profiles:
    iface = prof[len("rupture_time_"):-4]
    cplot = os.path.join(run, "scec", "cplot.txt" if len(profiles) == 1 else f"cplot_{iface}.txt")
    if not os.path.exists(cplot):  # a fault without stations is not exported
        continue
    text = open(cplot).read().splitlines()
    at = text.index("j k t")
    data = [list(map(float, l.split())) for l in text[at + 1:] if not l.startswith("#")]
    c = columns(os.path.join(run, prof))
    assert len(data) == len(c["x"])
    never = 0
    for row, x, tr in zip(data, c["x"], c["rupture_time"]):
        assert close(row[0], x, 1e-9) and row[1] == 0.0
        assert (row[2] == 1e9) if tr < 0 else close(row[2], tr, 1e-300)
        never += tr < 0
    print(f"{os.path.basename(cplot)}: {len(data)} nodes, {never} never ruptured (t = 1e9)")
print("export: ok")
