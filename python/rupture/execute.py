"""Running rupture from Python: run() and sweep() start the `rupture` executable and return the
opened run directory; a run that fails raises RunError with the run's message and exit code.

The executable is $RUPTURE_EXE, else `rupture` on PATH, else the checkout's
build/release/bin/rupture beside this package. With quiet=False the run's own lines (progress
and key=value results) are echoed as they come.
"""
import os
import shutil
import re
import subprocess
import threading
import sys

from .runs import Run, Sweep


class RunError(RuntimeError):
    """A rupture run that did not complete: `returncode`, the run's `message` (run.json or
    stderr), and the `run` directory when it wrote one."""

    def __init__(self, message, returncode, run=None, stderr=""):
        super().__init__(f"rupture exited with {returncode}: {message}")
        self.message = message
        self.returncode = returncode
        self.run = run
        self.stderr = stderr


def find_executable():
    exe = os.environ.get("RUPTURE_EXE")
    if exe:
        return exe
    on_path = shutil.which("rupture")
    if on_path:
        return on_path
    here = os.path.dirname(os.path.abspath(__file__))
    for candidate in (os.path.join(here, "..", "..", "build", "release", "bin", "rupture"),
                      os.path.join(here, "bin", "rupture")):
        if os.path.exists(candidate):
            return os.path.abspath(candidate)
    raise FileNotFoundError("no rupture executable: set RUPTURE_EXE, put rupture on PATH, or build "
                            "the checkout (cmake --preset release && cmake --build --preset release)")


def _value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (list, tuple)):
        return "[" + ",".join(_value(x) for x in v) + "]"
    if isinstance(v, str):
        return v if v[:1] in "[\"'" or _is_number(v) else f'"{v}"'
    return repr(v)


def _is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def _sets(set):
    args = []
    for k, v in (set or {}).items():
        args += ["--set", f"{k}={_value(v)}"]
    return args


_PROGRESS = re.compile(r"^step (\d+)/(\d+) .*\(\s*([0-9.]+) %\)")


def _progress_bar():
    """In a Jupyter notebook with ipywidgets (Debian's python3-ipywidgets): a callable that shows
    the run's progress line as a bar, update(percent, line). Elsewhere None: lines are printed."""
    try:
        from IPython import get_ipython

        shell = get_ipython()
        if shell is None or "IPKernelApp" not in shell.config:
            return None
        import ipywidgets
        from IPython.display import display
    except Exception:  # no IPython, no kernel, no widgets
        return None
    bar = ipywidgets.FloatProgress(min=0.0, max=100.0, description="rupture")
    label = ipywidgets.Label()
    display(ipywidgets.HBox([bar, label]))

    def update(percent, line):
        bar.value = percent
        label.value = line

    return update


def _execute(args, quiet):
    """Runs rupture with args; returns (returncode, stdout, stderr). Unless quiet, the run's
    own lines are shown as they come: the key=value results printed, the progress line
    (rupture writes it to stderr) as a progress bar in a notebook where one is available
    (_progress_bar), as lines elsewhere."""
    if quiet:
        proc = subprocess.run(args, capture_output=True, text=True)
        return proc.returncode, proc.stdout, proc.stderr
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, bufsize=1)
    bar = _progress_bar()
    err_lines = []

    def follow_stderr():  # a thread: stderr and stdout both fill as the run goes
        for line in proc.stderr:
            err_lines.append(line)
            m = _PROGRESS.match(line.strip())
            if m and bar is not None:
                bar(float(m.group(3)), line.strip())
            else:
                sys.stderr.write(line)
                sys.stderr.flush()

    reader = threading.Thread(target=follow_stderr, daemon=True)
    reader.start()
    lines = []
    for line in proc.stdout:
        lines.append(line)
        sys.stdout.write(line)
        sys.stdout.flush()
    proc.wait()
    reader.join()
    return proc.returncode, "".join(lines), "".join(err_lines)


def _fail(code, err, out_dir):
    run = None
    message = (err.strip().splitlines() or ["(no message)"])[-1]
    if out_dir and os.path.exists(os.path.join(out_dir, "run.json")):
        run = Run(out_dir)
        message = run.message or message
    raise RunError(message, code, run, err)


def run(case, out, set=None, threads=None, ranks=None, checkpoint_interval=None, overwrite=True,
        quiet=True, extra=()):
    """`rupture run CASE -o OUT` with each key=value of `set` as --set; returns the Run.
    ranks > 1 runs under mpirun."""
    args = [find_executable(), "run", os.fspath(case), "-o", os.fspath(out)]
    if overwrite:
        args.append("--overwrite")
    if quiet:
        args.append("--quiet")
    if threads is not None:
        args += ["--set", f"solver.threads={int(threads)}"]
    if checkpoint_interval is not None:
        args += ["--checkpoint-interval", repr(float(checkpoint_interval))]
    args += _sets(set) + list(extra)
    if ranks and ranks > 1:
        args = ["mpirun", "-n", str(ranks)] + args
    code, out_text, err = _execute(args, quiet)
    if code != 0:
        _fail(code, err, os.fspath(out))
    return Run(os.fspath(out))


def sweep(case, out, vary, set=None, jobs=None, threads=None, quiet=True):
    """`rupture sweep CASE -o OUT --vary KEY=V1,V2 ...` (vary: {key: [values]}); returns the Sweep.
    A sweep whose runs fail still returns (their status is in Sweep.summary); a sweep that could
    not start raises RunError."""
    args = [find_executable(), "sweep", os.fspath(case), "-o", os.fspath(out)]
    for k, values in vary.items():
        args += ["--vary", f"{k}=" + ",".join(_value(v) for v in values)]
    if jobs is not None:
        args += ["--jobs", str(jobs)]
    if threads is not None:
        args += ["--threads", str(threads)]
    args += _sets(set)
    code, out_text, err = _execute(args, quiet)
    if not os.path.exists(os.path.join(os.fspath(out), "summary.csv")):
        _fail(code, err, None)
    return Sweep(os.fspath(out))
