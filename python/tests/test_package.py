"""The rupture package on small real runs: each reader on a completed run, a failed one, an
interrupted one and a sweep; run() on a bad case raises with the run's message.

The runs are made by the rupture executable ($RUPTURE_EXE, set by ctest; else as
rupture.find_executable finds it), a few seconds in all."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "python"))

import rupture  # noqa: E402

EXAMPLE = os.path.join(ROOT, "examples", "rosakis1999.toml")
IMPACT = os.path.join(ROOT, "examples", "elastic_impact.toml")
CRACK = os.path.join(ROOT, "tests", "inputs", "diagonal_weak_plane.toml")


@pytest.fixture(scope="module")
def work(tmp_path_factory):
    return tmp_path_factory.mktemp("runs")


@pytest.fixture(scope="module")
def snapshots_run(work):
    return rupture.run(EXAMPLE, work / "snap", set={"time.end": 2e-6, "output.snapshot_interval": 1e-6})


@pytest.fixture(scope="module")
def crack_run(work):
    return rupture.run(CRACK, work / "crack", set={"output.interface_interval": 2e-6})


def test_version_matches_the_executable():
    out = subprocess.run([rupture.find_executable(), "--version"], capture_output=True, text=True, check=True)
    assert out.stdout.split()[1] == rupture.__version__, out.stdout


def test_completed_run_history_and_units(snapshots_run):
    r = snapshots_run
    assert r.status == "completed" and not r.running
    h = r.history
    assert h.units["time"] == "s" and h.units["kinetic_energy"] == "J/m"
    assert len(h) >= 2 and np.all(np.diff(h["time"]) > 0)
    # E14: the history's own balance column is kinetic + strain - initial - work, relative.
    assert np.all(np.isfinite(h["total_energy"]))
    assert r["particles"] == r.record["particles"] > 0
    assert r.case["time"]["end"] == pytest.approx(2e-6)
    assert r.version == rupture.__version__
    # What has not happened is null in run.json (None here), not -1: the crack has not
    # initiated by 2 us, no checkpoint was written.
    assert r.summary.initiated is False and r.summary.initiation_time is None
    assert r.summary.mach_angle is None and r.record["checkpoint_time"] is None


def test_snapshots_are_lazy_and_match_run_json(snapshots_run):
    s = snapshots_run.snapshots
    assert len(s) == 3
    t = s.times()
    assert t[0] == 0.0 and np.all(np.diff(t) > 0) and t[-1] <= 2e-6 * (1 + 1e-12)
    last = s[-1]
    n = snapshots_run["particles"]
    rows = len(last["id"])  # every particle, or those of output.snapshot_region
    assert 0 < rows <= n and last["tau_max"].shape == (rows,) and last["position"].shape == (rows, 3)
    assert np.all(last["tau_max"] >= 0)  # (sigma_1 - sigma_2) / 2
    # rows are in id order, the same particles in every file
    assert np.array_equal(s[0]["id"], last["id"]) and np.all(np.diff(last["id"]) > 0)
    assert s.at(1.1e-6).step == s[1].step
    with pytest.raises(KeyError, match="no dataset"):
        last["nonsense"]


def test_crack_tip_profiles_and_summary(crack_run):
    r = crack_run
    tip = r.crack_tip()
    assert "time" in tip and tip.units["time"] == "s"
    names = r.interface_names()
    assert names, "the interface wrote profiles"
    profiles = r.interface_profiles(names[0])
    assert len(profiles) >= 2
    assert profiles[0].units.get("x") == "m"
    summary = r.summary
    assert summary.initiation_time == r.record["crack"]["initiation_time"]
    with pytest.raises(AttributeError, match="crack summary has no"):
        summary.no_such_thing
    assert set(r.cracks) >= {summary.interface}
    with pytest.raises(FileNotFoundError, match="has no"):
        r.table("nothing.csv")
    # a DataFrame where pandas is installed, a structured array everywhere
    arr = tip.array()
    assert arr.dtype.names[0] == tip.names()[0] and len(arr) == len(tip)


def test_a_run_on_two_ranks_reads_as_one(work):
    """The plate impact on one process and on two MPI ranks (rank 0 writes every file; the
    snapshots are written collectively): the same tables and snapshot rows, to the distributed
    runs' agreement bound (tests/mpi: 1e-12 of each quantity's scale)."""
    opts = {"time.end": 1e-6, "output.snapshot_interval": 0.5e-6}
    one = rupture.run(IMPACT, work / "one_rank", set=opts)
    two = rupture.run(IMPACT, work / "two_ranks", set=opts, ranks=2)
    assert two.status == "completed" and two["ranks"] == 2 and one["ranks"] == 1
    h1, h2 = one.history, two.history
    assert h1.names() == h2.names() and len(h1) == len(h2)
    for col in ("kinetic_energy", "strain_energy", "external_work"):
        scale = np.abs(h1[col]).max()
        assert np.abs(h2[col] - h1[col]).max() <= 1e-12 * scale + 1e-300, col
    assert len(one.snapshots) == len(two.snapshots) == 3
    s1, s2 = one.snapshots[-1], two.snapshots[-1]
    assert np.array_equal(s1["id"], s2["id"]) and s1.time == s2.time
    assert np.abs(s2["position"] - s1["position"]).max() <= 1e-12 * np.abs(s1["position"]).max()
    assert np.abs(s2["velocity"] - s1["velocity"]).max() <= 1e-12 * np.abs(s1["velocity"]).max()
    assert np.array_equal(s1["half_size"], s2["half_size"])


def test_failed_run_raises_with_the_message(work):
    with pytest.raises(rupture.RunError) as e:
        rupture.run(IMPACT, work / "unstable", set={"bodies.plate.velocity": [3000, 0], "time.end": 10e-6,
                                                    "output.snapshot_interval": 0})
    assert e.value.returncode == 2
    assert e.value.run is not None and e.value.run.status == "failed"
    assert e.value.message == e.value.run.message and e.value.message
    h = e.value.run.history  # what it wrote before it stopped stays readable
    assert len(h) >= 1


def test_bad_case_raises_naming_the_key(work):
    with pytest.raises(rupture.RunError) as e:
        rupture.run(EXAMPLE, work / "bad", set={"grid.cell_size": -1})
    assert "grid.cell_size" in e.value.message and e.value.returncode != 0


def test_interrupted_run(work):
    out = work / "stopped"
    with pytest.raises(rupture.RunError) as e:
        rupture.run(EXAMPLE, out, set={"time.end": 4e-6, "output.snapshot_interval": 0},
                    checkpoint_interval=1e-6, extra=["--stop-after-steps", "20"])
    r = rupture.open_run(out)
    assert r.status == "interrupted", (r.status, e.value.message)
    # it stops at the first step it can checkpoint at after 20, well before the end
    assert 20 <= r["steps"] < r["steps_planned"] and len(r.history) >= 1


def test_sweep(work):
    sw = rupture.sweep(CRACK, work / "sweep", vary={"loads.impact.normal": [-94.74e6, -80e6]},
                       set={"output.interface_interval": 0, "time.end": 4e-6})
    assert isinstance(sw, rupture.Sweep) and len(sw) == 2
    assert sw.keys == ["loads.impact.normal"]
    assert list(sw.summary["status"]) == ["completed", "completed"]
    runs = sw.runs
    assert sorted(runs) == [(-94.74e6,), (-80e6,)]
    for (v,), run in runs.items():
        assert run.case["loads"]["impact"]["normal"] == pytest.approx(v)
    assert isinstance(rupture.open_run(work / "sweep"), rupture.Sweep)


def test_progress_lines_outside_a_notebook(work, capfd):
    """Not quiet: the key=value results on stdout and the progress line on stderr as lines (no
    notebook here, so no progress bar); the progress line is the one the bar would parse."""
    from rupture import execute

    assert execute._progress_bar() is None
    rupture.run(IMPACT, work / "progress", set={"time.end": 0.2e-6, "output.snapshot_interval": 0}, quiet=False)
    out, err = capfd.readouterr()
    assert "status=completed" in out
    last = [line for line in err.splitlines() if line.startswith("step ")][-1]
    m = execute._PROGRESS.match(last)
    assert m and float(m.group(3)) == pytest.approx(100.0) and m.group(1) == m.group(2), last
