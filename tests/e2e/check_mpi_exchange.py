#!/usr/bin/env python3
"""`rupture check --ranks N` predicts the bytes a distributed run exchanges; the run measures them.

Usage: check_mpi_exchange.py MPIEXEC RUPTURE CASE RANKS DIR [--set k=v ...] [--no-rebalance]
Runs `rupture check CASE --ranks RANKS` and `MPIEXEC -n RANKS rupture run CASE -o DIR`; with no
particle migration in the run, the mean of exchange_bytes_per_rank (check) must equal the
run's exchange_bytes_per_rank_per_step exactly (the same halo boxes, fields and values).
"""
import re
import subprocess
import sys

mpiexec, rupture, case, ranks, out = sys.argv[1:6]
sets = sys.argv[6:]
check = subprocess.run([rupture, "check", case, "--ranks", ranks, "--no-timing",
                        *[a for a in sets if a != "--no-rebalance"]],
                       capture_output=True, text=True, check=True).stdout
run = subprocess.run([mpiexec, "--oversubscribe", "-n", ranks, rupture, "run", case, "-o", out,
                      "--overwrite", "--quiet", *sets], capture_output=True, text=True, check=True).stdout
predicted = [float(x) for x in re.search(r"exchange_bytes_per_rank=([0-9.,]+)", check).group(1).split(",")]
measured = float(re.search(r"exchange_bytes_per_rank_per_step=([0-9.]+)", run).group(1))
migrations = int(re.search(r"migrations=([0-9]+)", run).group(1))
mean = sum(predicted) / len(predicted)
print(f"predicted per rank {predicted}, mean {mean:.1f}; measured mean {measured:.1f}; migrations {migrations}")
ok = migrations == 0 and abs(mean - measured) <= 0.5
print("ok" if ok else "FAIL")
sys.exit(0 if ok else 1)
