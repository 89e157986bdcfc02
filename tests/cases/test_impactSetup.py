#!/usr/bin/python3
"""impactSetup (docs/impactSetup.md): exact volume fractions, the errors
on bad input, and the fields of a tutorial set up from one dictionary.

Volumes: each shape (sphere, cylinder turned off the mesh axes, cone,
truncated cone, tangent ogive nose, box turned about (1 1 1), union of a
cylinder and a cone, a closed STL polyhedron, half-space) about 10 cells
across, off the grid, in three geometries: threeD (hex mesh), planar (hex 2-D, one cell in
z) and axisymmetric (2-degree wedge). The volume on the mesh is measured
here from the written alpha.<phase> and the cell volumes of the mesh
(meshGeometry.py): sum alpha V; on the wedge, times 2 pi/sin(2 deg) (a
flat-faced wedge cell of angle 2 theta holds sin(2 theta)/(2 pi) of the
ring it stands for); planar, divided by the depth. Exact volumes are the
closed forms (the STL's: its polyhedron's, by the divergence theorem).

Checks
  impactSetup_volume_<geometry>_<shape>   |V_mesh/V_exact - 1| < 1e-3 at
                    10 cells across, and smaller when h halves (or below
                    1e-9 on both meshes: boxes and half-spaces are
                    clipped exactly)
  impactSetup_error_<what>   a bad impactDict stops with the message
                    naming the body or entry (asserted on the text): unknown
                    keyword (body, domain, ambient, top level, gap), unknown
                    shape, missing dimension, an ogive too blunt (crh
                    below 1/2), overlapping bodies, body wholly and partly
                    outside, unknown material (with the list),
                    two materials in one phase, gap to an unknown body,
                    cuts naming no earlier body, radialVelocity with U,
                    a misspelled or bad radialVelocity entry
  impactSetup_radialVelocity   a sphere shell with radialVelocity
                    { U -600; radius 8e-3; exponent -2; } in still air:
                    in every cell the shell fills, U equals
                    -600 (8 mm/r)^2 along r at the cell centre (1e-9:
                    the files hold 10 digits),
                    and U is 0 where only air is
  impactSetup_cuts  a later box declaring cuts (earlier) takes the
                    earlier's volume where they overlap: the earlier's
                    volume is its own less the common part, the sum of the
                    fractions stays 1
  impactSetup_error_material_<what>  an error in a case's material file
                    (a missing and a misspelled keyword of its equation of
                    state) names that file and lines that hold the error
  impactSetup_variables  a top-level entry used as $name (rodU, the rod's U)
                    is read into the body and dropped; impactSetup_error_
                    unusedVariable: an entry nobody uses stops as unknown
  impactSetup_gap   a sphere placed by a gap of 0.7 mm from a half-space
                    sits 0.7 mm from it (its volume's centre measured from
                    alpha)
  impactSetup_copperRodImpact   two copper rods (phase copper, the
                    tutorial's copper as constant/materials/copperTaylor),
                    +-227 m/s, air rho 1.2, p 1e5, on impactSetup's mesh of
                    the tutorial's extent and cell size, give the same
                    alpha.copper, alpha.air, U, rho.copper, rho.air and p
                    as setFields with cylinderToCell on the same mesh
                    (cells aligned: differences below 1e-9)
  impactSetup_rerun  a second run with another cellSize and the phase
                    renamed rewrites its own files (new cell count in every
                    field) and removes the old phase's
  impactSetup_noOverwrite  a user's 0/U (no impactSetup mark) and a mesh
                    not made by impactSetup stop it, naming the file
  impactSetup_existingMesh  without a domain the case's mesh (the
                    tutorial's) is used as it is: the rods' volume on it
                    within 1e-6 of 2 pi R^2 L, no blockMeshDict written
  impactSetup_unstructured_<geometry>  without a domain, on jittered
                    triangular prisms (planar, a disc) and tetrahedra
                    (threeD, a ball) 10 grid spacings across: volume within
                    1e-3
  impactSetup_template  the projectileOnPlate template at 1 mm cells:
                    impactSetup, then impactFoam runs 0.1 us
"""
import math
import os
import re
import shutil
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
import meshGeometry as mg                     # noqa: E402
import triMesh                                # noqa: E402
from checks import Checks                     # noqa: E402

checks = Checks()
RUN = os.path.join(HERE, "..", "run", "impactSetup")
SYSTEM_FROM = "hypervelocityImpact"   # controlDict, fvSchemes, fvSolution
H0 = 1e-3                         # coarse cell size; shapes are ~10 H0 across
PI = math.pi


def new_case(name, impact_dict, materials=None):
    case = os.path.join(RUN, name)
    if os.path.lexists(case):
        shutil.rmtree(case)
    os.makedirs(os.path.join(case, "system"))
    os.makedirs(os.path.join(case, "constant"))
    src = fc.tutorial_path(SYSTEM_FROM)
    for f in ("controlDict", "fvSchemes", "fvSolution"):
        shutil.copy(os.path.join(src, "system", f),
                    os.path.join(case, "system", f))
    with open(os.path.join(case, "system", "impactDict"), "w") as f:
        f.write(impact_dict)
    for mat, text in (materials or {}).items():
        os.makedirs(os.path.join(case, "constant", "materials"),
                    exist_ok=True)
        with open(os.path.join(case, "constant", "materials", mat), "w") as f:
            f.write(text)
    return case


def run_setup(case, check=True):
    log = fc.run(case, ["impactSetup"], check=check)
    with open(log) as f:
        return f.read()


# --------------------------------------------------------------------------
# Shapes and their exact volumes, in units of H0 (scaled when written)
# --------------------------------------------------------------------------

def vec(v, s):
    return "(%s)" % " ".join("%.12g" % (x * s) for x in v)


def stl_sphere(path, centre, radius, n_theta=12, n_phi=24):
    """A closed triangulated sphere (ASCII STL); returns its volume."""
    c = np.array(centre, float)

    def p(i, j):
        th = PI * i / n_theta
        ph = 2 * PI * j / n_phi
        if i == 0 or i == n_theta:
            j = 0
        return c + radius * np.array([math.sin(th) * math.cos(ph),
                                      math.sin(th) * math.sin(ph),
                                      math.cos(th)])
    tris = []
    for i in range(n_theta):
        for j in range(n_phi):
            a, b = p(i, j), p(i, j + 1)
            d, e = p(i + 1, j), p(i + 1, j + 1)
            if i > 0:
                tris.append((a, d, b))
            if i < n_theta - 1:
                tris.append((b, d, e))
    vol = 0.0
    with open(path, "w") as f:
        f.write("solid sphere\n")
        for t in tris:
            n = np.cross(t[1] - t[0], t[2] - t[0])
            f.write(" facet normal %g %g %g\n  outer loop\n" % tuple(n))
            for q in t:
                f.write("   vertex %.15g %.15g %.15g\n" % tuple(q))
            f.write("  endloop\n endfacet\n")
            vol += np.dot(t[0], np.cross(t[1], t[2])) / 6.0
        f.write("endsolid sphere\n")
    return abs(vol)


def cone_volume(L, R0, R1):
    return PI * L * (R0 * R0 + R0 * R1 + R1 * R1) / 3.0


def ogive_volumes(a, crh):
    """(solid of revolution, section area) of a tangent ogive nose of
    radius a: the arc of radius S = 2 crh a centred at a - S from the axis
    on the base's plane; rho(s) = sqrt(S^2 - s^2) - (S - a) on [0, l]."""
    S = 2 * crh * a
    c = S - a
    ln = math.sqrt(S * S - c * c)
    arc = S * S * math.asin(ln / S)
    return PI * (S * S * ln - ln ** 3 / 3 - c * arc), arc - c * ln


def bodies_threeD(case, s):
    """(impactDict bodies text, {phase: exact volume}) at scale s (= H0)."""
    os.makedirs(os.path.join(case, "constant", "triSurface"), exist_ok=True)
    v_stl = stl_sphere(os.path.join(case, "constant", "triSurface",
                                    "ball.stl"), (40.3, 24.2, 8.1), 5.0)
    text = """
    sphere   { shape sphere; centre %s; radius %g; }
    cylinder { shape cylinder; base %s; axis (1 0.3 0.2); length %g;
               radius %g; }
    cone     { shape cone; base %s; axis (0 1 0); length %g; radius %g; }
    frustum  { shape cone; base %s; axis (0.2 1 -0.1); length %g;
               radius %g; topRadius %g; }
    box      { shape box; min %s; max %s; angle 30; rotationAxis (1 1 1); }
    union    { shape union; shapes
               { shank { shape cylinder; base %s; axis (1 0 0);
                         length %g; radius %g; }
                 nose  { shape cone; base %s; axis (1 0 0); length %g;
                         radius %g; } } }
    stl      { shape stl; file "constant/triSurface/ball.stl"; scale %g; }
    ogive    { shape ogive; base %s; axis (1 0.2 0.1); radius %g; crh 1; }
    halfSpace { shape halfSpace; point %s; normal (-1 0 0); }
""" % (vec((8.3, 8.2, 8.1), s), 5 * s,
       vec((19.3, 5.2, 6.1), s), 9 * s, 5 * s,
       vec((40.2, 3.3, 8.1), s), 10 * s, 5 * s,
       vec((56.1, 3.2, 8.2), s), 10 * s, 5 * s, 2.5 * s,
       vec((3.8, 19.7, 3.6), s), vec((11.8, 27.7, 11.6), s),
       vec((19.2, 24.1, 8.1), s), 6 * s, 5 * s,
       vec((25.2, 24.1, 8.1), s), 5 * s, 5 * s,
       s, vec((47.2, 24.1, 8.1), s), 4 * s, vec((62.3, 0, 0), s))
    exact = {
        "sphere": 4 * PI * 125 / 3,
        "cylinder": PI * 25 * 9,
        "ogive": ogive_volumes(4, 1)[0],
        "cone": cone_volume(10, 5, 0),
        "frustum": cone_volume(10, 5, 2.5),
        "box": 8.0 ** 3,
        "union": PI * 25 * 6 + cone_volume(5, 5, 0),
        "stl": v_stl,
        "halfSpace": (64 - 62.3) * 32 * 16,
    }
    return text, {k: v * s ** 3 for k, v in exact.items()}, \
        ((0, 0, 0), (64, 32, 16))


def bodies_planar(case, s):
    text = """
    disc     { shape sphere; centre %s; radius %g; }
    rectangle { shape cylinder; base %s; axis (1 0.3 0); length %g;
               radius %g; }
    rod      { shape cylinder; base %s; axis (0 0 1); length %g; radius %g; }
    trapezium { shape cone; base %s; axis (0.2 1 0); length %g; radius %g;
               topRadius %g; }
    box      { shape box; min %s; max %s; angle 30; }
    union    { shape union; shapes
               { shank { shape cylinder; base %s; axis (1 0 0);
                         length %g; radius %g; }
                 nose  { shape cone; base %s; axis (1 0 0); length %g;
                         radius %g; } } }
    ogive    { shape ogive; base %s; axis (1 0.2 0); radius %g; crh 1; }
    halfSpace { shape halfSpace; point %s; normal (-1 0 0); }
""" % (vec((8.3, 8.2, 0), s), 5 * s,
       vec((19.3, 5.2, 0), s), 9 * s, 5 * s,
       vec((40.3, 8.1, -1), s), 2 * s, 5 * s,
       vec((56.1, 3.2, 0), s), 10 * s, 5 * s, 2.5 * s,
       vec((3.8, 19.7, -1), s), vec((11.8, 27.7, 1), s),
       vec((19.2, 24.1, 0), s), 6 * s, 5 * s,
       vec((25.2, 24.1, 0), s), 5 * s, 5 * s,
       vec((40.2, 24.1, 0), s), 4 * s,
       vec((62.3, 0, 0), s))
    exact = {
        "disc": PI * 25, "rectangle": 10 * 9, "rod": PI * 25,
        "ogive": ogive_volumes(4, 1)[1],
        "trapezium": (5 + 2.5) * 10, "box": 64.0,
        "union": 10 * 6 + 5 * 5, "halfSpace": (64 - 62.3) * 32,
    }
    return text, {k: v * s ** 2 for k, v in exact.items()}, \
        ((0, 0, 0), (64, 32, 0))


def bodies_axisymmetric(case, s):
    text = """
    sphere   { shape sphere; centre %s; radius %g; }
    cylinder { shape cylinder; base %s; axis (1 0 0); length %g; radius %g; }
    cone     { shape cone; base %s; axis (1 0 0); length %g; radius %g; }
    frustum  { shape cone; base %s; axis (-1 0 0); length %g; radius %g;
               topRadius %g; }
    ring     { shape box; min %s; max %s; }
    union    { shape union; shapes
               { shank { shape cylinder; base %s; axis (1 0 0);
                         length %g; radius %g; }
                 nose  { shape cone; base %s; axis (1 0 0); length %g;
                         radius %g; } } }
    ogive    { shape ogive; base %s; axis (1 0 0); radius %g; crh 1; }
    halfSpace { shape halfSpace; point %s; normal (-1 0 0); }
""" % (vec((8.3, 0, 0), s), 5 * s,
       vec((16.2, 0, 0), s), 9.3 * s, 5 * s,
       vec((28.3, 0, 0), s), 10 * s, 5 * s,
       vec((51.1, 0, 0), s), 10 * s, 5 * s, 2.5 * s,
       vec((54.2, 3.3, -1), s), vec((62.2, 12.4, 1), s),
       vec((65.3, 0, 0), s), 5 * s, 5 * s,
       vec((70.3, 0, 0), s), 5 * s, 5 * s,
       vec((78.3, 0, 0), s), 4 * s,
       vec((90.3, 0, 0), s))
    exact = {
        "sphere": 4 * PI * 125 / 3, "cylinder": PI * 25 * 9.3,
        "cone": cone_volume(10, 5, 0), "frustum": cone_volume(10, 5, 2.5),
        "ring": PI * (12.4 ** 2 - 3.3 ** 2) * 8,
        "union": PI * 25 * 5 + cone_volume(5, 5, 0),
        "ogive": ogive_volumes(4, 1)[0],
        "halfSpace": PI * 16 ** 2 * (92 - 90.3),
    }
    return text, {k: v * s ** 3 for k, v in exact.items()}, \
        ((0, 0, 0), (92, 16, 0))


def volume_dict(geometry, bodies, lo, hi, h):
    """impactDict with every body its own phase (named as the body) of
    steel4340 at rho 7850 in air."""
    body_text = ""
    for line in bodies.strip("\n").split("\n"):
        words = line.split()
        if len(words) > 1 and words[1] == "{" \
                and len(line) - len(line.lstrip()) == 4:
            line = line.replace("{", "{ material steel4340; phase %s; "
                                "rho 7850;" % words[0], 1)
        body_text += line + "\n"
    return """geometry %s;
domain { min %s; max %s; cellSize %.12g; }
ambient { material air; rho 1.2; }
bodies
{
%s}
""" % (geometry, vec(lo, H0), vec(hi, H0), h, body_text)


def measured_volumes(case, phases, geometry):
    m = mg.read_polymesh(case)
    V = m.V.copy()
    if geometry == "axisymmetric":
        p = m.points[np.argmax(m.points[:, 1])]
        theta = math.atan2(abs(p[2]), p[1])            # half angle
        V *= 2 * PI / math.sin(2 * theta)
    elif geometry == "planar":
        V /= m.points[:, 2].max() - m.points[:, 2].min()
    out = {}
    for ph in phases:
        a = fc.read_field(case, "0", "alpha." + ph, m.nCells)
        out[ph] = float(np.sum(a * V))
    return out


def check_volumes():
    for geometry, maker in (("planar", bodies_planar),
                            ("axisymmetric", bodies_axisymmetric),
                            ("threeD", bodies_threeD)):
        errors = {}
        for level, h in enumerate((H0, H0 / 2)):
            case = new_case("volume_%s_%d" % (geometry, level), "")
            bodies, exact, (lo, hi) = maker(case, H0)
            with open(os.path.join(case, "system", "impactDict"), "w") as f:
                f.write(volume_dict(geometry, bodies, lo, hi, h))
            try:
                run_setup(case)
            except fc.FoamError as e:
                checks.fail("impactSetup_volume_%s" % geometry, e.summary
                            or str(e))
                break
            measured = measured_volumes(case, exact.keys(), geometry)
            for k in exact:
                errors.setdefault(k, []).append(measured[k] / exact[k] - 1)
        for k, e in errors.items():
            if len(e) < 2:
                continue
            ok = abs(e[0]) < 1e-3 and (abs(e[1]) < abs(e[0])
                                       or max(abs(e[0]), abs(e[1])) < 1e-9)
            checks.check("impactSetup_volume_%s_%s" % (geometry, k), ok,
                         "relative volume error %.2e at 10 cells across, "
                         "%.2e at 20 (limit 1e-3, falling)" % (e[0], e[1]))


# --------------------------------------------------------------------------
# Bad input
# --------------------------------------------------------------------------

BASE = """geometry axisymmetric;
domain { min (-10e-3 0 0); max (10e-3 8e-3 0); cellSize 0.5e-3;
         patches { xMin wall; xMax open; yMax wall; } }
ambient { material air; p 1e5; T 293; }
bodies
{
    rod    { shape cylinder; base (0.5e-3 0 0); axis (1 0 0);
             length 6e-3; radius 2e-3; material tungstenAlloy;
             U (-1500 0 0); T 293; }
    target { shape box; min (-8e-3 0 -1); max (0 6e-3 1);
             material steel4340; }
}
"""

BAD = [
    ("bodyKeyword", ("radius 2e-3", "radis 2e-3"),
     ["Body rod", "radis", "did you mean radius"]),
    ("topKeyword", ("ambient {", "ambiant {"),
     ["ambiant", "did you mean ambient"]),
    ("domainKeyword", ("cellSize 0.5e-3", "cellsize 0.5e-3"),
     ["domain", "cellsize", "did you mean cellSize"]),
    ("ambientKeyword", ("p 1e5; T 293; }", "p 1e5; Temp 293; }"),
     ["ambient", "Temp", "did you mean"]),
    ("patchKind", ("xMax open", "xMax opne"),
     ["unknown kind opne", "did you mean open"]),
    ("unknownShape", ("shape cylinder", "shape cylindr"),
     ["Body rod", "unknown shape cylindr", "did you mean cylinder"]),
    ("missingDimension", ("length 6e-3; radius 2e-3;", "length 6e-3;"),
     ["Body rod", "shape cylinder needs the entry radius"]),
    ("overlap", ("base (0.5e-3 0 0)", "base (-0.5e-3 0 0)"),
     ["Body target overlaps body rod", "cuts (rod)"]),
    ("whollyOutside", ("base (0.5e-3 0 0)", "base (20e-3 0 0)"),
     ["Body rod lies wholly outside the domain"]),
    ("partlyOutside", ("base (0.5e-3 0 0)", "base (6e-3 0 0)"),
     ["Body rod lies partly outside the domain", "patch xMax"]),
    ("unknownMaterial", ("material tungstenAlloy", "material tungstenAloy"),
     ["Body rod", "unknown material tungstenAloy", "Available materials",
      "tungstenAlloy"]),
    ("twoMaterials", ("material steel4340;", "material steel4340; phase "
                      "metal;"),
     None),
    ("gapUnknown", ("T 293; }\n    target", "T 293; gap { to plate; "
                    "distance 1e-3; } }\n    target"),
     ["Body rod, gap: unknown body plate", "target"]),
    ("gapKeyword", ("T 293; }\n    target", "T 293; gap { to target; "
                    "distanse 1e-3; } }\n    target"),
     ["Body rod, gap", "distanse", "did you mean distance"]),
    ("cutsUnknown", ("material steel4340; }", "material steel4340; "
                     "cuts (rods); }"),
     ["Body target", "cuts names rods", "not an earlier body"]),
    ("radialAndU", ("T 293; }\n    target", "T 293; radialVelocity { "
                    "centre (0 0 0); U -100; radius 1e-3; } }\n    target"),
     ["Body rod: give either U or radialVelocity, not both"]),
    ("radialKeyword", ("U (-1500 0 0); T 293;", "T 293; radialVelocity { "
                       "centre (0 0 0); U -100; radius 1e-3; exponnt -2; }"),
     ["Body rod, radialVelocity", "exponnt", "did you mean exponent"]),
    ("contactPhase", ("bodies\n{", "contacts { tungstenAlloy.steel434 "
                      "frictionless; }\nbodies\n{"),
     ["contacts", "names steel434", "nearest: steel4340"]),
    ("contactFluid", ("bodies\n{", "contacts { tungstenAlloy.air "
                      "frictionless; }\nbodies\n{"),
     ["contacts", "two different solid phases", "air fluid"]),
    ("contactLaw", ("bodies\n{", "contacts { default slippery; }"
                    "\nbodies\n{"),
     ["unknown contact law slippery", "coulomb", "frictionless"]),
    ("contactMu", ("bodies\n{", "contacts { default { type coulomb; } }"
                   "\nbodies\n{"),
     ["coulomb needs its friction coefficient mu"]),
    ("ogiveCrh", ("shape cylinder; base (0.5e-3 0 0); axis (1 0 0);\n"
                  "             length 6e-3;",
                  "shape ogive; base (0.5e-3 0 0); axis (1 0 0); crh 0.3;"),
     ["Body rod", "entry crh 0.3 must be at least 0.5"]),
    ("radialRadius", ("U (-1500 0 0); T 293;", "T 293; radialVelocity { "
                      "centre (0 0 0); U -100; radius 0; }"),
     ["Body rod, radialVelocity: radius 0 must be positive"]),
]


def check_errors():
    for name, (old, new), expect in BAD:
        text = BASE
        if name == "twoMaterials":
            # two bodies of phase metal with different materials
            text = BASE.replace("material tungstenAlloy;",
                                "material tungstenAlloy; phase metal;")
            text = text.replace("material steel4340;",
                                "material steel4340; phase metal;")
            expect = ["Body target", "phase metal has material steel4340",
                      "Body rod gives it material tungstenAlloy"]
        else:
            if old not in text:
                checks.fail("impactSetup_error_" + name,
                            "test set-up: %r not in the base" % old)
                continue
            text = text.replace(old, new, 1)
        case = new_case("error_" + name, text)
        log = run_setup(case, check=False)
        fatal = "FOAM FATAL" in log
        missing = [e for e in expect if e not in log]
        msg = log[log.find("FOAM FATAL"):].split("\n")[1:3] if fatal else \
            ["no FOAM FATAL"]
        checks.check("impactSetup_error_" + name, fatal and not missing,
                     ("missing %s; " % missing if missing else "")
                     + " ".join(msg)[:300])


def check_material_errors():
    """An error in a case's material file names that file and the lines of
    the entry at fault: a missing keyword of its equation of state, and a
    misspelled one"""
    lib = os.path.join(os.environ["IMPACTFOAM_DIR"], "etc", "materials",
                       "steel4340")
    with open(lib) as f:
        steel = f.read()
    for name, (old, new), expect in (
            ("missing", (r"\bGamma0\b", "Gama0"),
             ["needs the keyword Gamma0", "equationOfState"]),
            ("keyword", (r"\bGamma0(\s+[^;]+;)", r"Gamma0\1 rhoo 1;"),
             ["rhoo"])):
        text, n = re.subn(old, new, steel, count=1)
        if n != 1:
            checks.fail("impactSetup_error_material_" + name,
                        "test set-up: no %s in etc/materials/steel4340" % old)
            continue
        # The line of the change in the material file
        marker = "Gama0" if name == "missing" else "rhoo"
        line = text[:text.index(marker)].count("\n") + 1
        case = new_case("error_material_" + name,
                        BASE.replace("material steel4340;",
                                     "material myPlate;"),
                        materials={"myPlate": text})
        log = run_setup(case, check=False)
        fatal = log[log.find("FOAM FATAL"):] if "FOAM FATAL" in log else ""
        m = re.search(r"(?:file|in file): (\S+?)(?:\.equationOfState)?"
                      r"(?: at line (\d+)| from line (\d+) to line (\d+))",
                      fatal)
        ok = bool(fatal) and all(e in fatal for e in expect) and m \
            and m.group(1).endswith("constant/materials/myPlate")
        if ok:
            lo = int(m.group(2) or m.group(3))
            hi = int(m.group(2) or m.group(4))
            ok = lo <= line <= hi + 1
        checks.check("impactSetup_error_material_" + name, ok,
                     "the change at line %d of constant/materials/myPlate: "
                     "%s" % (line, " ".join(fatal.split("\n")[1:3])[:300]
                             if fatal else "no FOAM FATAL"))


def check_radial_velocity():
    text = """geometry axisymmetric;
domain { min (0 0 0); max (12e-3 12e-3 0); cellSize 0.5e-3;
         patches { xMin symmetry; xMax open; yMax open; } }
ambient { material air; p 1e5; T 293; phase gas; }
bodies
{
    shell { shape sphere; centre (0 0 0); radius 10e-3;
            material steel4340; phase shell; rho 7810;
            radialVelocity { centre (0 0 0); U -600; radius 8e-3;
                             exponent -2; } }
    inside { shape sphere; centre (0 0 0); radius 8e-3; material air;
             phase gas; T 293; cuts (shell); }
}
"""
    case = new_case("radialVelocity", text)
    run_setup(case)
    C = fc.cell_centres(case)
    U = fc.read_field(case, "0", "U")
    alpha = fc.read_field(case, "0", "alpha.shell")
    r = np.sqrt((C**2).sum(axis=1))
    full = alpha >= 1 - 1e-12
    air = alpha <= 1e-12
    exact = (-600*(8e-3/r[full])**2/r[full])[:, None]*C[full]
    err = abs(U[full] - exact).max()/600 if full.any() else float("nan")
    still = abs(U[air]).max() if air.any() else float("nan")
    checks.check("impactSetup_radialVelocity",
                 full.sum() > 50 and err <= 1e-9 and still == 0,
                 "%d cells full of the shell: U within %.2e of -600 "
                 "(8 mm/r)^2 at the centre (relative; bound 1e-9: U and the "
                 "centres are written with 10 digits); air "
                 "cells' largest speed %.3g" % (full.sum(), err, still))


def check_warnings():
    """A body too few cells across (a cell size in millimetres typed for
    metres), a solid without failure at speed: warned, not stopped; and
    neither warning where it does not apply."""
    text = """geometry axisymmetric;
domain { min (-4e-3 0 0); max (4e-3 4e-3 0); cellSize CELL;
         patches { xMin wall; xMax open; yMax open; } }
ambient { material air; p 1e5; T 293; }
bodies
{
    rod { shape cylinder; base (0.5e-3 0 0); axis (1 0 0); length 3e-3;
          radius 1e-3; material tungstenAlloy; U (-SPEED 0 0); T 293; }
    plate { shape box; min (-4e-3 0 -1); max (0 4e-3 1);
            material steel4340; T 293; }
}
"""
    cases = (("coarse", "1e-3", "500", True, False),
             ("fast", "0.25e-3", "4000", False, True),
             ("neither", "0.25e-3", "500", False, False))
    for name, h, v, coarse, fast in cases:
        case = new_case("warn_" + name,
                        text.replace("CELL", h).replace("SPEED", v))
        log = run_setup(case, check=False)
        written = "FOAM FATAL" not in log and os.path.isfile(
            os.path.join(case, "0", "alpha.tungstenAlloy"))
        w_cells = "Body rod is 1 cells across its smallest extent" in log
        w_fail = ("Phase tungstenAlloy (material tungstenAlloy) is a solid "
                  "without a failure model, and bodies meet at 4000 m/s"
                  in log)
        # steel4340 has its Johnson-Cook failure: never warned
        w_steel = "Phase steel4340 (material steel4340) is a solid" in log
        # the plate reaches the open patch yMax; the rod's tail is 0.5 mm
        # from xMax: within 1.5 cells of 1 mm, not of 0.25 mm
        w_plate = ("Body plate lies within a cell of the open patch yMax"
                   in log)
        w_rod = "Body rod lies within a cell of the open patch xMax" in log
        ok = (written and w_cells == coarse and w_fail == fast
              and not w_steel and w_plate and w_rod == coarse)
        checks.check("impactSetup_warn_" + name, ok,
                     "cellSize %s m, %s m/s: files written %s; warned of "
                     "too few cells %s (expected %s), of no failure model "
                     "%s (expected %s), of steel's %s (expected False), of "
                     "the plate at open yMax %s (expected True), of the rod "
                     "near open xMax %s (expected %s)"
                     % (h, v, written, w_cells, coarse, w_fail, fast,
                        w_steel, w_plate, w_rod, coarse))


def check_cuts_and_gap():
    # Two boxes overlapping by 2 x 2 x 1 mm^3 (planar, per unit depth:
    # 2 x 2 mm^2); the later one cuts the earlier
    text = """geometry planar;
domain { min (0 0 0); max (10e-3 10e-3 0); cellSize 0.5e-3; }
ambient { material air; rho 1.2; }
bodies
{
    a { shape box; min (1.1e-3 1.1e-3 -1) max (5.1e-3 5.1e-3 1);
        material steel4340; phase a; rho 7850; }
    b { shape box; min (3.1e-3 3.1e-3 -1) max (7.1e-3 7.1e-3 1);
        material steel4340; phase b; rho 7850; cuts (a); }
}
""".replace("-1) max", "-1); max")
    case = new_case("cuts", text)
    try:
        run_setup(case)
        vol = measured_volumes(case, ["a", "b"], "planar")
        m = mg.read_polymesh(case)
        total = sum(fc.read_field(case, "0", "alpha." + ph, m.nCells)
                    for ph in ("a", "b", "air"))
        ea = vol["a"] / (16e-6 - 4e-6) - 1
        eb = vol["b"] / 16e-6 - 1
        checks.check("impactSetup_cuts",
                     abs(ea) < 1e-5 and abs(eb) < 1e-5
                     and np.abs(total - 1).max() < 1e-12,
                     "earlier box %.2e, later box %.2e off their volumes; "
                     "max |sum alpha - 1| %.1e"
                     % (ea, eb, np.abs(total - 1).max()))
    except fc.FoamError as e:
        checks.fail("impactSetup_cuts", e.summary or str(e))

    # A sphere 0.7 mm from a half-space x < 0, moving towards it
    R, gap = 2e-3, 0.7e-3
    text = """geometry axisymmetric;
domain { min (-5e-3 0 0); max (10e-3 5e-3 0); cellSize 0.1e-3; }
ambient { material air; rho 1.2; }
bodies
{
    ball   { shape sphere; centre (5e-3 0 0); radius 2e-3;
             material steel4340; phase ball; rho 7850; U (-500 0 0);
             gap { to target; distance 0.7e-3; } }
    target { shape halfSpace; point (0 0 0); normal (1 0 0);
             material steel4340; phase target; rho 7850; }
}
"""
    case = new_case("gap", text)
    try:
        run_setup(case)
        m = mg.read_polymesh(case)
        a = fc.read_field(case, "0", "alpha.ball", m.nCells)
        r = np.hypot(m.C[:, 1], m.C[:, 2])
        # the centre of the volume of revolution: weights alpha r
        xc = np.sum(a * r * m.C[:, 0]) / np.sum(a * r)
        err = (xc - R) - gap
        checks.check("impactSetup_gap", abs(err) < 0.01 * gap,
                     "gap %.4f mm (asked 0.7 mm)" % ((xc - R) * 1e3))
    except fc.FoamError as e:
        checks.fail("impactSetup_gap", e.summary or str(e))


# --------------------------------------------------------------------------
# copperRodImpact from one dictionary
# --------------------------------------------------------------------------

COPPER = """// The copper of the copperRodImpact tutorial
type            solid;
equationOfState { type stiffenedGas; gamma 4.22; pInf 3.08e10; }
elasticity      { type metal; rho0 8930; mu 4.33e10; }
plasticity      { type vonMises; sigmaY0 4e8; H 1e8; tau 0; }
"""

ROD_DICT = """geometry axisymmetric;
domain
{
    min (-36e-3 0 0); max (36e-3 10e-3 0); cellSize %s;
    patches { xMin wall; xMax wall; yMax wall; }
}
ambient { material air; p 1e5; rho 1.2; }
bodies
{
    left  { shape cylinder; base (-32.4e-3 0 0); axis (1 0 0);
            length 32.4e-3; radius 3.2e-3; material copperTaylor;
            phase copper; U (227 0 0); }
    right { shape cylinder; base (0 0 0); axis (1 0 0); length 32.4e-3;
            radius 3.2e-3; material copperTaylor; phase copper;
            U (-227 0 0); }
}
"""


# The rod-on-rod problem as blockMesh and setFields state it: a wedge of
# one block (its radial nodes 1e-7 m off the multiples of h) and the rods
# as the cells whose centres they hold (cylinderToCell)
OLD_BLOCKMESH = """FoamFile { version 2.0; format ascii; class dictionary;
           object blockMeshDict; }
scale 1e-3;
vertices
(
    (-36 0.99984769515e-4 -0.01745240644e-4) (36 0.99984769515e-4 -0.01745240644e-4)
    (36 9.9984769515 -0.1745240644) (-36 9.9984769515 -0.1745240644)
    (-36 0.99984769515e-4 0.01745240644e-4) (36 0.99984769515e-4 0.01745240644e-4)
    (36 9.9984769515 0.1745240644) (-36 9.9984769515 0.1745240644)
);
blocks ( hex (0 1 2 3 4 5 6 7) (180 25 1) simpleGrading (1 1 1) );
boundary
(
    ends  { type wall; faces ((0 4 7 3) (1 2 6 5)); }
    side  { type wall; faces ((3 7 6 2)); }
    axis  { type symmetryPlane; faces ((0 1 5 4)); }
    front { type wedge; faces ((0 3 2 1)); }
    back  { type wedge; faces ((4 5 6 7)); }
);
"""

OLD_SETFIELDS = """FoamFile { version 2.0; format ascii; class dictionary;
           object setFieldsDict; }
defaultFieldValues
(
    volScalarFieldValue alpha.copper 0
    volScalarFieldValue alpha.air 1
    volVectorFieldValue U (0 0 0)
);
regions
(
    cylinderToCell
    {
        p1 (-0.0324 0 0); p2 (0 0 0); radius 0.0032;
        fieldValues ( volScalarFieldValue alpha.copper 1
                      volScalarFieldValue alpha.air 0
                      volVectorFieldValue U (227 0 0) );
    }
    cylinderToCell
    {
        p1 (0 0 0); p2 (0.0324 0 0); radius 0.0032;
        fieldValues ( volScalarFieldValue alpha.copper 1
                      volScalarFieldValue alpha.air 0
                      volVectorFieldValue U (-227 0 0) );
    }
);
"""


def check_copper_rods():
    case = new_case("copperRods", ROD_DICT % "0.4e-3",
                    {"copperTaylor": COPPER})
    tut = os.path.join(RUN, "copperRods_setFields")
    try:
        log = run_setup(case)
        # setFields on impactSetup's mesh and fields (its rho and p stay)
        if os.path.exists(tut):
            shutil.rmtree(tut)
        shutil.copytree(case, tut)
        with open(os.path.join(tut, "system", "setFieldsDict"), "w") as f:
            f.write(OLD_SETFIELDS)
        fc.run(tut, ["setFields"])
    except fc.FoamError as e:
        checks.fail("impactSetup_copperRodImpact", e.summary or str(e))
        return
    mt, ms = mg.read_polymesh(tut), mg.read_polymesh(case)
    if mt.nCells != ms.nCells:
        checks.fail("impactSetup_copperRodImpact",
                    "%d cells, the tutorial %d" % (ms.nCells, mt.nCells))
        return
    dC = np.abs(mt.C - ms.C).max()
    worst = []
    for name in ("alpha.copper", "alpha.air", "U", "rho.copper", "rho.air",
                 "p"):
        a = fc.read_field(tut, "0", name, mt.nCells)
        b = fc.read_field(case, "0", name, ms.nCells)
        scale = max(np.abs(a).max(), 1e-300)
        worst.append((float(np.abs(a - b).max() / scale), name))
    d, name = max(worst)
    checks.check("impactSetup_copperRodImpact",
                 d < 1e-9 and dC < 1e-6,
                 "largest relative difference %.1e (%s) over %d cells; "
                 "cell centres within %.1e m" % (d, name, ms.nCells, dC))

    # Rerun with another cell size: impactSetup rewrites its own files
    # (and the phase renamed: the old phase's files go)
    with open(os.path.join(case, "system", "impactDict"), "w") as f:
        f.write((ROD_DICT % "0.8e-3").replace("phase copper", "phase rods"))
    try:
        log = run_setup(case)
        n = mg.read_polymesh(case).nCells
        sizes = [len(fc.read_field(case, "0", f, n))
                 for f in ("alpha.rods", "alpha.air", "rho.rods", "U", "p")]
        gone = not fc.has_field(case, "0", "alpha.copper") \
            and not fc.has_field(case, "0", "rho.copper")
        # 72 mm / 0.8 mm = 90 cells along x, 10/0.8 = 12.5 rounded to 13
        checks.check("impactSetup_rerun",
                     n == 90 * 13 and all(s == n for s in sizes)
                     and "Files written" in log and gone,
                     "%d cells after %d; field sizes %s; the old phase's "
                     "files removed: %s" % (n, ms.nCells, sizes, gone))
    except fc.FoamError as e:
        checks.fail("impactSetup_rerun", e.summary or str(e))

    # A user's file is not overwritten: 0/U without the mark; a mesh of
    # the user's (blockMeshDict not impactSetup's)
    with open(os.path.join(case, "0", "U"), "w") as f:
        f.write("// my own U\n")
    log1 = run_setup(case, check=False)
    tut = fc.copy_tutorial("copperRodImpact", "impactSetup_tutorial",
                           run_dir=RUN)
    fc.set_entry(tut, "system/controlDict", "writeFormat", "ascii")
    with open(os.path.join(tut, "system", "blockMeshDict"), "w") as f:
        f.write(OLD_BLOCKMESH)
    fc.run(tut, ["blockMesh"])
    mt = mg.read_polymesh(tut)
    shutil.copy(os.path.join(case, "system", "impactDict"),
                os.path.join(tut, "system", "impactDict"))
    os.makedirs(os.path.join(tut, "constant", "materials"), exist_ok=True)
    with open(os.path.join(tut, "constant", "materials", "copperTaylor"),
              "w") as f:
        f.write(COPPER)
    log2 = run_setup(tut, check=False)
    ok1 = "FOAM FATAL" in log1 and "does not overwrite" in log1 \
        and "0/U" in log1
    ok2 = "FOAM FATAL" in log2 and "did not make" in log2
    with open(os.path.join(case, "0", "U")) as f:
        kept = f.read() == "// my own U\n"
    checks.check("impactSetup_noOverwrite", ok1 and ok2 and kept,
                 "user's 0/U refused: %s, kept: %s; foreign mesh refused: %s"
                 % (ok1, kept, ok2))

    # Without a domain: the case's own mesh (the tutorial's, its radial
    # nodes not on the rods' radius), used as it is
    text = ROD_DICT % "0.4e-3"
    text = text[:text.find("domain")] + text[text.find("ambient"):]
    case = new_case("existingMesh", text, {"copperTaylor": COPPER})
    shutil.copytree(os.path.join(tut, "constant", "polyMesh"),
                    os.path.join(case, "constant", "polyMesh"))
    try:
        run_setup(case)
        m = mg.read_polymesh(case)
        a = fc.read_field(case, "0", "alpha.copper", m.nCells)
        p = m.points[np.argmax(m.points[:, 1])]
        V = m.V * 2 * PI / math.sin(2 * math.atan2(abs(p[2]), p[1]))
        err = np.sum(a * V) / (2 * PI * 3.2e-3 ** 2 * 32.4e-3) - 1
        checks.check("impactSetup_existingMesh",
                     abs(err) < 1e-6 and m.nCells == mt.nCells
                     and not os.path.exists(os.path.join(case, "system",
                                                          "blockMeshDict")),
                     "copper volume %.1e off the rods' on the tutorial's "
                     "mesh (%d cells)" % (err, m.nCells))
    except fc.FoamError as e:
        checks.fail("impactSetup_existingMesh", e.summary or str(e))


def check_template():
    """The projectileOnPlate template at a coarse cell size: impactSetup
    writes what impactFoam starts from (a few steps)."""
    case = fc.copy_tutorial("templates/projectileOnPlate",
                            "impactSetup_projectileOnPlate", run_dir=RUN)
    path = os.path.join(case, "system", "impactDict")
    with open(path) as f:
        text = f.read()
    text = re.sub(r"cellSize\s+[^;]+;", "cellSize 1e-3;", text, count=1)
    with open(path, "w") as f:
        f.write(text)
    try:
        log = run_setup(case)
        fc.run(case, ["impactFoam", "-endTime", "1e-7"])
        checks.check("impactSetup_template", "Files written" in log,
                     "projectileOnPlate: impactSetup and 1e-7 s of "
                     "impactFoam ran")
    except fc.FoamError as e:
        checks.fail("impactSetup_template", e.summary or str(e))


def check_variables():
    """A top-level entry used as $name is a variable: read, then dropped;
    one nobody uses is an unknown entry."""
    case = fc.copy_tutorial("templates/projectileOnPlate",
                            "impactSetup_variables", run_dir=RUN)
    path = os.path.join(case, "system", "impactDict")
    with open(path) as f:
        text = f.read()
    # (the template's own variable, speed, replaced by rodU)
    for old, new in (
            ("speed       1500;", "rodU        (-1800 0 0);"
             "    // $rodU in a comment"),
            ("U           (#eval{ -$speed } 0 0);", "U           $rodU;")):
        if old not in text:
            checks.fail("impactSetup_variables",
                        "the template's impactDict has no %s" % old)
            return
        text = text.replace(old, new, 1)
    with open(path, "w") as f:
        f.write(text)
    try:
        fc.run(case, ["impactSetup", "-cellSize", "2e-3"])
        U = fc.read_field(case, "0", "U")
        a = fc.read_field(case, "0", "alpha.rod")
        inside = a > 0.999
        ok = inside.any() and np.allclose(U[inside, 0], -1800, rtol=1e-9)
        checks.check("impactSetup_variables", ok,
                     "U $rodU with rodU (-1800 0 0) at the top level: Ux in "
                     "the cells the rod fills %s"
                     % (np.unique(np.round(U[inside, 0], 6))[:3]))
    except fc.FoamError as e:
        checks.fail("impactSetup_variables", e.summary or str(e))

    with open(path, "w") as f:
        f.write(text.replace("rodU        (-1800 0 0);",
                             "rodU        (-1800 0 0);\nrodV 1;", 1))
    log = fc.run(case, ["impactSetup", "-cellSize", "2e-3"], check=False)
    with open(log) as f:
        out = " ".join(f.read().split())
    checks.check("impactSetup_error_unusedVariable",
                 "FOAM FATAL" in out and "unknown entry rodV" in out,
                 "an unused top-level entry rodV: %s"
                 % out[out.find("impactDict:"):][:160])


def check_unstructured():
    """Without a domain, on meshes blockMesh does not make: jittered
    triangular prisms (planar) and tetrahedra (threeD), tests/lib/triMesh.py.
    A disc and a ball 10 grid spacings across."""
    for geometry, name in (("planar", "disc"), ("threeD", "ball")):
        n = 32 if geometry == "planar" else 16
        R = 5.0 / n
        text = """geometry %s;
ambient { material air; rho 1.2; }
bodies
{
    %s { shape sphere; centre (0.513 0.488 %s); radius %.12g;
         material steel4340; phase %s; rho 7850; }
}
""" % (geometry, name, "0" if geometry == "planar" else "0.507", R, name)
        case = new_case("unstructured_" + geometry, text)
        if geometry == "planar":
            pts, cells = triMesh.triangle_prisms(n, n, jitter=0.2, seed=3)
            triMesh.write_polymesh(case, pts, cells, triMesh.box_patches_2d)
            exact = PI * R * R
        else:
            pts, cells = triMesh.tetrahedra(n, n, n, z1=1.0, jitter=0.15,
                                            seed=3)
            triMesh.write_polymesh(case, pts, cells, triMesh.box_patches_3d)
            exact = 4 * PI * R ** 3 / 3
        try:
            run_setup(case)
            vol = measured_volumes(case, [name], geometry)[name]
            err = vol / exact - 1
            checks.check("impactSetup_unstructured_" + geometry,
                         abs(err) < 1e-3,
                         "%s on %s: relative volume error %.2e (limit 1e-3)"
                         % (name, "triangular prisms" if geometry == "planar"
                            else "tetrahedra", err))
        except fc.FoamError as e:
            checks.fail("impactSetup_unstructured_" + geometry,
                        e.summary or str(e))


def main():
    missing = fc.require_apps("impactSetup", "blockMesh", "setFields",
                              "impactFoam")
    if missing:
        checks.fail("impactSetup", "missing " + str(missing))
        checks.exit()
    os.makedirs(RUN, exist_ok=True)
    check_errors()
    check_material_errors()
    check_warnings()
    check_cuts_and_gap()
    try:
        check_radial_velocity()
    except fc.FoamError as e:
        checks.fail("impactSetup_radialVelocity", e.summary or str(e))
    check_copper_rods()
    check_template()
    check_variables()
    check_unstructured()
    check_volumes()
    checks.exit()


if __name__ == "__main__":
    main()
