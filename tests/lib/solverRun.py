"""Run impactFoam (serial or under mpirun) with a cap on the number of time
steps and on the wall time, so that a run whose time step collapses (a
broken state with huge wave speeds) fails in seconds instead of running
until the test harness's time limit.

    import solverRun
    solverRun.run_capped(case, "impactFoam", max_steps=1000)
    solverRun.run_capped(case, "mpirun -np 2 impactFoam -parallel",
                         max_steps=300, log="log.mpirun")

The solver's output goes to case/log (default log.impactFoam). A run
stopped by a cap raises foamcase.FoamError whose summary says so.
"""
import os

import foamcase as fc


def run_capped(case, cmd, max_steps, log="log.impactFoam", timeout=300):
    """Run the shell command cmd in case; stop it after max_steps lines
    'Time = ...' or timeout seconds (coreutils timeout kills the solver
    itself, not only the shell). Returns the log path."""
    script = (
        "set -o pipefail; timeout -k 10 %d %s 2>&1 | awk -v max=%d "
        "'{ print; fflush() } "
        "/^Time = / { n++; if (n > max) { print \"stopped by the test: "
        "more than \" max \" time steps (the time step collapsed)\"; "
        "exit 3 } }'; status=$?; "
        "if [ $status = 124 ]; then echo \"stopped by the test: timed out "
        "after %d s\"; fi; exit $status"
        % (timeout, cmd, max_steps, timeout))
    try:
        return fc.run(case, script, log=log, timeout=timeout + 60)
    except fc.FoamError:
        text = fc.tail(os.path.join(case, log), 400)
        raise fc.FoamError("%s in %s failed; last lines of %s:\n%s"
                           % (cmd, case, log, fc.tail(os.path.join(case, log),
                                                      25)),
                           summary="%s failed: %s"
                           % (cmd, fc.log_summary(text)))
