"""rupture from Python: read a run directory as arrays, run and sweep cases.

    import rupture
    r = rupture.open_run("out")            # a run, a sweep, or a run that is still going
    r.status, r.summary.initiation_time    # run.json, the crack summary as attributes
    t = r.history; t["time"], t.units["kinetic_energy"]
    snap = r.snapshots[-1]; snap["tau_max"], snap.time

    r = rupture.run("examples/rosakis1999.toml", "out", set={"time.end": 2e-6})

Needs numpy; h5py for snapshots; pandas is optional (Table.frame()).
"""
from ._version import __version__
from .tables import Table, read_table
from .runs import Run, Snapshot, Snapshots, Sweep, open_run
from .execute import RunError, find_executable, run, sweep

__all__ = [
    "__version__", "Table", "read_table", "Run", "Snapshot", "Snapshots", "Sweep", "open_run",
    "RunError", "find_executable", "run", "sweep",
]
