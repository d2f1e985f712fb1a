"""A run directory (or a sweep directory) as Python objects.

open_run(DIR) reads what `rupture run` or `rupture sweep` wrote there:
  run.json            Run.record (dict), Run.status, Run.message, Run.summary (the first
                      interface's crack summary with attribute access), Run.cracks (per
                      interface), Run.case (the input as the run merged it)
  history.csv         Run.history                       (Tables: numpy columns with units)
  crack_tip[_NAME].csv, crack_stretches[_NAME].csv, rupture_time_NAME.csv, mach_angle*.csv
                      Run.crack_tip(name=None), Run.stretches(name=None),
                      Run.rupture_time(name), Run.table(file)
  stations/NAME.csv   Run.stations (dict name -> Table)
  interface/NAME_NNNNNN.csv   Run.interface_profiles(name) (list of Tables, in time order)
  snapshots/*.h5      Run.snapshots: a lazy sequence of Snapshot (h5py opens a file when a
                      snapshot's arrays are first read)
It works on completed, failed and interrupted runs, on runs still going (their run.json is
rewritten every few seconds: Run.running, Run.heartbeat_age) and on runs written by several
MPI ranks (rank 0 writes every file; snapshots are one file per time). A sweep directory
(summary.csv) opens as a Sweep: Sweep.summary (Table), Sweep.runs (Run per row, by its varied
values).
"""
import glob
import json
import os
import re
import time

import numpy as np

from .tables import read_table, read_units


class Summary(dict):
    """A dict whose keys are also attributes (run.summary.initiation_time)."""

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(f"the crack summary has no {name!r}; it has {', '.join(self)}") from None


class Snapshot:
    """One snapshot file: time (s), step, and its datasets read on first use (position [N,3] m,
    velocity [N,3] m/s, half_size [N,2] m (GIMP half-widths; files written before 0.1.0's
    figures lack it), sxx, syy, sxy, szz, tau_max [N] Pa, body, id)."""

    def __init__(self, path):
        self.path = path
        self._attrs = None
        self._data = {}

    def _open(self):
        import h5py  # only snapshots need it

        return h5py.File(self.path, "r")

    def _read_attrs(self):
        if self._attrs is None:
            with self._open() as f:
                self._attrs = {k: f.attrs[k].item() if hasattr(f.attrs[k], "item") else f.attrs[k] for k in f.attrs}
                self._names = list(f.keys())
        return self._attrs

    @property
    def time(self):
        return float(self._read_attrs()["time"])

    @property
    def step(self):
        return int(self._read_attrs()["step"])

    def names(self):
        self._read_attrs()
        return list(self._names)

    def __getitem__(self, name):
        if name not in self._data:
            with self._open() as f:
                if name not in f:
                    raise KeyError(f"{self.path} has no dataset {name!r}: it has {', '.join(f.keys())}")
                self._data[name] = f[name][...]
        return self._data[name]

    @property
    def x(self):
        return self["position"][:, 0]

    @property
    def y(self):
        return self["position"][:, 1]

    def __repr__(self):
        return f"Snapshot({os.path.basename(self.path)!r})"


class Snapshots:
    """The run's snapshots in time order; nothing is read until a snapshot's data is."""

    def __init__(self, run_dir):
        self._files = sorted(glob.glob(os.path.join(run_dir, "snapshots", "particles_*.h5")))
        self._items = [Snapshot(p) for p in self._files]

    def __len__(self):
        return len(self._items)

    def __getitem__(self, k):
        return self._items[k]

    def __iter__(self):
        return iter(self._items)

    def times(self):
        return np.array([s.time for s in self._items])

    def at(self, t):
        """The snapshot nearest time t (s)."""
        if not self._items:
            raise LookupError("the run wrote no snapshots (output.snapshot_interval)")
        return self._items[int(np.argmin(np.abs(self.times() - t)))]


class Run:
    """One run directory."""

    def __init__(self, run_dir):
        self.dir = os.path.abspath(run_dir)
        path = os.path.join(self.dir, "run.json")
        if not os.path.exists(path):
            raise FileNotFoundError(f"{run_dir} holds no run.json: not a rupture run directory "
                                    "(a sweep directory holds summary.csv)")
        with open(path) as f:
            self.record = json.load(f)
        self.units = read_units(self.dir)
        self.snapshots = Snapshots(self.dir)

    # run.json
    @property
    def status(self):
        """"running", "completed", "failed" or "interrupted"."""
        return self.record.get("status")

    @property
    def message(self):
        return self.record.get("message", "")

    @property
    def case(self):
        """The input as the run merged it (defaults and --set included)."""
        return self.record.get("input", {})

    @property
    def version(self):
        return self.record.get("version")

    @property
    def heartbeat_age(self):
        """Seconds since run.json was last rewritten by the run (a "running" record whose
        heartbeat is old belongs to a run that was killed)."""
        return time.time() - float(self.record.get("heartbeat_unix", 0.0))

    @property
    def running(self):
        return self.status == "running"

    @property
    def summary(self):
        """The first interface's crack summary (run.json "crack"), keys as attributes."""
        return Summary(self.record.get("crack", {}))

    @property
    def cracks(self):
        """Every interface's crack summary by name."""
        cracks = self.record.get("cracks", {})
        if isinstance(cracks, list):  # run.json: a list, each naming its interface
            return {c.get("interface", str(k)): Summary(c) for k, c in enumerate(cracks)}
        return {k: Summary(v) for k, v in cracks.items()}

    def __getitem__(self, key):
        return self.record[key]

    # CSV files
    def table(self, name):
        """Any CSV file of the run directory, by its path inside it."""
        path = os.path.join(self.dir, name)
        if not os.path.exists(path):
            have = sorted(os.path.relpath(p, self.dir) for p in glob.glob(os.path.join(self.dir, "**", "*.csv"), recursive=True))
            raise FileNotFoundError(f"{self.dir} has no {name}; it has {', '.join(have) or 'no CSV file'}")
        return read_table(path, self.units)

    @property
    def history(self):
        return self.table("history.csv")

    def crack_tip(self, name=None):
        """crack_tip.csv (the first interface's), or crack_tip_NAME.csv."""
        return self.table(f"crack_tip_{name}.csv" if name else "crack_tip.csv")

    def stretches(self, name=None):
        return self.table(f"crack_stretches_{name}.csv" if name else "crack_stretches.csv")

    def rupture_time(self, name):
        return self.table(f"rupture_time_{name}.csv")

    @property
    def stations(self):
        out = {}
        for p in sorted(glob.glob(os.path.join(self.dir, "stations", "*.csv"))):
            out[os.path.splitext(os.path.basename(p))[0]] = read_table(p, self.units)
        return out

    def interface_names(self):
        names = set()
        for p in glob.glob(os.path.join(self.dir, "interface", "*_[0-9][0-9][0-9][0-9][0-9][0-9].csv")):
            names.add(re.sub(r"_\d{6}\.csv$", "", os.path.basename(p)))
        return sorted(names)

    def interface_profiles(self, name=None):
        """The profiles of one interface (default: the first that wrote any), in time order."""
        names = self.interface_names()
        if name is None:
            if not names:
                return []
            name = names[0]
        files = sorted(glob.glob(os.path.join(self.dir, "interface", f"{glob.escape(name)}_[0-9]*.csv")))
        return [read_table(p, self.units) for p in files]

    def __repr__(self):
        return f"Run({self.dir!r}, status={self.status!r})"


class Sweep:
    """A sweep directory: summary.csv and one run per row."""

    def __init__(self, sweep_dir):
        self.dir = os.path.abspath(sweep_dir)
        self.summary = read_table(os.path.join(self.dir, "summary.csv"), text=("run", "status", "regime", "arrested", "message"))
        cols = self.summary.names()
        self.keys = cols[1:cols.index("status")]  # the varied keys: between run and status

    def __len__(self):
        return len(self.summary)

    def row(self, k):
        return {c: self.summary[c][k] for c in self.summary.names()}

    @property
    def runs(self):
        """{(value of each varied key, ...): Run} for every run that wrote a run.json."""
        out = {}
        for k in range(len(self)):
            d = os.path.join(self.dir, str(self.summary["run"][k]))
            if os.path.exists(os.path.join(d, "run.json")):
                out[tuple(self.summary[key][k] for key in self.keys)] = Run(d)
        return out

    def __repr__(self):
        return f"Sweep({self.dir!r}, {len(self)} runs over {', '.join(self.keys)})"


def open_run(path):
    """A Run (DIR/run.json) or a Sweep (DIR/summary.csv)."""
    if os.path.exists(os.path.join(path, "summary.csv")) and not os.path.exists(os.path.join(path, "run.json")):
        return Sweep(path)
    return Run(path)
