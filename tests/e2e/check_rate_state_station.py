#!/usr/bin/python3
"""A rate-and-state fault station's file (examples/rate_state_1d.toml, the uniform 1D fault)
carries the state psi, and its columns satisfy the friction law at every sample:
  - the header ends in `state`;
  - shear_traction = sigma a asinh[V/(2 V0) exp(psi/a)] (sigma = -normal_traction, V the
    slip_rate column) to 1e-8 relative at every sample that slides (the file's 10 digits;
    measured 1.6e-10): on a uniform fault the node's values are the Gauss points';
  - the first sample's psi is the steady balance of the initial traction,
    a ln[(2 V0/V_ini) sinh(tau0/(sigma0 a))], to 1e-8;
  - at the end, after some 30 Dc of slip, psi has reached the aging law's steady state at the
    final rate, f0 - b ln(V/V0), within b times the relative spread of V over the last 0.05 s
    (the rate still rings by ~1e-3 there; psi itself fell from 0.517 to 0.427).
Usage: check_rate_state_station.py RUN"""
import csv
import math
import sys

run = sys.argv[1]
a, b, v0, f0 = 0.008, 0.012, 1e-6, 0.6          # examples/rate_state_1d.toml
v_ini, tau0, sigma0 = 1e-3, 68684277.46608856, 120e6
rows = list(csv.reader(open(f"{run}/stations/fault_centre.csv")))
head = rows[0]
assert head[-1] == "state", head
col = {k: i for i, k in enumerate(head)}
data = [[float(x) for x in r] for r in rows[1:]]
psi0 = a * math.log(2 * v0 / v_ini * math.sinh(tau0 / (sigma0 * a)))
print(f"psi at t = 0: {data[0][col['state']]:.9f} (steady balance {psi0:.9f})")
assert abs(data[0][col["state"]] - psi0) <= 1e-8
worst = 0.0
for r in data:
    v, psi = abs(r[col["slip_rate"]]), r[col["state"]]
    if v <= 0.0:
        continue
    tau, sigma = r[col["shear_traction"]], -r[col["normal_traction"]]
    worst = max(worst, abs(tau - sigma * a * math.asinh(v / (2 * v0) * math.exp(psi / a))) / abs(tau))
print(f"friction law at the station: largest relative residual {worst:.2e}")
assert worst <= 1e-8
last = [r for r in data if r[0] >= data[-1][0] - 0.05]
rates = [abs(r[col["slip_rate"]]) for r in last]
spread = (max(rates) - min(rates)) / rates[-1]
v_end, psi_end = rates[-1], data[-1][col["state"]]
gap = abs(psi_end - (f0 - b * math.log(v_end / v0)))
print(f"psi at the end {psi_end:.7f}, steady state at V = {v_end:.4f} m/s: {gap:.2e} off "
      f"(bound b x spread {b * spread:.2e})")
assert gap <= b * spread
print("rate-and-state station: ok")
