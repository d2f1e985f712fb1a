"""The CSV files a run writes, as tables of numpy columns with their units.

Every CSV file of a run directory has a one-line header; DIR/units.csv gives the unit and the
meaning of each column of each file (file,column,unit,meaning). A Table holds the columns as
float arrays (text columns, such as a sweep's status, as arrays of str), in file order.
"""
import csv
import os

import numpy as np


def _column(values):
    try:
        return np.array([float(v) if v != "" else np.nan for v in values], dtype=float)
    except ValueError:
        return np.array(values, dtype=str)


class Table:
    """Columns of one CSV file: table["time"] is an array, table.units["time"] its unit."""

    def __init__(self, columns, units=None, meaning=None, path=None):
        self.columns = dict(columns)
        self.units = dict(units or {})
        self.meaning = dict(meaning or {})
        self.path = path

    def __getitem__(self, name):
        try:
            return self.columns[name]
        except KeyError:
            raise KeyError(f"{name!r} is not a column of {self.path or 'this table'}: "
                           f"columns are {', '.join(self.columns)}") from None

    def __contains__(self, name):
        return name in self.columns

    def __len__(self):
        return len(next(iter(self.columns.values()))) if self.columns else 0

    def __iter__(self):
        return iter(self.columns)

    def __repr__(self):
        cols = ", ".join(f"{k} [{self.units[k]}]" if self.units.get(k) else k for k in self.columns)
        return f"Table({os.path.basename(self.path or '')!r}, {len(self)} rows: {cols})"

    def names(self):
        return list(self.columns)

    def array(self):
        """The table as a numpy structured array (one field per column)."""
        dtype = [(k, v.dtype) for k, v in self.columns.items()]
        out = np.empty(len(self), dtype=dtype)
        for k, v in self.columns.items():
            out[k] = v
        return out

    def frame(self):
        """The table as a pandas DataFrame (units in .attrs["units"]); needs pandas."""
        import pandas as pd  # optional dependency

        df = pd.DataFrame(self.columns)
        df.attrs["units"] = dict(self.units)
        return df


def read_units(run_dir):
    """{file: {column: (unit, meaning)}} from DIR/units.csv ({} where the run wrote none)."""
    path = os.path.join(run_dir, "units.csv")
    out = {}
    if not os.path.exists(path):
        return out
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            out.setdefault(row["file"], {})[row["column"]] = (row["unit"], row["meaning"])
    return out


def _units_for(units, name):
    """The units.csv entry for a file: its own name, or its family's (station_*.csv and
    interface profiles are listed once, under a pattern)."""
    if name in units:
        return units[name]
    for pattern, cols in units.items():
        if "*" in pattern or "NAME" in pattern or "NNNNNN" in pattern:
            head = pattern.split("*")[0].split("NAME")[0].split("NNNNNN")[0]
            tail = pattern.split("*")[-1].split("NAME")[-1].split("NNNNNN")[-1]
            if name.startswith(head) and name.endswith(tail):
                return cols
    return {}


def read_table(path, units=None, text=()):
    """One CSV file as a Table; `units` is read_units() of its run directory (or None); the
    columns named in `text` stay strings."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        try:
            header = next(reader)
        except StopIteration:
            return Table({}, path=path)
        rows = [r for r in reader if len(r) == len(header)]  # a row being written is left out
    columns = {h: np.array([r[k] for r in rows], dtype=str) if h in text else _column([r[k] for r in rows])
               for k, h in enumerate(header)}
    rel = os.path.basename(path)
    if units is not None:
        parent = os.path.basename(os.path.dirname(path))
        entry = _units_for(units, f"{parent}/{rel}") or _units_for(units, rel)
    else:
        entry = {}
    return Table(columns, {c: u for c, (u, _) in entry.items()},
                 {c: m for c, (_, m) in entry.items()}, path=path)
