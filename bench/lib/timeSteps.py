#!/usr/bin/env python3
"""Run an OpenFOAM solver and time its steps from the outside.

Usage:
    timeSteps.py run LOG TIMES -- solver [args]
        Run the solver, copy its output (stdout and stderr) to LOG and, for
        every "Time = ..." line it prints, the wall-clock instant (monotonic
        clock, seconds since the start) and the solver process's CPU time
        (user + system, from /proc/<pid>/stat, 10 ms ticks) to TIMES as
        "<wall> <cpu> <line>", and at the end the process's peak resident
        memory ("<maxrss KB>", from wait4). Exits with the solver's status.

    timeSteps.py summary TIMES CELLS WARMUP
        Print one JSON object describing the time loop:
          steps        "Time =" lines in the log (steps taken)
          timedSteps   steps in the timed window
          loopSeconds  wall time of the timed window
          nsPerCellStep, medianNsPerCellStep, minNsPerCellStep  (wall)
          cpuNsPerCellStep  the same from the solver's CPU time: what the
                       wall figure would be on an idle core (the bench
                       machine may be shared)
          startSeconds wall time from launch to the first "Time =" line
          totalSeconds wall time from launch to exit
          cpuLoopSecondsProc  the solver's CPU time over the window
          cpuLoopSecondsSolver  the solver's own ExecutionTime (CPU) over the same
                       window when it prints one per step (rhoCentralFoam),
                       else null
          dtMin, dtMax, coMax  step sizes and largest Courant number printed
                       (impactFoam) over the timed steps
          maxRssKb     peak resident memory of the process in kB (of
                       mpirun itself, not its ranks, for a parallel run;
                       null if not recorded)
          systemShare  system CPU time over user + system time of the
                       whole run (page faults of freshly allocated
                       fields show here), null if not recorded

The timed window: both solvers print "Time = t" at the start of a step, so
the interval between consecutive "Time =" lines is one whole step. The first
WARMUP steps (first touch of memory, lazily built mesh data) and the last
step (it ends with writing the fields) are left out: the window runs from the
"Time =" line of step WARMUP+1 to that of the last step N, N-1-WARMUP steps.
ns/cell/step = window wall time / (cells x steps in the window).
"""

import json
import math
import os
import re
import statistics
import subprocess
import sys
import time

TIME_LINE = re.compile(r"^Time = (\S+)")
DELTA_T = re.compile(r"deltaT = (\S+)")
COURANT = re.compile(r"Courant Number (?:mean: \S+ )?max(?: =|:) (\S+)")
EXEC_TIME = re.compile(r"^ExecutionTime = (\S+) s")


TICK = float(os.sysconf("SC_CLK_TCK"))


def cpuSeconds(pid):
    """User + system CPU seconds of a live process, None once it is gone"""
    try:
        with open("/proc/%d/stat" % pid) as f:
            fields = f.read().rsplit(")", 1)[1].split()
        # after "pid (comm)": state is field 3, utime 14 and stime 15
        return (int(fields[11]) + int(fields[12]))/TICK
    except (OSError, IndexError, ValueError):
        return None


def run(logName, timesName, command):
    start = time.perf_counter()
    with open(logName, "w") as log, open(timesName, "w") as times:
        times.write("0.000000 0.00 <start>\n")
        proc = subprocess.Popen(
            command,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            universal_newlines=True,
            bufsize=1,
        )
        for line in proc.stdout:
            now = time.perf_counter() - start
            if TIME_LINE.match(line):
                cpu = cpuSeconds(proc.pid)
                times.write("%.6f %s %s" % (
                    now, "nan" if cpu is None else "%.2f" % cpu, line))
            elif EXEC_TIME.match(line) or line.startswith("End"):
                times.write("%.6f nan %s" % (now, line))
            log.write(line)
        _, raw, usage = os.wait4(proc.pid, 0)
        proc.returncode = status = os.waitstatus_to_exitcode(raw)
        end = time.perf_counter() - start
        times.write("%.6f nan <maxrss %d>\n" % (end, usage.ru_maxrss))
        times.write("%.6f nan <rusage %.3f %.3f>\n"
                    % (end, usage.ru_utime, usage.ru_stime))
        times.write("%.6f nan <exit %d>\n" % (end, status))
    return status


def summary(timesName, cells, warmup):
    stamps = []         # (wall, cpu, simulated time) of each "Time =" line
    execTimes = []      # ExecutionTime after each step (rhoCentralFoam)
    dts = []
    cos = []
    total = None
    maxRss = None
    systemShare = None
    lastTime = None
    with open(timesName) as f:
        for raw in f:
            wall, cpu, line = raw.split(" ", 2)
            wall = float(wall)
            m = TIME_LINE.match(line)
            if m:
                t = float(m.group(1))
                stamps.append((wall, float(cpu), t))
                d = DELTA_T.search(line)
                if d:
                    dts.append(float(d.group(1)))
                elif lastTime is not None:
                    dts.append(t - lastTime)
                else:
                    dts.append(t)
                lastTime = t
            c = COURANT.search(line)
            if c:
                cos.append(float(c.group(1)))
            e = EXEC_TIME.match(line)
            if e:
                execTimes.append(float(e.group(1)))
            if line.startswith("<exit"):
                total = wall
            if line.startswith("<maxrss"):
                maxRss = int(line.split()[1].rstrip(">"))
            if line.startswith("<rusage"):
                user, system = (float(v) for v in
                                line.rstrip().rstrip(">").split()[1:3])
                systemShare = system/(user + system) if user + system else None

    steps = len(stamps)
    first = warmup          # index of the "Time =" line of step warmup+1
    last = steps - 1        # index of the "Time =" line of the last step
    timed = last - first
    if timed < 1:
        raise SystemExit(
            "%s: %d steps, too few for %d warm-up steps" % (timesName, steps, warmup)
        )
    loop = stamps[last][0] - stamps[first][0]
    perStep = [stamps[i + 1][0] - stamps[i][0] for i in range(first, last)]
    scale = 1e9 / cells
    cpu = stamps[last][1] - stamps[first][1]

    cpuLoop = None
    # ExecutionTime printed at the end of step k is execTimes[k-1]; the
    # window covers steps warmup+1 .. N-1
    if len(execTimes) >= steps - 1 and steps - 2 >= 0:
        cpuLoop = execTimes[steps - 2] - execTimes[warmup - 1] \
            if warmup >= 1 else execTimes[steps - 2]

    print(json.dumps({
        "steps": steps,
        "timedSteps": timed,
        "loopSeconds": loop,
        "nsPerCellStep": loop*scale/timed,
        "medianNsPerCellStep": statistics.median(perStep)*scale,
        "minNsPerCellStep": min(perStep)*scale,
        "cpuLoopSecondsProc": None if math.isnan(cpu) else cpu,
        "cpuNsPerCellStep": None if math.isnan(cpu) else cpu*scale/timed,
        "startSeconds": stamps[0][0],
        "totalSeconds": total,
        "cpuLoopSecondsSolver": cpuLoop,
        "dtMin": min(dts[first:last]),
        "dtMax": max(dts[first:last]),
        "coMax": max(cos[first:last]) if len(cos) >= last else None,
        "maxRssKb": maxRss,
        "systemShare": systemShare,
    }))


def main(argv):
    if len(argv) >= 5 and argv[1] == "run" and argv[4] == "--":
        return run(argv[2], argv[3], argv[5:])
    if len(argv) == 5 and argv[1] == "summary":
        summary(argv[2], int(argv[3]), int(argv[4]))
        return 0
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
