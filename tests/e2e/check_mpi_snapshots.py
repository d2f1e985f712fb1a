#!/usr/bin/env python3
"""A distributed run's snapshots (parallel HDF5) hold what one process writes, row by row.

Usage: check_mpi_snapshots.py SERIAL_DIR DISTRIBUTED_DIR BOUND
Every snapshot file: the same datasets and shapes; id, body, connectivity equal; position,
velocity and stresses equal to BOUND relative to each dataset's largest magnitude; the same
time and step attributes; particles.xdmf identical.
"""
import sys

import h5py
import numpy as np

a_dir, b_dir, bound = sys.argv[1], sys.argv[2], float(sys.argv[3])
ok = True


def check(cond, what):
    global ok
    print(("ok   " if cond else "FAIL ") + what)
    ok = ok and cond


xa, xb = open(f"{a_dir}/particles.xdmf").read(), open(f"{b_dir}/particles.xdmf").read()
check(xa == xb, "particles.xdmf identical")
files = sorted(set(l.split(">")[1].split(":")[0] for l in xa.splitlines() if "Format=\"HDF\"" in l))
check(len(files) >= 2, f"{len(files)} snapshot files")
for f in files:
    with h5py.File(f"{a_dir}/{f}", "r") as A, h5py.File(f"{b_dir}/{f}", "r") as B:
        check(sorted(A.keys()) == sorted(B.keys()), f"{f}: datasets {sorted(B.keys())}")
        check(A.attrs["time"] == B.attrs["time"] and A.attrs["step"] == B.attrs["step"],
              f"{f}: time {B.attrs['time']:.6e}, step {B.attrs['step']}")
        for k in A.keys():
            a, b = A[k][...], B[k][...]
            if a.shape != b.shape:
                check(False, f"{f}:{k} shapes {a.shape} and {b.shape}")
                continue
            if a.dtype.kind in "iu":
                check(np.array_equal(a, b), f"{f}:{k} equal")
            else:
                scale = max(float(np.max(np.abs(a))), 1e-300)
                d = float(np.max(np.abs(a - b))) / scale
                check(d <= bound, f"{f}:{k} largest difference {d:.2e} of its largest value")
sys.exit(0 if ok else 1)
