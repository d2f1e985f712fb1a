#!/usr/bin/env python3
"""Runs the code cells of a notebook as one script, in the notebook's folder (as Jupyter
would), with matplotlib's Agg backend; RUPTURE_NOTEBOOK_OUT (argv[2]) gets its files. Then
checks what it must have made: the figures it saves, non-empty. Usage: run_notebook.py NB OUT"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")


def main(nb_path, out):
    os.makedirs(out, exist_ok=True)
    os.environ["RUPTURE_NOTEBOOK_OUT"] = out
    nb = json.load(open(nb_path))
    code = "\n\n".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code")
    os.chdir(os.path.dirname(os.path.abspath(nb_path)))
    exec(compile(code, nb_path, "exec"), {"__name__": "__main__"})
    for fig in ("tip_speed.png", "tau_max.png"):
        path = os.path.join(out, fig)
        if not os.path.exists(path) or os.path.getsize(path) < 1000:
            print(f"FAIL: the notebook did not make {path}")
            sys.exit(1)
    print(f"ok: {nb_path} ran; figures in {out}")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
