#!/usr/bin/python3
"""TPV103-2D against the converged reference (tests/data/validation/tpv103-2d-converged, 25 m;
docs/faults.md, TPV103-2D).

    check_tpv103_converged.py short RUPTURE OUT_DIR
        examples/tpv103_2d.toml 10 km off the fault, twice: at 100 m to 2.5 s (OUT_DIR/early; the
        edges' reflections come back to the fault after 3.3 s) and at 200 m to 8 s (OUT_DIR/far).
        Fails unless
        - at 100 m the rupture times at 0, 2.5 and 5 km (the early, nucleation-driven supershear
          transient) lag the reference's by no more than TOL_EARLY (each about 1.4 times the lag
          measured at 100 m: 0.002, 0.039, 0.107 s; a run that misses the transient, as 200 m
          does, lags 0.079 and 0.407 s at 2.5 and 5 km), and are symmetric (+-5 km within a step);
        - at 200 m the rupture reaches 20 km by 8 s (the converged solution passes 20 km at
          7.23 s and arrests near 25 km at 9.2 s; the stored, unconverged uguca run arrests at
          18-19 km), and its front is nowhere on 0-12 km ahead of the reference's by more than
          0.05 s (that run's sustained supershear front is 0.26 s ahead at 7.5 km, 0.87 s at
          12 km).
    check_tpv103_converged.py long RUPTURE OUT_DIR
        examples/tpv103_2d_nested.toml as it is (25 m, to 10 s): scripts/tpv103_compare.py
        --check (rupture times at 0-18 km within 0.05 s, 0.1 s at 7.5 km; slip at 0-15 km within
        2 % to 9 s; the arrest within 1 km).
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from tpv103_compare import compare, read_csv, run_rupture_time  # noqa: E402

REF = os.path.join(ROOT, "tests", "data", "validation", "tpv103-2d-converged")
# Bound on the lag at 0, 2.5 and 5 km at 100 m (s); measured 0.002, 0.039, 0.107 s (docs/faults.md).
TOL_EARLY = {0.0: 0.02, 2.5: 0.06, 5.0: 0.15}
SMALL = ["--overwrite", "--quiet", "--set", "grid.min=[-30000.0,-10000.0]", "--set", "grid.max=[30000.0,10000.0]",
         "--set", "bodies.north.max=[30000.0,10000.0]", "--set", "bodies.south.min=[-30000.0,-10000.0]"]


def main():
    mode, rupture, out = sys.argv[1:4]
    if mode == "short":
        case = os.path.join(ROOT, "examples", "tpv103_2d.toml")
        early, far = os.path.join(out, "early"), os.path.join(out, "far")
        subprocess.run([rupture, "run", case, "-o", early] + SMALL + [
            "--set", "time.end=2.5", "--set", "grid.cell_size=100", "--set", "interface.fault.segments=600"], check=True)
        subprocess.run([rupture, "run", case, "-o", far] + SMALL + [
            "--set", "time.end=8", "--set", "grid.cell_size=200", "--set", "interface.fault.segments=300"], check=True)
        failures = []
        rows, _, _ = compare(early, REF, "25m", 2.5, (0.0, 2.5, 5.0))
        for km, t_r, t_ref, diff, _, _, _ in rows:
            print(f"100 m: x = {km:4.1f} km: {t_r:.3f} s, reference {t_ref:.3f} s ({diff:+.3f}, bound {TOL_EARLY[km]:.2f})")
            if abs(diff) > TOL_EARLY[km]:
                failures.append(f"100 m, x = {km} km: rupture time {t_r:.3f} s, {diff:+.3f} s from the reference")
        rt = read_csv(os.path.join(early, "rupture_time_fault.csv"))
        dt = 0.4 * 100.0 / 6000.0
        tm, tp = run_rupture_time(rt, -5000.0), run_rupture_time(rt, 5000.0)
        print(f"100 m: symmetry at 5 km: {tm:.4f} / {tp:.4f} s")
        if tm < 0 or abs(tm - tp) > dt:
            failures.append(f"+-5 km: rupture times {tm:.4f} and {tp:.4f} s differ by more than a step")
        rows, (right, left, ref_arrest, _), t_end = compare(far, REF, "25m", 8.0, (0.0, 2.5, 5.0, 7.5, 9.0, 12.0))
        for km, t_r, t_ref, diff, _, _, _ in rows:
            print(f"200 m: x = {km:4.1f} km: {t_r:.3f} s, reference {t_ref:.3f} s ({diff:+.3f})")
            if diff < -0.05:
                failures.append(f"200 m, x = {km} km: front {-diff:.3f} s ahead of the reference (supershear?)")
        t20 = run_rupture_time(read_csv(os.path.join(far, "rupture_time_fault.csv")), 20000.0)
        print(f"200 m: ruptured to {right:.2f} km (x < 0: {left:.2f} km) by {t_end:.2f} s; 20 km at {t20:.3f} s "
              f"(reference 7.225 s, arrest {ref_arrest:.2f} km)")
        if t20 < 0:
            failures.append(f"200 m: arrested before 20 km ({right:.2f} km by {t_end:.2f} s)")
        for f in failures:
            print("FAIL:", f)
        sys.exit(1 if failures else 0)
    if mode == "long":
        cmd = [rupture, "run", os.path.join(ROOT, "examples", "tpv103_2d_nested.toml"), "-o", out,
               "--overwrite", "--quiet"]
        subprocess.run(cmd, check=True)
        r = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "tpv103_compare.py"), out, REF,
                            "--check"])
        sys.exit(r.returncode)
    sys.exit(f"unknown mode {mode}")


if __name__ == "__main__":
    main()
