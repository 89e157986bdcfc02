"""Helpers the bench scripts share: a case's dictionary entries, its time
directories, its cells, and a solver run timed by timeSteps.py."""

import json
import os
import re
import shutil
import subprocess
import sys

TIME_STEPS = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                          "timeSteps.py")
TIME_DIR = re.compile(r"^[0-9.eE+-]+$")


def set_entry(path, key, value):
    """Sets the one top-level entry key of a dictionary file to value"""
    text = open(path).read()
    new, n = re.subn(r"(?m)^(%s\s+)[^;]*;" % re.escape(key),
                     lambda m: m.group(1) + str(value) + ";", text)
    if n != 1:
        sys.exit("bench: %s: entry %s not found" % (path, key))
    open(path, "w").write(new)


def clear_times(case, keep="0"):
    """Removes the time directories after keep (a timed run's output)"""
    for d in os.listdir(case):
        if TIME_DIR.match(d) and float(d) > float(keep):
            shutil.rmtree(os.path.join(case, d))


def n_cells(case):
    """The cells of the case's mesh, from the header of its owner file"""
    # (the header is text also in a binary file)
    header = open(os.path.join(case, "constant", "polyMesh", "owner"),
                  "rb").read(2000).decode("ascii", "replace")
    return int(re.search(r"nCells:\s*(\d+)", header).group(1))


def summary(times, cells, warmup):
    """timeSteps.py's summary of the time stamps in the file times"""
    return json.loads(subprocess.check_output(
        [sys.executable, TIME_STEPS, "summary", times, str(cells),
         str(warmup)], text=True))


def timed(case, tag, cmd, cells, warmup, env=None):
    """Runs cmd in case under timeSteps.py (log.<tag>, times.<tag>) and
    returns the summary of its time loop"""
    log = os.path.join(case, "log." + tag)
    times = os.path.join(case, "times." + tag)
    if subprocess.call([sys.executable, TIME_STEPS, "run", log, times, "--"]
                       + cmd, cwd=case, env=env):
        sys.exit("bench: %s failed in %s (see %s)"
                 % (" ".join(cmd), case, log))
    return summary(times, cells, warmup)
