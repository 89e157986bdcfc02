#!/usr/bin/python3
"""Restart from the latest time and function objects (the solver behaves as
OpenFOAM users expect).

The Favrie double impact (aluminium, 200 cells, t = 5e-5 s) runs once
straight through and once in two legs, the second started from the latest
time of the first (startFrom latestTime), fields every 1 us. The state is in
the written fields (alpha, rho, p.<phase>, U, A.<phase>, epsilonP,
plasticWork), written with 17 digits; only the energy is rebuilt from p,
e = e(rho, p), whose round trip loses about 1e-16 gamma pInf/p relative
(1e-11 for the aluminium at 1e5 Pa). So, four steps after the restart
(2.6e-5 s), both runs must agree within 1e-12 of each field's largest
magnitude (restart_equal): a field missing from the restart shows at the
1e-6 level or more. The difference at the end (5e-5 s, about 100 steps
later) is reported: the flow amplifies the round-off (to 4e-12 of U here;
2e-13 to 2e-12 with other write intervals or with the cobasis rotation
kept), which says nothing about the restart.

A fieldMinMax function object in controlDict must run during the solve and
write its table with the extremes of p.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "lib"))
import checks  # noqa: E402
import foamcase as fc  # noqa: E402

TUTORIAL = "favrieDoubleImpact"
FIELDS = ["alpha.aluminium", "rho.aluminium", "p.aluminium", "U",
          "A.aluminium", "sigma", "rho", "p"]
T_MID, T_NEAR, T_END = "2.5e-05", "2.6e-05", "5e-05"

FUNCTIONS = """
functions
{
    pRange
    {
        type            fieldMinMax;
        libs            ("libfieldFunctionObjects.so");
        fields          (p);
        writeControl    timeStep;
        writeInterval   1;
    }
}
"""


def prepare(name):
    case = fc.copy_tutorial(TUTORIAL, name)
    bm = os.path.join(case, "system", "blockMeshDict")
    text = open(bm).read().replace("nx      1000;", "nx      200;")
    open(bm, "w").write(text)
    cd = os.path.join(case, "system", "controlDict")
    text = open(cd).read()
    text = text.replace("writePrecision  12;", "writePrecision  17;")
    open(cd, "w").write(text + FUNCTIONS)
    fc.set_entry(case, "system/controlDict", "writeInterval", "1e-06")
    fc.run(case, ["blockMesh"])
    fc.run(case, ["cp", "-r", "0.orig", "0"], log="log.cp")
    fc.run(case, ["setFields"])
    return case


def main():
    c = checks.Checks()
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields")
    if missing:
        c.fail("restart_run", "not found on PATH: %s" % " ".join(missing))
        return c.exit()

    straight = prepare("restart_straight")
    fc.run(straight, ["impactFoam"])

    legs = prepare("restart_legs")
    fc.set_entry(legs, "system/controlDict", "endTime", T_MID)
    fc.run(legs, ["impactFoam"], log="log.impactFoam.1")
    fc.set_entry(legs, "system/controlDict", "endTime", T_END)
    fc.set_entry(legs, "system/controlDict", "startFrom", "latestTime")
    fc.run(legs, ["impactFoam"], log="log.impactFoam.2")
    restarted = fc.find_time(legs, float(T_MID)) is not None
    leg2 = open(os.path.join(legs, "log.impactFoam.2")).read()
    first_time = [l for l in leg2.splitlines() if l.startswith("Time = ")][:1]
    c.check("restart_latestTime", restarted and first_time
            and float(first_time[0].split()[2]) > float(T_MID),
            "second leg starts after %s: first step %s" % (T_MID, first_time))

    def difference(t):
        worst, worst_field = 0.0, None
        for f in FIELDS:
            a = fc.read_field(straight, t, f)
            b = fc.read_field(legs, t, f)
            scale = max(np.max(np.abs(a)), 1e-300)
            d = float(np.max(np.abs(a - b)) / scale)
            if d > worst:
                worst, worst_field = d, f
        return worst, worst_field

    worst, worst_field = difference(T_NEAR)
    end, end_field = difference(T_END)
    c.check("restart_equal", worst <= 1e-12,
            "largest difference at t = %s (4 steps after the restart) "
            "between one run and two legs: %.3e of the field's largest "
            "value (%s; bound 1e-12); at t = %s: %.3e (%s)"
            % (T_NEAR, worst, worst_field, T_END, end, end_field))

    table = None
    for root, _, files in os.walk(os.path.join(straight, "postProcessing",
                                               "pRange")):
        for f in files:
            if f.endswith(".dat"):
                table = os.path.join(root, f)
    rows = []
    if table:
        rows = [l for l in open(table) if l.strip() and not l.startswith("#")]
    p = fc.read_field(straight, T_END, "p")
    last = rows[-1].split() if rows else []
    nums = []
    for tok in last:
        try:
            nums.append(float(tok.strip("()")))
        except ValueError:
            pass
    ok = bool(rows) and nums and any(abs(v - p.max()) <= 1e-6 * abs(p.max())
                                      for v in nums)
    c.check("functionObject_fieldMinMax", ok,
            "%d rows in %s; max p at the end %.6e Pa, last row %s"
            % (len(rows), os.path.relpath(table, straight) if table else None,
               p.max(), " ".join(last[:8])))
    return c.exit()


if __name__ == "__main__":
    sys.exit(main())
