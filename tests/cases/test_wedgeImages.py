#!/usr/bin/python3
"""The second wedge face of an axisymmetric cell as the image of the first
(docs/numerics.md 7.2, discreteEquations wedgeImages).

Both sides of a wedge face hold the cell's state rotated into the face
plane, so the face's solution is the physical flux of that state (every
Riemann solver's consistency). The two wedge faces of a cell are images of
each other under the rotation Q = T_B T_A^T with the orientation reversed:
the solver solves the first and adds the second as its image (default), or
solves both (wedgeImages no, the code path before the images). The two are
the same discretisation; they differ by round-off only, in the order of
the sums and in the image point and frame of the second face.

Run: the taylorBar tutorial on 0.8 mm cells (45 x 13), 10 us (about 300
steps), fields every 2 us in ascii, once with the default and once with
wedgeImages no, and with the default on 2 processes (each processor pairs
the wedge faces of its own cells; its processor patches sit between the
wedge patches in the boundary list). A bad image (Q for Q^T, a lost sign of the traction, the
cobasis not rotated) changes the hoop terms, which are of the order of the
wedge angle times the stress, i.e. 1e-2 of the fields, at the first step
(Q^T for Q in the momentum image: the copper on the axis goes to -3e11 Pa
and the run keeps rejecting steps).

Checks
  wedgeImages_paired       the default run's log names the image pairing
                           ("Wedge faces: back as the image of front"), the
                           other run says the faces are each solved
  wedgeImages_fields       at every write, every field of the two runs
                           agrees within 1e-6 of the field's largest
                           magnitude. Round-off grows in this run to 4e-9
                           by 10 us (plastic work, at the cells that just
                           yield; the same bar serial against 2 processes
                           differs by 3.5e-10 at 20 us on 0.4 mm cells);
                           a bad image gives 1e-2 or breaks the run
  wedgeImages_profile      rodProfile's length and largest radius agree to
                           1e-9 relative at every write
  wedgeImages_parallel     the 2-process run pairs the faces too (its log)
                           and its reconstructed fields agree with the
                           serial run's within 1e-6 of each field's
                           magnitude at every write (the same round-off
                           argument)
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))

import numpy as np  # noqa: E402

import foamcase  # noqa: E402
from checks import Checks  # noqa: E402

H = 0.8  # mm
END = 10e-6
WRITE = 2e-6
FIELD_TOL = 1e-6
PROFILE_TOL = 1e-9
PAIRED = "Wedge faces: back as the image of front"


def log_says(case, text):
    """Whether the case's solver log holds the line text"""
    return text in open(os.path.join(case, "log.impactFoam")).read()


def run_case(name, images, np_=1):
    case = foamcase.copy_tutorial("taylorBar", name=name)
    foamcase.set_entry(case, "system/controlDict", "writeInterval", WRITE)
    foamcase.set_entry(case, "system/controlDict", "writeFormat", "ascii")
    if not images:
        foamcase.foam_dictionary(case, "system/fvSchemes",
                                 "discreteEquations/wedgeImages", "no")
    foamcase.run(case, ["./Allrun", "-h", str(H), "-end", str(END),
                        "-np", str(np_)],
                 log="log.Allrun", timeout=600)
    return case


def field_differences(a, b):
    """Largest difference of any field of case a from case b over a's
    writes, relative to the field's largest magnitude: (difference, where,
    fields compared, writes)"""
    times = [(t, n) for t, n in foamcase.time_dirs(a) if t > 0]
    worst, worstAt, compared = 0.0, "none", 0
    for t, n in times:
        nb = foamcase.find_time(b, t)
        for name in sorted(os.listdir(os.path.join(a, n))):
            if not os.path.isfile(os.path.join(a, n, name)):
                continue
            fa = np.asarray(foamcase.read_field(a, n, name), float)
            fb = np.asarray(foamcase.read_field(b, nb, name), float)
            scale = max(np.abs(fa).max(), 1e-300)
            d = np.abs(fa - fb).max()/scale
            compared += 1
            if d > worst or worstAt == "none":
                worst, worstAt = d, "%s at %.0f us" % (name, t*1e6)
    return worst, worstAt, compared, len(times)


def main():
    checks = Checks()
    foamcase.require_apps("impactFoam", "blockMesh", "setFields",
                          "rodProfile", "foamDictionary")
    a = run_case("wedgeImages_yes", True)
    b = run_case("wedgeImages_no", False)

    paired = log_says(a, PAIRED)
    solved = log_says(b, "Wedge faces: each solved (wedgeImages no)")
    checks.check("wedgeImages_paired", paired and solved,
                 "default run pairs the wedge faces: %s; wedgeImages no "
                 "solves each: %s" % (paired, solved))

    worst, worstAt, compared, writes = field_differences(a, b)
    checks.check("wedgeImages_fields",
                 compared > 0 and writes == round(END/WRITE)
                 and worst < FIELD_TOL,
                 "%d fields at %d writes; largest difference %.2e of the "
                 "field's magnitude (%s; bound %.0e)"
                 % (compared, writes, worst, worstAt, FIELD_TOL))

    def profile(case):
        path = os.path.join(case, "postProcessing", "rodProfile",
                            "copper.csv")
        return np.genfromtxt(path, delimiter=",", names=True)
    pa, pb = profile(a), profile(b)
    same_rows = len(pa) == len(pb) and len(pa) == writes + 1
    dL = np.abs(pa["length"] - pb["length"]).max()/pa["length"].max()
    dR = np.abs(pa["maxRadius"] - pb["maxRadius"]).max() \
        / pa["maxRadius"].max()
    checks.check("wedgeImages_profile",
                 same_rows and dL < PROFILE_TOL and dR < PROFILE_TOL,
                 "length %.4f mm, max radius %.4f mm at %.0f us; largest "
                 "relative differences %.1e (length), %.1e (radius); "
                 "bound %.0e"
                 % (pa["length"][-1]*1e3, pa["maxRadius"][-1]*1e3,
                    pa["t"][-1]*1e6, dL, dR, PROFILE_TOL))

    p = run_case("wedgeImages_parallel", True, np_=2)
    pairedP = log_says(p, PAIRED)
    worst, worstAt, compared, writes = field_differences(p, a)
    checks.check("wedgeImages_parallel",
                 pairedP and compared > 0 and writes == round(END/WRITE)
                 and worst < FIELD_TOL,
                 "2 processes pair the wedge faces: %s; %d fields at %d "
                 "writes against the serial run: largest difference %.2e of "
                 "the field's magnitude (%s; bound %.0e)"
                 % (pairedP, compared, writes, worst, worstAt, FIELD_TOL))
    checks.exit()


if __name__ == "__main__":
    main()
