#!/usr/bin/python3
"""A pressure-relaxation path added by the recipe of docs/README.md is
followed (numerics.md 9, interfacePressure), also when it needs no payer.

The path is frozenVolume (tests/models, libimpactTestModels): the phase
keeps its specific volume through the relaxation and needs no payer. Case:
one closed planar cell (slip walls), half water at 1e7 Pa, half air at
1e5 Pa, at rest: in the first step no mass crosses a face, and the
phases' densities change by the relaxation alone.

Checks
  relaxationPath_setup     impactSetup starts each phase at its body's
                           pressure (0/p.water 1e7, 0/p.air 1e5 in the
                           mixed cell), not at the cell's mean
  relaxationPath_frozen    with `pressureRelaxation frozenVolume;` for the
                           water, after a step its density is that of the
                           start (1e-12), and so the air's (1e-9: the
                           interface pressure's solve), the water still
                           above 0.9e7 Pa
  relaxationPath_default   without it (constantPressure) the same step
                           relaxes: the water expands (its density falls by
                           more than 1e-3) and the two pressures end within
                           20 % of each other (the air follows its
                           isentrope and the water pays the difference)
  relaxationPath_energy    in both runs the log's total energy is unchanged
                           over the step (1e-12 of the water's internal
                           energy scale, p V)
About 5 s.
"""
import os
import re
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402

checks = Checks()
RUN = os.path.join(HERE, "..", "run", "relaxationPath")
H = 1e-3

IMPACT_DICT = """
geometry    planar;
domain
{
    min (0 0 0);  max (%(h)g %(h)g 0);  cellSize %(h)g;
    patches { xMin wall; xMax wall; yMin wall; yMax wall; }
}
ambient     { material air; p 1e5; T 293; }
bodies
{
    water { shape box; min (0 0 -1); max (%(half)g %(h)g 1); material water;
            p 1e7; rho 1000; }
}
outputs { energy { type energy; } }
%(extra)s
""" % {"h": H, "half": H / 2, "extra": "%s"}


def run(name, extra):
    case = os.path.join(RUN, name)
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(os.path.join(case, "system"))
    src = fc.tutorial_path("templates/projectileOnPlate")
    for f in ("controlDict", "fvSchemes", "fvSolution"):
        shutil.copy(os.path.join(src, "system", f),
                    os.path.join(case, "system", f))
    with open(os.path.join(case, "system", "controlDict"), "a") as f:
        f.write('\nlibs ("libimpactTestModels.so");\n')
    with open(os.path.join(case, "system", "impactDict"), "w") as f:
        f.write(IMPACT_DICT % extra)
    fc.run(case, ["impactSetup"])
    log = fc.run(case, ["impactFoam", "-endTime", "1e-9"])
    with open(log) as f:
        text = f.read()
    totals = [float(x) for x in re.findall(
        r"totals: mass \S+ kg, energy (\S+) J", text)]
    initial = float(re.search(r"Initial totals: mass \S+ kg, energy (\S+) J",
                              text).group(1))
    t = fc.latest_time(case)
    out = {ph: (fc.read_field(case, "0", "rho." + ph)[0],
                fc.read_field(case, t, "rho." + ph)[0],
                fc.read_field(case, t, "p." + ph)[0],
                fc.read_field(case, "0", "p." + ph)[0])
           for ph in ("water", "air")}
    return out, initial, totals[-1] if totals else None


def main():
    fc.require_apps("impactSetup", "impactFoam", "blockMesh")
    scale = 1e7 * H * H * H      # p V of the water, for the energy
    try:
        frozen, e0f, e1f = run("frozen", "phaseProperties { water "
                               "{ pressureRelaxation frozenVolume; } }")
        default, e0d, e1d = run("default", "")
    except fc.FoamError as e:
        checks.fail("relaxationPath_frozen", e.summary or str(e))
        checks.exit()
    start = (abs(default["water"][3] / 1e7 - 1), abs(default["air"][3] / 1e5
                                                     - 1))
    checks.check("relaxationPath_setup", max(start) <= 1e-12,
                 "impactSetup's 0/p.water %.10g Pa, 0/p.air %.10g Pa (each "
                 "its body's, not the cell's mean)"
                 % (default["water"][3], default["air"][3]))
    dw = abs(frozen["water"][1] / frozen["water"][0] - 1)
    da = abs(frozen["air"][1] / frozen["air"][0] - 1)
    checks.check("relaxationPath_frozen",
                 dw <= 1e-12 and da <= 1e-9 and frozen["water"][2] > 0.9e7,
                 "water density %.15g -> %.15g (%.1e), air %.1e; water at "
                 "%.4g Pa, air at %.4g Pa" % (frozen["water"][0],
                                              frozen["water"][1], dw, da,
                                              frozen["water"][2],
                                              frozen["air"][2]))
    dd = 1 - default["water"][1] / default["water"][0]
    dp = abs(default["water"][2] / default["air"][2] - 1)
    checks.check("relaxationPath_default", dd > 1e-3 and dp < 0.2,
                 "water density %.6g -> %.6g (%.2e); pressures water %.6g, "
                 "air %.6g Pa (%.2f apart: the air on its isentrope, the "
                 "difference paid by the water; bound 0.2)"
                 % (default["water"][0], default["water"][1], dd,
                    default["water"][2], default["air"][2], dp))
    errs = [abs(e1 - e0) / scale for e0, e1 in ((e0f, e1f), (e0d, e1d))
            if e1 is not None]
    checks.check("relaxationPath_energy", len(errs) == 2 and
                 max(errs) <= 1e-12,
                 "total energy change over the step, of p V: frozen %s, "
                 "default %s" % tuple("%.1e" % e for e in errs)
                 if len(errs) == 2 else "no totals line")
    checks.exit()


if __name__ == "__main__":
    main()
