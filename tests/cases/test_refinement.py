#!/usr/bin/python3
"""Adaptive refinement's mapping (docs/numerics.md section 11): a refine /
unrefine cycle of a case with two solids, a gas and a shock in it
conserves every phase's mass, the momentum and the total energy to
round-off, and brings the state back to itself, in 3-D (hexCutter) and on
an axisymmetric wedge (quadCutter).

The cases: the projectileOnPlate template in 3-D (a quarter: symmetry
planes y = 0 and z = 0, 2 mm cells, 720 cells) and as it is, axisymmetric
(1 mm cells, 1400), each run 2 us past the impact so that a shock runs
through the plate and the rod. tests/tools/refinementCheck
reads it with constant/refinementProperties (interfaces and shocks, two
levels, one buffer layer), refines twice where the criteria mark cells,
unrefines with nothing marked until the mesh is the base mesh again, and
refines once more; after each change it prints the cells, each phase's
mass, the momentum and the total energy (phaseSystem's sums) and the
kinetic energy turned into heat by merging; after the unrefinement, the
largest difference of the state from the start (roundTrip: U, each
phase's alpha, rho, e over its largest c^2, cobasis and carried variables,
each relative to its largest magnitude).

Decides, for each (refinement_* in 3-D, refinement_wedge* on the wedge):
  conservation   every phase's mass and the total energy within 1e-12
                 relative of the start after every change, the momentum
                 within 1e-12 of its magnitude (measured: 1e-14, 4e-13,
                 2e-14);
  levels         both levels reached, and the base mesh again at the end;
  round trip     roundTrip <= 1e-12 (measured 5e-15, wedge 4.7e-15): the
                 children copy their parent, a merged cell of eight (four)
                 copies is the cell;
  heat           the kinetic energy turned into heat >= -1e-12 of the
                 total energy (merging never creates kinetic energy);
  parallel       the same on 2 processes (maxImbalance 0: the round trip
                 compares each process's own cells): the same cells after
                 every change and the same sums within 1e-12;
  restart        the refined state written (-write) holds the mesh and
                 the levels in its time's polyMesh, impactPlot draws it
                 and the time before on their own meshes, and impactFoam
                 runs on from it;
  bad input      a misspelled entry, no criterion, a value out of range,
                 refinement of a 1-D mesh: each stops with an error naming
                 it;
  collapsed axis the cycle (conservation, round trip, levels) on the
                 clayImpact tutorial's wedge at 2 mm cells with its axis
                 collapsed (prisms at the axis, whose front and back faces
                 share the axis points), and checkMesh on the refined mesh;
  impactSetup    impactDict's refinement: the rod's volume on the mesh
                 refined at the surfaces within 1e-3 of the exact one and
                 nearer than on the base mesh; every cell a surface crosses
                 at the finest level; constant/refinementProperties written
                 (and removed with the levels when the entry goes); the
                 same on the axisymmetric template (1.5 mm cells, whose
                 surfaces do not lie on cell faces): both bodies' volumes
                 within 1e-3, every cell a surface crosses at the finest
                 level.
About 60 s.
"""
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))

import foamcase as fc  # noqa: E402
from checks import Checks  # noqa: E402

TEMPLATE = os.path.join("templates", "projectileOnPlate")

QUARTER = [
    ("geometry    axisymmetric;", "geometry    threeD;"),
    ("max         (60e-3 20e-3 0);", "max         (30e-3 12e-3 12e-3);"),
    ("cellSize    0.25e-3;", "cellSize    2e-3;"),
    ("        yMax    open;", "        yMin    symmetry;\n        yMax    open;"
     "\n        zMin    symmetry;\n        zMax    open;"),
    ("length      40e-3;", "length      20e-3;"),
    ("min         (-10e-3 0 -1);", "min         (-10e-3 0 0);"),
    ("max         (0 15e-3 1);", "max         (0 12e-3 12e-3);"),
]

PROPERTIES = """FoamFile { version 2.0; format ascii; class dictionary;
           object refinementProperties; }
maxRefinement   2;
refineInterval  5;
nBufferLayers   1;
interfaces      { lower 1e-3; upper 0.999; }
shocks          { jump 0.1; }
"""

LINE = re.compile(r"^cells (\d+) mass (.*) momentum (\S+) (\S+) (\S+) "
                  r"energy (\S+) heat (\S+)$", re.M)


# The template as it is (axisymmetric) at 1 mm cells
WEDGE = [("cellSize    0.25e-3;", "cellSize    1e-3;")]


def make_case(name, changes=QUARTER):
    case = fc.copy_tutorial(TEMPLATE, name)
    path = os.path.join(case, "system", "impactDict")
    with open(path) as f:
        text = f.read()
    for old, new in changes:
        if old not in text:
            raise fc.FoamError("template impactDict: no %r" % old)
        text = text.replace(old, new, 1)
    with open(path, "w") as f:
        f.write(text)
    fc.run(case, ["impactSetup"])
    fc.run(case, ["impactFoam", "-endTime", "2e-6"])
    fc.set_entry(case, "system/controlDict", "startFrom", "latestTime")
    with open(os.path.join(case, "constant", "refinementProperties"),
              "w") as f:
        f.write(PROPERTIES)
    return case


def no_balance(case):
    """The cycle on 2 processes without the load balance: the round trip
    compares each process's cells with the ones it started with
    (test_refinementRun checks the balance)"""
    with open(os.path.join(case, "constant", "refinementProperties"),
              "w") as f:
        f.write(PROPERTIES + "maxImbalance    0;\n")


def parse(log):
    text = open(log).read()
    rows = []
    for m in LINE.finditer(text):
        rows.append({
            "cells": int(m.group(1)),
            "mass": [float(v) for v in m.group(2).split()],
            "momentum": [float(m.group(i)) for i in (3, 4, 5)],
            "energy": float(m.group(6)),
            "heat": float(m.group(7)),
        })
    rt = re.search(r"^roundTrip (\S+)", text, re.M)
    levels = re.findall(r"per level \d+\(([\d ]+)\)", text)
    return rows, (float(rt.group(1)) if rt else None), \
        [[int(v) for v in lv.split()] for lv in levels]


def drift(rows):
    """Largest relative change of the sums from the first row"""
    r0 = rows[0]
    pScale = sum(v * v for v in r0["momentum"]) ** 0.5
    worst = {"mass": 0.0, "momentum": 0.0, "energy": 0.0}
    for r in rows[1:]:
        for m, m0 in zip(r["mass"], r0["mass"]):
            worst["mass"] = max(worst["mass"], abs(m - m0) / m0)
        dp = sum((a - b) ** 2 for a, b in
                 zip(r["momentum"], r0["momentum"])) ** 0.5
        worst["momentum"] = max(worst["momentum"], dp / pScale)
        worst["energy"] = max(worst["energy"],
                              abs(r["energy"] - r0["energy"]) / r0["energy"])
    return worst


def check_cycle(checks, name, rows, round_trip, levels):
    ok = len(rows) >= 5
    checks.check(name + "_changes", ok,
                 "%d states printed (start, two refinements, two "
                 "unrefinements, one refinement: 6 expected); cells %s"
                 % (len(rows), [r["cells"] for r in rows]))
    if not ok:
        return
    w = drift(rows)
    checks.check(
        name + "_conservation",
        w["mass"] <= 1e-12 and w["momentum"] <= 1e-12
        and w["energy"] <= 1e-12,
        "largest change over %d changes of the mesh: phase masses %.2g, "
        "momentum %.2g (of its magnitude), total energy %.2g (bound 1e-12)"
        % (len(rows) - 1, w["mass"], w["momentum"], w["energy"]))
    top = max((lv[2] if len(lv) > 2 else 0) for lv in levels) \
        if levels else 0
    back = rows[0]["cells"] in [r["cells"] for r in rows[3:-1]]
    checks.check(
        name + "_levels", top > 0 and back,
        "%d cells at level 2 at the finest; the base mesh's %d cells "
        "again after the unrefinement: %s" % (top, rows[0]["cells"], back))
    checks.check(
        name + "_roundTrip",
        round_trip is not None and round_trip <= 1e-12,
        "state after refine / unrefine against the start: largest "
        "relative difference %s (bound 1e-12)" % round_trip)
    heat = min(r["heat"] for r in rows)
    checks.check(
        name + "_heat", heat >= -1e-12 * rows[0]["energy"],
        "kinetic energy turned into heat by merging: %.3g J at the end, "
        "smallest %.3g J (bound >= -1e-12 of %.6g J)"
        % (rows[-1]["heat"], heat, rows[0]["energy"]))


def bad_input(checks, case):
    """Each bad refinementProperties stops refinementCheck with a message
    naming the problem"""
    props = os.path.join(case, "constant", "refinementProperties")
    cases = [
        ("misspelled", PROPERTIES.replace("maxRefinement", "maxRefinment"),
         "maxRefinment"),
        ("noCriterion", PROPERTIES.replace(
            "interfaces      { lower 1e-3; upper 0.999; }", "").replace(
            "shocks          { jump 0.1; }", ""), "No criterion"),
        ("badRange", PROPERTIES.replace("lower 1e-3", "lower 0.9999"),
         "lower"),
    ]
    for name, text, expect in cases:
        with open(props, "w") as f:
            f.write(text)
        log = fc.run(case, ["refinementCheck"],
                     log="log.refinementCheck." + name, check=False)
        out = open(log).read()
        checks.check("refinement_badInput_" + name,
                     "FOAM FATAL" in out and expect in out,
                     "refinementCheck stops naming %r: %s"
                     % (expect, "FOAM FATAL" in out and expect in out))
    with open(props, "w") as f:
        f.write(PROPERTIES)

    # A 1-D mesh (empty in two directions) is not refined
    line = fc.copy_tutorial("waterAirShockTube", "refinement_line")
    fc.run(line, ["blockMesh"])
    shutil.copytree(os.path.join(line, "0.orig"), os.path.join(line, "0"))
    fc.run(line, ["setFields"])
    with open(os.path.join(line, "constant", "refinementProperties"),
              "w") as f:
        f.write(PROPERTIES)
    log = fc.run(line, ["refinementCheck"], check=False)
    out = open(log).read()
    ok = "FOAM FATAL" in out and "1-D mesh" in out
    checks.check("refinement_badInput_line", ok,
                 "refinement of the 1-D shock tube refused, naming a 1-D "
                 "mesh: %s" % ok)


SETUP_REFINEMENT = """
refinement
{
    maxRefinement   2;
    refineInterval  5;
    nBufferLayers   1;
    interfaces      { lower 1e-3; upper 0.999; }
    shocks          { jump 0.1; }
}
"""


def rod_volume(log):
    """The rod's volume on the mesh and the exact one from impactSetup's
    summary"""
    m = re.search(r"Body rod:.*?volume on the mesh (\S+), exact (\S+)",
                  open(log).read(), re.S)
    return (float(m.group(1)), float(m.group(2))) if m else (None, None)


def setup_refinement(checks):
    """impactDict's refinement: impactSetup refines the 3-D mesh at the
    bodies' surfaces and computes the exact fractions on it; it writes
    constant/refinementProperties, and removes it when the entry goes"""
    case = fc.copy_tutorial(TEMPLATE, "refinement_setup")
    path = os.path.join(case, "system", "impactDict")
    with open(path) as f:
        text = f.read()
    for old, new in QUARTER:
        text = text.replace(old, new, 1)
    with open(path, "w") as f:
        f.write(text)
    base_log = fc.run(case, ["impactSetup"], log="log.impactSetup.base")
    v_base, exact = rod_volume(base_log)
    with open(path, "w") as f:
        f.write(text + SETUP_REFINEMENT)
    log = fc.run(case, ["impactSetup"])
    v_fine, _ = rod_volume(log)
    # The quarter of the rod lies in the domain
    quarter = exact / 4 if exact else None
    err_base = abs(v_base / quarter - 1) if quarter and v_base else None
    err_fine = abs(v_fine / quarter - 1) if quarter and v_fine else None
    checks.check(
        "refinement_setup_volume",
        err_fine is not None and err_fine <= 1e-3 and err_fine < err_base,
        "the rod's volume on the refined mesh against the exact one: "
        "%.3g relative (bound 1e-3), on the 2 mm base mesh %.3g"
        % (err_fine if err_fine is not None else -1,
           err_base if err_base is not None else -1))

    # Every cell the rod's or the plate's surface crosses at the finest
    # level
    t = "0"
    level_file = os.path.join(case, "constant", "polyMesh", "cellLevel")
    ok = os.path.isfile(level_file)
    coarse_surface = -1
    if ok:
        text_l = open(level_file).read()
        m = re.search(r"\n(\d+)\s*\n\(\s*\n([\s\d]*?)\)", text_l)
        levels = [int(v) for v in m.group(2).split()] if m else []
        alphas = [fc.read_field(case, t, "alpha." + p) for p in
                  ("rod", "plate")]
        coarse_surface = sum(
            1 for c, lv in enumerate(levels)
            if lv < 2 and any(1e-3 < a[c] < 0.999 for a in alphas))
        ok = len(levels) == len(alphas[0]) and coarse_surface == 0
    props = os.path.join(case, "constant", "refinementProperties")
    written = os.path.isfile(props) and open(props).readline().startswith(
        "// Generated by impactSetup")
    checks.check(
        "refinement_setup_surfaces", ok and written,
        "cells holding a surface (1e-3 < alpha < 0.999) below the finest "
        "level: %d (must be 0); constant/refinementProperties written and "
        "marked as generated: %s" % (coarse_surface, written))

    # Without the entry: the generated settings and the levels go
    with open(path, "w") as f:
        f.write(text)
    fc.run(case, ["impactSetup"], log="log.impactSetup.again")
    gone = not os.path.exists(props) and not os.path.exists(level_file)
    checks.check("refinement_setup_removed", gone,
                 "impactSetup rerun without refinement: refinementProperties "
                 "and cellLevel removed: %s" % gone)

    # Axisymmetric: the template at 1.5 mm cells, refined twice
    wedge = fc.copy_tutorial(TEMPLATE, "refinement_setupWedge")
    wpath = os.path.join(wedge, "system", "impactDict")
    with open(wpath) as f:
        wtext = f.read()
    with open(wpath, "w") as f:
        f.write(wtext.replace("cellSize    0.25e-3;", "cellSize    1.5e-3;")
                + SETUP_REFINEMENT)
    log = fc.run(wedge, ["impactSetup"])
    errors = []
    for body in ("rod", "plate"):
        m = re.search(r"Body %s:.*?volume on the mesh (\S+), exact (\S+)"
                      % body, open(log).read(), re.S)
        errors.append(abs(float(m.group(1)) / float(m.group(2)) - 1)
                      if m else 1.0)
    level_file = os.path.join(wedge, "constant", "polyMesh", "cellLevel")
    coarse = -1
    if os.path.isfile(level_file):
        m = re.search(r"\n(\d+)\s*\n\(\s*\n([\s\d]*?)\)",
                      open(level_file).read())
        levels = [int(v) for v in m.group(2).split()] if m else []
        alphas = [fc.read_field(wedge, "0", "alpha." + p) for p in
                  ("rod", "plate")]
        if len(levels) == len(alphas[0]):
            coarse = sum(1 for c, lv in enumerate(levels) if lv < 2 and
                         any(1e-3 < a[c] < 0.999 for a in alphas))
    checks.check(
        "refinement_setup_axisymmetric",
        max(errors) <= 1e-3 and coarse == 0,
        "the axisymmetric template refined at its surfaces: the rod's and "
        "the plate's volumes against the exact ones %.2g, %.2g (bound "
        "1e-3); cells holding a surface below the finest level: %d (must "
        "be 0)" % (errors[0], errors[1], coarse))

def serial_and_parallel(checks, case, parallel_name, serial_check,
                        parallel_check, same_check):
    """The cycle on the case (written at a new time, -write) and on a copy
    of it decomposed on 2 processes: each checked, and the same cells and
    sums on both; the serial run's rows"""
    parallel = os.path.join(fc.RUN_DIR, parallel_name)
    if os.path.lexists(parallel):
        shutil.rmtree(parallel)
    shutil.copytree(case, parallel)
    rows, rt, levels = parse(fc.run(case, ["refinementCheck", "-write"]))
    check_cycle(checks, serial_check, rows, rt, levels)

    no_balance(parallel)
    fc.write_decompose_dict(parallel, 2)
    fc.run(parallel, ["decomposePar", "-force", "-latestTime"])
    prow, prt, plevels = parse(fc.run(
        parallel, "mpirun -np 2 --oversubscribe refinementCheck -parallel",
        log="log.refinementCheck.parallel"))
    check_cycle(checks, parallel_check, prow, prt, plevels)
    same = len(prow) == len(rows) and all(
        a["cells"] == b["cells"]
        and abs(a["energy"] - b["energy"]) <= 1e-12 * b["energy"]
        and all(abs(x - y) <= 1e-12 * y for x, y in zip(a["mass"], b["mass"]))
        for a, b in zip(prow, rows))
    checks.check(same_check, same,
                 "2 processes against serial: cells %s and %s, the sums "
                 "within 1e-12" % ([r["cells"] for r in prow],
                                   [r["cells"] for r in rows]))
    return rows


def wedge_cycle(checks):
    """The cycle on the axisymmetric template, serial and on 2 processes"""
    case = make_case("refinement_wedge", WEDGE)
    serial_and_parallel(checks, case, "refinement_wedgeParallel",
                        "refinement_wedge", "refinement_wedgeParallel",
                        "refinement_wedgeSerialParallel")

    # The written refined mesh is a valid mesh
    t = fc.latest_time(case)
    log = fc.run(case, ["checkMesh", "-time", t], log="log.checkMesh",
                 check=False)
    ok = "Mesh OK." in open(log).read()
    checks.check("refinement_wedgeMesh", ok,
                 "checkMesh on the refined wedge at %s: %s"
                 % (t, "Mesh OK" if ok else fc.tail(log)))


# clayImpact's wedge with its axis collapsed: the axis points on both planes
AXIS = [
    ("    (0  0.99984769515e-4 -0.01745240644e-4)\n"
     "    (24 0.99984769515e-4 -0.01745240644e-4)",
     "    (0  0 0)\n    (24 0 0)"),
    ("    (0  0.99984769515e-4  0.01745240644e-4)\n"
     "    (24 0.99984769515e-4  0.01745240644e-4)",
     "    (0  0 0)\n    (24 0 0)"),
]
AXIS_PROPERTIES = PROPERTIES.replace("shocks          { jump 0.1; }\n", "")


def collapsed_axis(checks):
    """The cycle on a wedge whose axis is collapsed"""
    case = fc.copy_tutorial("clayImpact", "refinement_axis")
    path = os.path.join(case, "system", "blockMeshDict")
    with open(path) as f:
        text = f.read()
    for old, new in AXIS:
        if old not in text:
            raise fc.FoamError("clayImpact blockMeshDict: no %r" % old)
        text = text.replace(old, new, 1)
    with open(path, "w") as f:
        f.write(text)
    # Its Allrun's set-up without the run
    allrun = os.path.join(case, "Allrun")
    with open(allrun) as f:
        script = f.read()
    with open(allrun, "w") as f:
        f.write(re.sub(r"^impactRunSolver.*$", "exit 0", script, flags=re.M))
    fc.run(case, "./Allrun -h 2", log="log.Allrun")
    with open(os.path.join(case, "constant", "refinementProperties"),
              "w") as f:
        f.write(AXIS_PROPERTIES)
    rows, rt, levels = parse(fc.run(case, ["refinementCheck", "-write"]))
    check_cycle(checks, "refinement_axis", rows, rt, levels)
    t = fc.latest_time(case)
    log = fc.run(case, ["checkMesh", "-time", t], log="log.checkMesh",
                 check=False)
    out = open(log).read()
    ok = "Mesh OK." in out and re.search(r"prisms:\s+[1-9]", out)
    checks.check("refinement_axisMesh", bool(ok),
                 "checkMesh on the refined wedge with a collapsed axis at "
                 "%s: %s" % (t, "Mesh OK, prisms at the axis" if ok
                             else fc.tail(log)))


def main():
    checks = Checks()
    missing = fc.require_apps("refinementCheck", "impactSetup", "impactFoam",
                              "decomposePar")
    if missing:
        checks.fail("refinement", "missing: %s" % ", ".join(missing))
        checks.exit()

    case = make_case("refinement_cycle")
    parallel = os.path.join(fc.RUN_DIR, "refinement_parallel")
    rows = serial_and_parallel(checks, case, "refinement_parallel",
                               "refinement_serial", "refinement_parallel",
                               "refinement_serialParallel")

    # The written refined state: mesh and levels with the fields, and the
    # solver runs on from it
    t = fc.latest_time(case)
    mesh_dir = os.path.join(case, t, "polyMesh")
    have = all(os.path.isfile(os.path.join(mesh_dir, f)) for f in
               ("points", "faces", "owner", "neighbour", "cellLevel",
                "pointLevel", "refinementHistory"))
    owner = os.path.join(mesh_dir, "owner")
    m = re.search(r"nCells\s*:\s*(\d+)",
                  open(owner).read(4000)) if have else None
    mesh_n = int(m.group(1)) if m else None
    field_n = len(fc.read_field(case, t, "alpha.rod"))
    refined = rows[-1]["cells"] if rows else None
    checks.check("refinement_written",
                 have and mesh_n == refined and field_n == refined,
                 "time %s holds the refined mesh and its levels: %s; the "
                 "mesh has %s cells, alpha.rod %s, the refined state %s"
                 % (t, have, mesh_n, field_n, refined))
    # impactPlot draws each time on its own mesh
    plot = os.path.join(HERE, "..", "..", "applications", "utilities",
                        "impactPlot", "impactPlot")
    proc = subprocess.run([sys.executable, plot, "-case", case, "-time",
                           "2e-06,%s" % t], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True)
    pngs = [os.path.join(case, "postProcessing", "impactPlot",
                         "materials_%s.png" % x) for x in ("2e-06", t)]
    checks.check("refinement_impactPlot",
                 proc.returncode == 0 and all(map(os.path.isfile, pngs)),
                 "impactPlot draws the base mesh's time 2e-06 and the "
                 "refined time %s: %s" % (t, "yes" if proc.returncode == 0
                                          else proc.stdout[-300:]))
    os.remove(os.path.join(case, "constant", "refinementProperties"))
    log = fc.run(case, ["impactFoam", "-endTime", "2.2e-6"],
                 log="log.impactFoam.restart", check=False)
    out = open(log).read()
    checks.check("refinement_restart", "FOAM FATAL" not in out
                 and out.rstrip().endswith("End"),
                 "impactFoam on from the refined state %s to 2.2 us: %s"
                 % (t, "ran" if "FOAM FATAL" not in out else fc.tail(log)))

    wedge_cycle(checks)
    collapsed_axis(checks)
    bad_input(checks, parallel)
    setup_refinement(checks)
    checks.exit()


if __name__ == "__main__":
    main()
