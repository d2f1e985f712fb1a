#!/usr/bin/env python3
"""Parallel efficiency model of a distributed run (docs/parallel.md, "Efficiency model").

Usage: mpi_model.py RUPTURE T_P ALPHA BETA N1,N2,... [--scale K] -- CASE [--set k=v ...]
  T_P    measured compute time per particle-update on one thread, s (rupture run's
         1 / particle_updates_per_second)
  ALPHA  latency of one neighbour exchange or one scalar reduction step, s
  BETA   bandwidth per rank, B/s
  --scale K   a K times larger problem of the same shape: work x K, halo bytes x sqrt(K)
              (the blocks' perimeters), interface syncs x sqrt(K)

For each N, `rupture check CASE --ranks N` gives per level and rank the particles, and per rank
the bytes sent per finest step (bytes_r); the levels' periods give the exchanges per finest
step. The ranks meet at every finest step, so a finest step s of a cycle takes the largest
over the ranks of the work of the levels stepping at s (level l when s is a multiple of its
period): work_r(s). Per finest step, averaged over the cycle:
  T(N) = mean_s max_r work_r(s) * T_P + n_ex * ALPHA + max_r bytes_r / BETA + n_red * ALPHA * ceil(log2 N)
with n_ex = per level, the scatter's sum once per level step and the re-mapped momentum's every
finest step (1 / period + 1), and with interfaces 3 more (cohesive forces, 2 interface syncs),
and n_red = 3 reductions per finest step
(time step, migration check, failure flag). Efficiency E(N) = sum_r mean_s work_r(s) * T_P / (N T(N)).
"""
import math
import re
import subprocess
import sys

rupture, t_p, alpha, beta, ns = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
rest = sys.argv[6:]
scale = 1.0
if rest[0] == "--scale":
    scale, rest = float(rest[1]), rest[2:]
assert rest[0] == "--"
case = rest[1:]
print(f"T_P = {t_p * 1e9:.1f} ns, alpha = {alpha * 1e6:.1f} us, beta = {beta / 1e9:.1f} GB/s, problem x {scale:g}")
print("N | work per rank (max, mean) | bytes per rank (max) | exchanges / finest step | compute | communication | efficiency")
for n in [int(x) for x in ns.split(",")]:
    out = subprocess.run([rupture, "check", *case, "--ranks", str(n), "--no-timing"],
                         capture_output=True, text=True, check=True).stdout
    # Per level, per rank: particles (rupture check prints each level's blocks).
    per_level = []
    for block in re.split(r"^(?:level [0-9]+|grid): ", out, flags=re.M)[1:]:
        per_level.append([float(x) * scale for x in re.findall(r"^  rank [0-9]+: .*?particles ([0-9]+)", block, re.M)])
    sent = [float(x) * math.sqrt(scale) for x in re.search(r"exchange_bytes_per_rank=([0-9.,]+)", out).group(1).split(",")]
    periods = [int(p) for p in re.findall(r"one step every ([0-9]+) finest", out)]
    levels = len(re.findall(r"^level [0-9]+:", out, re.M)) or 1
    periods = periods + [1] * (levels - len(periods))  # coarsest first; the finer step every finest step
    cohesive = "dt_cohesive_limit=" in out  # rupture check prints it for cases with interfaces
    n_ex = sum(1.0 / p + 1.0 for p in periods) + (3.0 if cohesive else 0.0)
    # The ranks meet at every finest step (the halo sums): a finest step takes the largest work
    # of the levels stepping then (level l at steps divisible by its period).
    longest = max(periods)
    steps = [[sum(per_level[l][r] for l in range(levels) if s % periods[l] == 0) for r in range(n)]
             for s in range(longest)]
    work = [sum(steps[s][r] for s in range(longest)) / longest for r in range(n)]
    compute = sum(max(w) for w in steps) / longest * t_p
    comm = n_ex * alpha + max(sent) / beta + 3 * alpha * math.ceil(math.log2(n)) if n > 1 else 0.0
    serial = sum(work) * t_p
    eff = serial / (n * (compute + comm))
    print(f"{n} | {max(work):.0f}, {sum(work) / n:.0f} | {max(sent):.0f} | {n_ex:.2f} | "
          f"{compute * 1e6:.1f} us | {comm * 1e6:.1f} us | {eff:.3f}")
