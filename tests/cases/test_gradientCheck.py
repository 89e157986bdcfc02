#!/usr/bin/python3
"""The reconstruction's slopes of alpha, rho and p (cellLimitedGauss, on
plain arrays) against OpenFOAM's fvc::grad with "cellLimited Gauss linear 1"
(docs/numerics.md 5.1): the same values to the last bit, so that replacing
fvc::grad changed no result.

tests/tools/gradientCheck builds a field with kinks and jumps on the case's
mesh and compares the two gradients in every cell (maxDifference), and
with every other cell masked over the masked cells (maxDifferenceMasked;
the others must get zero, maskedNonZero); the two-field pass (a phase's
rho and p together) must give each field's single-pass gradient
(maxDifferencePair); limitedCells counts the cells where the limiter
acted, so that the check covers the limiter.

The same tool checks linearVelocityGradient::calculatePresent, the
gradient of a sliding phase's own velocity from the neighbours that hold
it (docs/numerics.md 9.3a): a phase on one side of a plane with a linear
velocity (a dilatation, plus a rotation where the mesh has no wedge),
a far-off constant beyond it that must not be read; in every cell that
holds it, limited or not, as exact as the mixture's gradient of the same
velocity linear everywhere (bound: its error + 1e-9 relative; both are
exact to round-off but in a wedge's cells on the axis), and the other
cells untouched; and the mixture's gradient within 1e-9 of the exact one
(1e-3 on the wedge, whose axis cells are not exact), in every direction
with extent: on a wedge its normal too, the hoop rate u_r/r. Meshes:
  wedge      the taylorBar tutorial's axisymmetric wedge (0.4 mm: wedge,
             wall, slip and axis patches), serial;
  parallel   the same on 2 processes (processor patches);
  box3D      a graded 3-D hex box with a symmetry plane and walls;
  scheme     the wedge with gradSchemes "Gauss linear": matches() must
             say no (MUSCLHancock then calls fvc::grad).
Bound: 0 (bit for bit). About 10 s.
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))

import foamcase  # noqa: E402
from checks import Checks  # noqa: E402

BOX = """FoamFile { version 2.0; format ascii; class dictionary;
           object blockMeshDict; }
scale 0.01;
vertices ( (0 0 0) (2 0 0) (2 1 0) (0 1 0)
           (0 0 1.5) (2 0 1.5) (2 1 1.5) (0 1 1.5) );
blocks ( hex (0 1 2 3 4 5 6 7) (14 9 11) simpleGrading (3 0.5 2) );
boundary
(
    sym   { type symmetryPlane; faces ( (0 4 7 3) ); }
    walls { type wall; faces ( (1 2 6 5) (0 1 5 4) (3 7 6 2)
                               (0 3 2 1) (4 5 6 7) ); }
);
"""


def check_output(log):
    text = open(log).read()
    vals = {}
    for key in ("matches", "cells", "maxAbsGradient", "maxDifference",
                "maxDifferenceMasked", "maskedNonZero",
                "maxDifferencePair", "limitedCells", "phaseCells",
                "phaseMaxError", "phaseMaxErrorLimited", "phaseUntouched",
                "mixtureMaxError"):
        m = re.search(r"^%s (\S+)" % key, text, re.M)
        vals[key] = float(m.group(1)) if m else None
    return vals


def main():
    checks = Checks()
    missing = foamcase.require_apps("gradientCheck", "blockMesh",
                                    "decomposePar")
    if missing:
        checks.fail("gradientCheck", "missing: %s" % ", ".join(missing))
        checks.exit()

    wedge = foamcase.copy_tutorial("taylorBar", "gradientCheck_wedge")
    foamcase.run(wedge, ["impactSetup"])

    box = os.path.join(foamcase.RUN_DIR, "gradientCheck_box3D")
    foamcase.copy_tutorial("taylorBar", "gradientCheck_box3D")
    with open(os.path.join(box, "system", "blockMeshDict"), "w") as f:
        f.write(BOX)
    foamcase.run(box, ["blockMesh"])

    results = {}
    results["wedge"] = check_output(
        foamcase.run(wedge, ["gradientCheck"]))
    foamcase.write_decompose_dict(wedge, 2)
    foamcase.run(wedge, ["decomposePar", "-force"])
    results["parallel"] = check_output(foamcase.run(
        wedge, "mpirun -np 2 --oversubscribe gradientCheck -parallel",
        log="log.gradientCheck.parallel"))
    results["box3D"] = check_output(foamcase.run(box, ["gradientCheck"]))

    for name, v in results.items():
        ok = (
            v["matches"] == 1 and v["maxDifference"] == 0
            and v["maxDifferenceMasked"] == 0 and v["limitedCells"] > 0
            and v["maskedNonZero"] == 0 and v["maxDifferencePair"] == 0
        )
        checks.check(
            "gradientCheck_" + name, ok,
            "%d cells, %d limited: largest |fvc::grad - cellLimitedGauss| "
            "%g (masked %g, %d masked-out cells not zero; two-field pass "
            "against single passes %g) on gradients up to %.3g (bound 0)"
            % (v["cells"] or -1, v["limitedCells"] or -1,
               v["maxDifference"], v["maxDifferenceMasked"],
               int(v["maskedNonZero"] if v["maskedNonZero"] is not None else -1),
               v["maxDifferencePair"],
               v["maxAbsGradient"] or 0))

    for name, v in results.items():
        err = max(v["phaseMaxError"] if v["phaseMaxError"] is not None else 1,
                  v["phaseMaxErrorLimited"]
                  if v["phaseMaxErrorLimited"] is not None else 1)
        bound = (v["mixtureMaxError"] if v["mixtureMaxError"] is not None
                 else -1) + 1e-9
        checks.check(
            "gradientCheck_phase_" + name,
            (v["phaseCells"] or 0) > 0 and err < bound
            and v["phaseUntouched"] == 1,
            "a phase's own velocity gradient over the %d cells that hold "
            "it: largest relative error %g unlimited, %g limited (bound "
            "%g: the mixture's gradient's %g + 1e-9); other cells "
            "untouched: %s"
            % (v["phaseCells"] or -1, v["phaseMaxError"],
               v["phaseMaxErrorLimited"], bound, v["mixtureMaxError"],
               v["phaseUntouched"] == 1))

    # The mixture's gradient itself against the exact one, in every
    # direction with extent: on the wedge its normal too, whose derivative
    # is the hoop rate u_r/r (completed as if empty it came out halved,
    # 0.29 relative); the wedge's cells on the axis are not exact
    for name, v in results.items():
        bound = 1e-3 if name in ("wedge", "parallel") else 1e-9
        err = v["mixtureMaxError"]
        checks.check(
            "gradientCheck_mixture_" + name,
            err is not None and err <= bound,
            "the velocity gradient of u = a x%s against the exact one "
            "(the hoop rate included on a wedge): largest relative error "
            "%s (bound %g)"
            % ("" if name in ("wedge", "parallel") else " + b e x x",
               err, bound))

    schemes = os.path.join(wedge, "system", "fvSchemes")
    text = open(schemes).read()
    open(schemes, "w").write(text.replace(
        "default         cellLimited Gauss linear 1;",
        "default         Gauss linear;"))
    v = check_output(foamcase.run(wedge, ["gradientCheck"],
                                  log="log.gradientCheck.scheme"))
    checks.check("gradientCheck_scheme", v["matches"] == 0,
                 "gradSchemes Gauss linear: matches %s (must be 0: "
                 "fvc::grad is used)" % v["matches"])
    checks.exit()


if __name__ == "__main__":
    main()
