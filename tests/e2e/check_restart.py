#!/usr/bin/env python3
"""Durable runs, end to end (the rupture CLI on a small cohesive case).

usage: check_restart.py RUPTURE CASE REF_DIR WORK_DIR MODE -- RUN_ARGS...

REF_DIR holds an uninterrupted run of CASE with RUN_ARGS. MODE:
  stop       run with --stop-after-steps (as if interrupted), exit 4, then `rupture resume`
  sigterm    SIGTERM once a checkpoint exists: exit 4, message, status "interrupted"; resume
  sigint     SIGINT (Ctrl-C) on a run with no checkpoint interval, once it has taken steps:
             it stops within 30 s with exit 4 and a checkpoint (it once spun forever); resume
  kill9      kill -9 once a checkpoint exists: run.json still "running"; resume
  overwrite  a used directory is refused (exit 1) unless --overwrite, which keeps user files
  full_disk  a 12 MB tmpfs fills up: exit 3, "No space left on device", run.json not "running",
             history.csv and crack_tip.csv written
  foreign    another run's checkpoint copied in is refused (exit 1, both run ids named, nothing
             changed); its own back with a snapshot file deleted: resumed, the index drops it
             (skipped, exit 77, where a tmpfs cannot be mounted)
A resumed run must equal the reference bitwise: history.csv, crack_tip.csv,
crack_stretches.csv, particles.xdmf, interface/*.csv byte for byte, every snapshot's datasets
and attributes bit for bit.
"""
import glob
import json
import os
import shutil
import signal
import subprocess
import sys
import time

import h5py
import numpy as np

SKIP = 77


def fail(msg):
    print(f"FAIL: {msg}")
    sys.exit(1)


def run(args, expect_rc, what):
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != expect_rc:
        fail(f"{what}: exit code {p.returncode}, expected {expect_rc}\n"
             f"stdout:\n{p.stdout[-2000:]}\nstderr:\n{p.stderr[-2000:]}")
    return p


def run_json(d):
    with open(os.path.join(d, "run.json")) as f:
        return json.load(f)


def same_bytes(a, b):
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


def compare_runs(ref, d):
    """Every output of d equals ref's bitwise; returns a one-line summary."""
    n = 0
    for name in ["history.csv", "crack_tip.csv", "crack_stretches.csv", "particles.xdmf"]:
        if not same_bytes(os.path.join(ref, name), os.path.join(d, name)):
            fail(f"{d}/{name} differs from {ref}/{name}")
        n += 1
    for pattern in ["interface/*.csv", "snapshots/*.h5"]:
        rf = sorted(os.path.relpath(p, ref) for p in glob.glob(os.path.join(ref, pattern)))
        df = sorted(os.path.relpath(p, d) for p in glob.glob(os.path.join(d, pattern)))
        if rf != df or not rf:
            fail(f"{pattern}: {len(df)} files in {d}, {len(rf)} in {ref}")
        for rel in rf:
            if rel.endswith(".csv"):
                if not same_bytes(os.path.join(ref, rel), os.path.join(d, rel)):
                    fail(f"{d}/{rel} differs")
                n += 1
                continue
            # HDF5 files carry creation times; compare what they hold, bit for bit.
            with h5py.File(os.path.join(ref, rel)) as a, h5py.File(os.path.join(d, rel)) as b:
                if sorted(a.keys()) != sorted(b.keys()):
                    fail(f"{rel}: datasets {sorted(b.keys())} vs {sorted(a.keys())}")
                for k in a.keys():
                    x, y = a[k][()], b[k][()]
                    if x.shape != y.shape or x.tobytes() != y.tobytes():
                        diff = np.max(np.abs(x.astype(float) - y.astype(float))) if x.shape == y.shape else "shape"
                        fail(f"{d}/{rel}:{k} differs from the reference (max |diff| {diff})")
                for k in a.attrs:
                    if np.asarray(a.attrs[k]).tobytes() != np.asarray(b.attrs[k]).tobytes():
                        fail(f"{d}/{rel} attribute {k}: {b.attrs[k]} vs {a.attrs[k]}")
            n += 1
    last = sorted(glob.glob(os.path.join(d, "snapshots/*.h5")))[-1]
    return f"{n} files bitwise equal to the reference (final snapshot {os.path.basename(last)})"


def wait_for(path, proc, timeout=120):
    t0 = time.time()
    while not os.path.exists(path):
        if proc.poll() is not None:
            fail(f"run ended (exit {proc.returncode}) before {path} appeared")
        if time.time() - t0 > timeout:
            proc.kill()
            fail(f"{path} did not appear in {timeout} s")
        time.sleep(0.02)


def resume_and_compare(rupture, ref, d, segments):
    p = run([rupture, "resume", d, "--quiet"], 0, f"rupture resume {d}")
    if "status=completed" not in p.stdout:
        fail(f"resume did not complete:\n{p.stdout}")
    j = run_json(d)
    if j["status"] != "completed" or j["segments"] != segments:
        fail(f"run.json after resume: status {j['status']}, segments {j['segments']}")
    print(f"{d}: resumed; {compare_runs(ref, d)}")


def main():
    rupture, case, ref, work, mode = sys.argv[1:6]
    assert sys.argv[6] == "--"
    args = sys.argv[7:]
    os.makedirs(work, exist_ok=True)
    d = os.path.join(work, mode)
    shutil.rmtree(d, ignore_errors=True)
    base = [rupture, "run", case, "-o", d, "--quiet"] + args

    if mode == "stop":
        p = run(base + ["--checkpoint-interval", "3e-6", "--stop-after-steps", "160"], 4,
                "run stopped after 160 steps")
        if f"resume with: rupture resume {d}" not in p.stderr or "status=interrupted" not in p.stdout:
            fail(f"no resume hint / status line:\n{p.stdout}\n{p.stderr}")
        j = run_json(d)
        # Per-level time steps stop at the first step >= 160 where every level ends its step
        # together (a checkpoint holds every particle at one time): within the coarsest period.
        subcycled = any('time.subcycling="levels"' in a for a in args)
        steps_ok = 160 <= j["steps"] < 160 + 64 if subcycled else j["steps"] == 160
        if j["status"] != "interrupted" or j["stop_reason"] != "interrupted" or not steps_ok:
            fail(f"run.json: {j['status']}, {j['stop_reason']}, steps {j['steps']}")
        resume_and_compare(rupture, ref, d, 2)

    elif mode == "sigterm":
        proc = subprocess.Popen(base + ["--checkpoint-interval", "2e-6"], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True)
        wait_for(os.path.join(d, "checkpoint", "checkpoint.bin"), proc)
        proc.send_signal(signal.SIGTERM)
        out, err = proc.communicate(timeout=120)
        if proc.returncode != 4:
            fail(f"SIGTERM: exit code {proc.returncode}, expected 4\n{out}\n{err}")
        if "interrupted by signal 15 at step" not in err or f"resume with: rupture resume {d}" not in err:
            fail(f"SIGTERM message:\n{err}")
        j = run_json(d)
        if j["status"] != "interrupted" or j["checkpoint_step"] != j["steps"]:
            fail(f"run.json after SIGTERM: status {j['status']}, checkpoint_step "
                 f"{j['checkpoint_step']}, steps {j['steps']}")
        print(f"SIGTERM at step {j['steps']}: exit 4, status interrupted, checkpoint written")
        resume_and_compare(rupture, ref, d, 2)

    elif mode == "sigint":
        proc = subprocess.Popen(base, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        # history.csv is first written inside the time loop (at the first snapshot, 2 of the
        # 14 us): the run has taken steps, and the whole run lasts about a second, so the signal
        # goes at once (a longer wait let the run end first on a fast machine).
        wait_for(os.path.join(d, "history.csv"), proc)
        time.sleep(0.05)
        proc.send_signal(signal.SIGINT)
        try:
            out, err = proc.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            proc.kill()
            fail("SIGINT without a checkpoint interval: the run did not stop within 30 s")
        if proc.returncode != 4 or "interrupted by signal 2 at step" not in err:
            fail(f"SIGINT: exit code {proc.returncode}, expected 4\n{out}\n{err}")
        j = run_json(d)
        if j["status"] != "interrupted" or j["checkpoint_step"] != j["steps"]:
            fail(f"run.json after SIGINT: status {j['status']}, checkpoint_step {j['checkpoint_step']}")
        print(f"SIGINT at step {j['steps']} (no checkpoint interval): exit 4, checkpoint written")
        resume_and_compare(rupture, ref, d, 2)

    elif mode == "kill9":
        proc = subprocess.Popen(base + ["--checkpoint-interval", "2e-6"], stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL)
        wait_for(os.path.join(d, "checkpoint", "checkpoint.bin"), proc)
        time.sleep(0.5)
        proc.kill()
        proc.wait()
        if proc.returncode != -signal.SIGKILL:
            fail(f"the run ended by itself (exit {proc.returncode}) before kill -9")
        j = run_json(d)
        if j["status"] != "running" or abs(time.time() - j["heartbeat_unix"]) > 60:
            fail(f"run.json after kill -9: status {j['status']}, heartbeat {j['heartbeat']}")
        print(f"kill -9: run.json says running, heartbeat {j['heartbeat']}")
        resume_and_compare(rupture, ref, d, 2)

    elif mode == "overwrite":
        before = os.stat(os.path.join(ref, "run.json")).st_mtime_ns
        p = run([rupture, "run", case, "-o", ref, "--quiet"] + args, 1, "run into a used directory")
        if "--overwrite" not in p.stderr or ref not in p.stderr:
            fail(f"refusal message:\n{p.stderr}")
        if os.stat(os.path.join(ref, "run.json")).st_mtime_ns != before:
            fail("the refused run touched the directory")
        shutil.copytree(ref, d)
        with open(os.path.join(d, "notes.txt"), "w") as f:
            f.write("mine\n")
        run(base + ["--overwrite", "--set", "time.end=1e-6"], 0, "run with --overwrite")
        snaps = glob.glob(os.path.join(d, "snapshots", "*.h5"))
        if not os.path.exists(os.path.join(d, "notes.txt")) or len(snaps) != 2:
            fail(f"--overwrite: notes.txt kept? {os.path.exists(os.path.join(d, 'notes.txt'))}, "
                 f"{len(snaps)} snapshots (expected 2, t = 0 and the end: the old run's are gone)")
        print(f"refused without --overwrite (exit 1); --overwrite cleared the old run, kept notes.txt")

    elif mode == "full_disk":
        os.makedirs(d)
        if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=12m", "tmpfs", d],
                          capture_output=True).returncode != 0:
            print(f"SKIP: cannot mount a 12 MB tmpfs on {d} (needs root)")
            sys.exit(SKIP)
        try:
            out = os.path.join(d, "run")
            p = run([rupture, "run", case, "-o", out, "--quiet"] + args, 3, "run on a full disk")
            if "No space left on device" not in p.stderr:
                fail(f"message without the reason:\n{p.stderr}")
            j = run_json(out)
            if j["status"] != "failed" or j["stop_reason"] != "io_error" or "No space" not in j["message"]:
                fail(f"run.json: status {j['status']}, stop_reason {j['stop_reason']}")
            left = [p for p in glob.glob(os.path.join(out, "**", "*.tmp"), recursive=True)]
            if left:
                fail(f"incomplete files left: {left}")
            # The small files that say what happened come before the large ones.
            with open(os.path.join(out, "history.csv")) as f:
                rows = sum(1 for _ in f) - 1
            if rows < 2 or not os.path.exists(os.path.join(out, "crack_tip.csv")):
                fail(f"history.csv has {rows} rows after {j['steps']} steps (crack_tip.csv: "
                     f"{os.path.exists(os.path.join(out, 'crack_tip.csv'))})")
            print(f"full disk: exit 3, {p.stderr.strip()}; run.json status failed (io_error)")
        finally:
            subprocess.run(["umount", d])
    elif mode == "foreign":
        # Another run's checkpoint copied into this run's directory is refused (run_id).
        other = d + "_other"
        shutil.rmtree(other, ignore_errors=True)
        stop = ["--checkpoint-interval", "3e-6", "--stop-after-steps", "160"]
        run(base + stop, 4, "run stopped after 160 steps")
        run([rupture, "run", case, "-o", other, "--quiet"] + args + stop, 4, "the other run")
        mine = os.path.join(d, "checkpoint", "checkpoint.bin")
        shutil.copy(mine, mine + ".mine")
        shutil.copy(os.path.join(other, "checkpoint", "checkpoint.bin"), mine)
        history = open(os.path.join(d, "history.csv")).read()
        p = run([rupture, "resume", d, "--quiet"], 1, "resume from another run's checkpoint")
        if "belongs to run" not in p.stderr or run_json(d)["run_id"] not in p.stderr:
            fail(f"message:\n{p.stderr}")
        if open(os.path.join(d, "history.csv")).read() != history:
            fail("the refused resume changed history.csv")
        print(f"foreign checkpoint refused: {p.stderr.strip()[:160]}")
        # Its own checkpoint back, one snapshot file deleted by hand: the index drops it.
        shutil.move(mine + ".mine", mine)
        snaps = sorted(glob.glob(os.path.join(d, "snapshots", "*.h5")))
        if len(snaps) < 2:
            fail(f"{len(snaps)} snapshots before the resume")
        gone = os.path.basename(snaps[1])
        os.remove(snaps[1])
        p = run([rupture, "resume", d, "--quiet"], 0, "resume after a snapshot was deleted")
        if "missing" not in p.stderr or gone not in p.stderr:
            fail(f"no warning naming {gone}:\n{p.stderr}")
        xdmf = open(os.path.join(d, "particles.xdmf")).read()
        for f in glob.glob(os.path.join(d, "snapshots", "*.h5")):
            if os.path.basename(f) not in xdmf:
                fail(f"particles.xdmf does not name {f}")
        if gone in xdmf:
            fail(f"particles.xdmf still names the deleted {gone}")
        print(f"deleted {gone}: warned, left out of particles.xdmf")
    else:
        fail(f"unknown mode {mode}")
    print("OK")


if __name__ == "__main__":
    main()
