#!/usr/bin/env python3
"""Benchmark regression (SPEC §6, V_imp = 30 m/s): initiation 10.4 +- 0.3 us, sustained speed
2300 m/s +- 5 %, energy balance within 2 %, intersonic regime. Reads DIR/run.json."""
import json
import sys

run = json.load(open(sys.argv[1] + "/run.json"))
crack = run["crack"]
checks = [
    ("crack.initiation_time (us)", crack["initiation_time"] * 1e6, 10.4, 0.3),
    ("crack.sustained_speed (m/s)", crack["sustained_speed"], 2300.0, 0.05 * 2300.0),
]
ok = run["status"] == "completed"
for name, value, expected, tol in checks:
    good = abs(value - expected) <= tol
    ok &= good
    print(f"{name}: {value:.4g} (expected {expected} +- {tol:.3g}) {'ok' if good else 'FAIL'}")
err = run["energy_balance_error"]
print(f"energy_balance_error: {err:.3e} (limit 0.02) {'ok' if err < 0.02 else 'FAIL'}")
print(f"crack.regime: {crack['regime']} (expected intersonic)")
ok &= err < 0.02 and crack["regime"] == "intersonic" and run["crack.regime"] == crack["regime"]
sys.exit(0 if ok else 1)
