#!/usr/bin/env python3
"""`rupture sweep`, end to end, on the reference problem cropped at 1 mm to 14 us.

usage: check_sweep.py RUPTURE CASE WORK_DIR -- RUN_ARGS...

1. A 2 x 3 sweep (impact speed 20, 30 m/s x strength 24, 30 MPa and an invalid 0) with -j 2:
   exit 1 (one value invalid), summary.csv has one row per combination with its values; the
   invalid ones say why and were not run; the others completed. Physics: the crack starts
   earlier under the faster impact at either strength, and later on the stronger plane at
   either speed.
2. The same sweep again: the completed runs are not run again (their outputs are untouched).
3. A run killed with SIGKILL after its first checkpoint: its row says failed (killed by signal
   9), and the sweep again resumes it from the checkpoint to completion.
4. `rupture plot DIR` on the sweep writes the map and the speed histories.
5. `rupture plot DIR --compare DIR2 --labels A B` draws one map of two sweeps; a directory that
   is not a sweep is refused with a message.
"""
import csv
import os
import shutil
import signal
import subprocess
import sys
import time

ok = True


def check(cond, what):
    global ok
    print(("ok   " if cond else "FAIL ") + what)
    ok = ok and cond


def pids_with(text):
    """Processes whose command line (NUL-separated) contains text (no pgrep on a bare system)."""
    found = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                if text.encode() in f.read():
                    found.append(pid)
        except OSError:
            pass
    return found


def rows(d):
    with open(os.path.join(d, "summary.csv")) as f:
        return list(csv.DictReader(f))


def main():
    rupture, case, work = sys.argv[1:4]
    run_args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    shutil.rmtree(work, ignore_errors=True)
    d = os.path.join(work, "grid")
    base = [rupture, "sweep", case, "-o", d, "--vary", "boundary.impact.velocity=20,30",
            "--vary", "interface.weak_plane.sigma_max=24e6,30e6,0", "-j", "2", "--threads", "2", "--quiet"]
    # --set key=value ... for every run; the sweep sets solver.threads itself.
    pairs = [run_args[i:i + 2] for i in range(0, len(run_args), 2)]
    for flag, value in pairs:
        if not value.startswith("solver.threads"):
            base += [flag, value]
    base += ["--set", "output.snapshot_interval=0", "--set", "output.interface_interval=0"]
    p = subprocess.run(base, capture_output=True, text=True)
    check(p.returncode == 1, f"sweep with an invalid value exits 1 (got {p.returncode})")
    r = rows(d)
    check(len(r) == 6, f"summary.csv: {len(r)} rows (6 combinations)")
    by = {(x["boundary.impact.velocity"], x["interface.weak_plane.sigma_max"]): x for x in r}
    for v in ("20", "30"):
        x = by[(v, "0")]
        check(x["status"] == "invalid" and "sigma_max" in x["message"] and not os.path.exists(
            os.path.join(d, x["run"], "run.json")), f"V = {v}, sigma_max = 0: invalid, not run ({x['message'][:60]}...)")
    done = [x for x in r if x["status"] == "completed"]
    check(len(done) == 4, f"{len(done)} runs completed")
    t = {k: float(x["initiation_time_s"]) for k, x in by.items() if x["status"] == "completed"}
    for s in ("24e6", "30e6"):
        check(t[("30", s)] < t[("20", s)], f"sigma_max {s}: initiation {t[('30', s)] * 1e6:.3f} us at 30 m/s "
              f"before {t[('20', s)] * 1e6:.3f} us at 20 m/s")
    for v in ("20", "30"):
        check(t[(v, "30e6")] > t[(v, "24e6")], f"V = {v} m/s: initiation {t[(v, '30e6')] * 1e6:.3f} us on the "
              f"30 MPa plane after {t[(v, '24e6')] * 1e6:.3f} us on 24 MPa")

    # 2. Again: nothing completed is run again.
    stamps = {x["run"]: os.path.getmtime(os.path.join(d, x["run"], "rupture.out")) for x in done}
    p = subprocess.run(base, capture_output=True, text=True)
    again = {x["run"]: os.path.getmtime(os.path.join(d, x["run"], "rupture.out")) for x in done}
    check(p.returncode == 1 and stamps == again, "a second sweep leaves the completed runs alone")

    # 3. A run killed after its first checkpoint fails alone, and the next sweep resumes it.
    k = os.path.join(work, "killed")
    one = [rupture, "sweep", case, "-o", k, "--vary", "boundary.impact.velocity=30", "--threads", "1",
           "--checkpoint-interval", "2e-6", "--quiet"] + base[base.index("--quiet") + 1:]
    proc = subprocess.Popen(one, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    run_dir = os.path.join(k, "velocity_30")
    deadline = time.time() + 60
    while time.time() < deadline and not os.path.exists(os.path.join(run_dir, "checkpoint", "checkpoint.bin")):
        time.sleep(0.02)
    child = pids_with(f"{run_dir}\0--overwrite")
    check(len(child) == 1, f"the run is found to kill ({len(child)} process)")
    for pid in child:
        os.kill(int(pid), signal.SIGKILL)
    out, err = proc.communicate(timeout=60)
    row = rows(k)[0]
    check(proc.returncode == 1 and row["status"] == "failed" and "signal 9" in row["message"],
          f"killed run: sweep exit {proc.returncode}, status {row['status']}: {row['message'][:50]}")
    p = subprocess.run(one, capture_output=True, text=True)
    row = rows(k)[0]
    with open(os.path.join(run_dir, "rupture.out")) as f:
        resumed = "resuming run in" in f.read()
    check(p.returncode == 0 and row["status"] == "completed" and resumed,
          f"the next sweep resumed it from its checkpoint: exit {p.returncode}, status {row['status']}")
    # 4. The figures of a sweep.
    p = subprocess.run([rupture, "plot", d], capture_output=True, text=True)
    figs = [os.path.join(d, "figures", f) for f in ("sweep_map.png", "sweep_histories.png")]
    check(p.returncode == 0 and all(os.path.getsize(f) > 10000 for f in figs if os.path.exists(f))
          and all(map(os.path.exists, figs)), f"rupture plot on the sweep: exit {p.returncode}, "
          f"{sum(map(os.path.exists, figs))} of 2 figures {p.stderr[-200:]}")
    # 5. One map of two sweeps (the paper's map on two meshes): both are read, labelled.
    p = subprocess.run([rupture, "plot", d, "--compare", k, "--labels", "coarse", "fine"],
                       capture_output=True, text=True)
    check(p.returncode == 0 and "sweep_map.png" in p.stdout,
          f"rupture plot on two sweeps: exit {p.returncode} {p.stderr[-200:]}")
    p = subprocess.run([rupture, "plot", d, "--compare", os.path.join(d, "figures")],
                       capture_output=True, text=True)
    check(p.returncode != 0 and "not a rupture sweep directory" in p.stderr,
          f"rupture plot on a sweep and a non-sweep fails with a message: exit {p.returncode}")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
