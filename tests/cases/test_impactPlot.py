#!/usr/bin/python3
"""impactPlot (docs/impactPlot.md): the picture of the materials at every
written time, on the three geometries, serial and decomposed.

The projectileOnPlate template (a rod 1 us after it started 0.5 mm from a
steel plate), axisymmetric and planar on 1 mm cells, serial, and 3-D on 2 mm
cells on 2 processes (the reconstructed times removed, so that impactPlot
reads the processors' meshes and fields).

Checks
  impactPlot_<geometry>   a PNG of every written time (0 and 1e-06); the
                    picture's pixel at a point inside the rod, inside the
                    plate and in the air (and at their mirror images about
                    y = 0) has the colour of the cell holding the point
                    (the blend of its fractions, within 2 of 255 per
                    channel), a cell that phase fills most of; the cells
                    drawn are the mesh's: every cell in
                    2-D (once each side of the axis on the wedge), one layer
                    of the 3-D mesh cut by the plane z = 0 (35 x 20 cells)
  impactPlot_line  a 1-D case (waterAirShockTube): drawn as lines along x,
                    the colour at mid-height over cells a phase fills is
                    that phase's, the p curve passes within a pixel of ten
                    cells' (x, p)
  impactPlot_blend  a cell's colour is its phases' colours weighted by the
                    fractions (a half rod, half air cell: the mean)
  impactPlot_binary  the axisymmetric case written with writeFormat binary
                    (mesh and fields): the same picture with -field sigmaEq
                    (at most 1e-3 of the pixels differ by more than 2 of
                    255: the interface line where a fraction is 1/2 to
                    the ASCII files' 10 digits)
  impactPlot_field  -field sigmaEq: a picture at 1e-06; at 0, where the field
                    is not written, the materials alone and a note saying so
  impactPlot_boundaryPlane  3-D, a plane on the mesh's boundary: the
                    layer of cells above it (35 x 20)
  impactPlot_animate  -animate: a GIF with a frame per written time
  impactPlot_error_<what>  a time not written, a bad -plane, a case without
                    constant/phaseProperties: a message naming it, exit
                    status not 0, no traceback
About 20 s.
"""
import importlib.machinery
import importlib.util
import os
import re
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
from checks import Checks                     # noqa: E402

checks = Checks()
RUN = os.path.join(HERE, "..", "run", "impactPlot")
TEMPLATE = "templates/projectileOnPlate"
SCRIPT = os.path.join(HERE, "..", "..", "applications", "utilities",
                      "impactPlot", "impactPlot")


def load_module():
    loader = importlib.machinery.SourceFileLoader("impactPlot", SCRIPT)
    spec = importlib.util.spec_from_loader("impactPlot", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


plot = load_module()

# The template's impactDict turned planar or 3-D (both sides of y = 0)
SUBS = {
    "planar": [
        ("geometry    axisymmetric;", "geometry    planar;"),
        ("min         (-10e-3 0 0);", "min         (-10e-3 -20e-3 0);"),
        ("min         (-10e-3 0 -1);", "min         (-10e-3 -15e-3 -1);"),
        ("        yMax    open;", "        yMin    open;\n        yMax    open;"),
    ],
    "threeD": [
        ("geometry    axisymmetric;", "geometry    threeD;"),
        ("min         (-10e-3 0 0);", "min         (-10e-3 -20e-3 -20e-3);"),
        ("max         (60e-3 20e-3 0);", "max         (60e-3 20e-3 20e-3);"),
        ("min         (-10e-3 0 -1);", "min         (-10e-3 -15e-3 -15e-3);"),
        ("max         (0 15e-3 1);", "max         (0 15e-3 15e-3);"),
        ("        yMax    open;", "        yMin    open;\n        yMax    open;"
         "\n        zMin    open;\n        zMax    open;"),
    ],
}


def make_case(geometry, binary=False):
    case = fc.copy_tutorial(TEMPLATE, geometry + ("Binary" if binary
                                                 else ""), run_dir=RUN)
    if binary:
        fc.set_entry(case, "system/controlDict", "writeFormat", "binary")
    path = os.path.join(case, "system", "impactDict")
    with open(path) as f:
        text = f.read()
    for old, new in SUBS.get(geometry, []):
        if old not in text:
            raise fc.FoamError("template impactDict: no %r" % old)
        text = text.replace(old, new, 1)
    with open(path, "w") as f:
        f.write(text)
    if geometry == "threeD":
        fc.run(case, ["./Allrun", "-h", "2", "-end", "1e-6", "-np", "2"],
               log="log.Allrun")
        for _, t in fc.time_dirs(case):
            shutil.rmtree(os.path.join(case, t))
    else:
        fc.run(case, ["./Allrun", "-h", "1", "-end", "1e-6"],
               log="log.Allrun")
    shutil.rmtree(os.path.join(case, "postProcessing", "impactPlot"),
                  ignore_errors=True)
    return case


def run_plot(case, args):
    proc = subprocess.run([sys.executable, SCRIPT, "-case", case] + args,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True)
    return proc.returncode, proc.stdout


def cell_at(parts, x, y):
    """The part and the index (in the part's drawn cells) of the cell whose
    outline holds (x, y)"""
    from matplotlib.path import Path
    for part in parts:
        for c, outline in enumerate(part.outlines):
            lo, hi = outline.min(axis=0), outline.max(axis=0)
            if lo[0] <= x <= hi[0] and lo[1] <= y <= hi[1] and \
                    Path(outline).contains_point((x, y)):
                return part, c
    raise fc.FoamError("no drawn cell holds (%g, %g)" % (x, y))


def pixel(png, at):
    from PIL import Image
    image = Image.open(png).convert("RGB")
    return np.array(image.getpixel(at), dtype=float)


# Points (x, y) inside the rod, inside the plate and in the air at 1 us
# (the rod's axis at y = 0 runs from about 0 to 38 mm; in 3-D the slice's
# first cell layer lies below z = 0, 1 mm from the rod's axis)
POINTS = {"rod": (20.3e-3, 0.7e-3), "plate": (-5.3e-3, 8.3e-3),
          "air": (50.3e-3, 15.3e-3)}       # (off the cells' edges)


def check_geometry(geometry):
    case = make_case(geometry)
    code, out = run_plot(case, [])
    pngs = sorted(re.findall(r"impactPlot: (\S+\.png)", out))
    expect = ["postProcessing/impactPlot/materials_0.png",
              "postProcessing/impactPlot/materials_1e-06.png"]
    ok = code == 0 and pngs == expect and all(
        os.path.getsize(os.path.join(case, p)) > 0 for p in pngs)

    # Redraw the latest time here to know where points lie in the picture
    phases = plot.phases_of(case)
    roots = plot.roots_of(case)
    parts = [plot.Part(r, (np.zeros(3), np.array([0, 0, 1.0])))
             for r in roots]
    png = os.path.join(RUN, geometry + ".png")
    to_pixel = plot.draw(parts, case, "1e-06", phases, None, png, 120)
    colours = plot.phase_colours(len(phases))
    worst = 0.0
    dominant = True
    for name, (x, y) in POINTS.items():
        for yy in (y, -y):
            # The colour of the cell holding the point (the wedge's lower
            # half is the mirror image), and whether the named phase fills
            # most of it
            part, c = cell_at(parts, x, abs(yy) if geometry ==
                              "axisymmetric" else yy)
            alpha = np.array([plot.read_field(os.path.join(
                part.root, "1e-06", "alpha." + ph), part.nCells)[
                    part.cells[c]] for ph in phases])
            dominant = dominant and phases[int(np.argmax(alpha))] == name
            expect = plot.blend(alpha[:, None], colours)[0] * 255
            diff = np.abs(pixel(png, to_pixel(x, yy)) - expect).max()
            worst = max(worst, diff)
    drawn = sum(len(p.cells) for p in parts)
    nCells = sum(p.nCells for p in parts)
    if geometry == "threeD":
        expectDrawn = 35 * 20
    else:
        expectDrawn = nCells
    ok = ok and dominant and worst <= 2 and drawn == expectDrawn \
        and len(roots) == (
        2 if geometry == "threeD" else 1)
    checks.check("impactPlot_" + geometry, ok,
                 "exit %d, pictures %s; largest difference of the colour at "
                 "the rod, plate and air points from their cells' blend "
                 "%.0f of 255 (bound 2), each in a cell its phase fills "
                 "most: %s; %d cells drawn (expected %d) from %d mesh "
                 "part(s)" % (code, pngs, worst, dominant, drawn,
                              expectDrawn, len(roots)))
    return case


def check_binary(case):
    """The same case written in binary (mesh and fields): the same
    picture"""
    other = make_case("axisymmetric", binary=True)
    phases = plot.phases_of(case)
    pngs = []
    for c in (case, other):
        parts = [plot.Part(r, (np.zeros(3), np.array([0, 0, 1.0])))
                 for r in plot.roots_of(c)]
        png = os.path.join(RUN, os.path.basename(c) + "_compare.png")
        # (the title names the first case in both)
        plot.draw(parts, case, "1e-06", phases, "sigmaEq", png, 80)
        pngs.append(png)
    from PIL import Image
    a, b = (np.asarray(Image.open(p).convert("RGB"), dtype=float)
            for p in pngs)
    with open(os.path.join(other, "constant", "polyMesh", "points"),
              "rb") as f:
        isBinary = b"format      binary" in f.read(2000)
    # (the ASCII fields hold 10 digits: where a fraction is 1/2 to that,
    # as at the rod's tip, the interface line may take another pixel)
    share = float((np.abs(a - b).max(axis=2) > 2).mean()) \
        if a.shape == b.shape else 1.0
    checks.check("impactPlot_binary", isBinary and share <= 1e-3,
                 "the case written in binary (mesh binary: %s) against "
                 "ASCII: %.1e of the pixels differ by more than 2 of 255 "
                 "(bound 1e-3)" % (isBinary, share))


def check_blend():
    colours = plot.phase_colours(3)
    alpha = np.array([[1.0, 0.5, 0.0], [0.0, 0.0, 0.0], [0.0, 0.5, 1.0]])
    rgb = plot.blend(alpha, colours)
    expect = np.array([colours[0], 0.5 * (colours[0] + colours[2]),
                       colours[2]])
    err = np.abs(rgb - expect).max()
    checks.check("impactPlot_blend", err <= 1e-12,
                 "pure, half-half and ambient cells: largest difference "
                 "%.1e" % err)


def check_field(case):
    code, out = run_plot(case, ["-field", "sigmaEq"])
    ok = code == 0 and "no sigmaEq at time 0: the materials only" in out \
        and os.path.isfile(os.path.join(case, "postProcessing", "impactPlot",
                                        "sigmaEq_1e-06.png"))
    checks.check("impactPlot_field", ok, "exit %d: %s" % (code, " ".join(
        out.split())[:300]))


def check_animate(case):
    code, out = run_plot(case, ["-animate"])
    gif = os.path.join(case, "postProcessing", "impactPlot",
                       "materials.gif")
    frames = 0
    if os.path.isfile(gif):
        from PIL import Image
        frames = Image.open(gif).n_frames
    checks.check("impactPlot_animate", code == 0 and frames == 2,
                 "exit %d, %d frames (2 written times)" % (code, frames))


def check_errors(case):
    bare = os.path.join(RUN, "noPhases")
    shutil.rmtree(bare, ignore_errors=True)
    os.makedirs(os.path.join(bare, "constant"))
    cases = [
        ("time", case, ["-time", "5"], "no time 5"),
        ("plane", case, ["-plane", "0,0,0"], "-plane 0,0,0"),
        ("phases", bare, [], "phaseProperties"),
    ]
    for what, c, args, expect in cases:
        code, out = run_plot(c, args)
        ok = code != 0 and expect in out and "Traceback" not in out
        checks.check("impactPlot_error_" + what, ok,
                     "exit %d: %s" % (code, " ".join(out.split())[:200]))


def check_line():
    """A 1-D case (one cell across in y and z): the stacked fractions and
    the field along x"""
    case = fc.copy_tutorial("waterAirShockTube", run_dir=RUN)
    fc.run(case, ["./Allrun"], log="log.Allrun")
    code, out = run_plot(case, ["-latestTime", "-field", "p"])
    time = fc.time_dirs(case)[-1][1]
    ok = code == 0 and ("p_%s.png" % time) in out
    phases = plot.phases_of(case)
    parts = [plot.Part(case, (np.zeros(3), np.array([0, 0, 1.0])))]
    png = os.path.join(RUN, "line.png")
    to_pixel = plot.draw(parts, case, time, phases, "p", png, 120)
    part = parts[0]
    x = part.centres[:, 0]
    alpha = [plot.read_field(os.path.join(case, time, "alpha." + ph),
                             part.nCells)[part.cells] for ph in phases]
    p = plot.read_field(os.path.join(case, time, "p"),
                        part.nCells)[part.cells]
    colours = plot.phase_colours(len(phases))
    colours[-1] = plot.hex_to_rgb(plot.AMBIENT_LINE)
    # The colour at mid-height over cells a phase fills (to 1e-3): its own
    worst, n = 0.0, 0
    for k in range(len(phases)):
        full = np.nonzero(alpha[k] > 0.999)[0]
        for c in full[len(full) // 4::max(len(full) // 4, 1)][:3]:
            diff = np.abs(pixel(png, to_pixel(x[c], 0.5)) -
                          colours[k] * 255).max()
            worst = max(worst, diff)
            n += 1
    # The field's curve passes through each cell's (x, p): a dark pixel
    # within one pixel of it, at ten cells
    from PIL import Image
    image = np.array(Image.open(png).convert("L"), dtype=float)
    misses = 0
    for c in np.linspace(0, len(x) - 1, 10).astype(int):
        col, row = to_pixel(x[c], p[c], panel=1)
        if image[row - 1:row + 2, col - 1:col + 2].min() > 100:
            misses += 1
    ok = ok and n >= 2 * len(phases) - 1 and worst <= 2 and misses == 0 \
        and part.geometry == "line" and len(part.cells) == part.nCells
    checks.check("impactPlot_line", ok,
                 "waterAirShockTube (%d cells, one across): exit %d, drawn "
                 "as %s; colour at mid-height over %d cells a phase fills "
                 "off its colour by %.0f of 255 (bound 2); the p curve "
                 "misses %d of 10 cells' (x, p)"
                 % (part.nCells, code, part.geometry, n, worst, misses))


def check_boundary_plane(case):
    """3-D: a plane on the mesh's boundary (z = -20 mm, the domain's min)
    draws the layer of cells above it"""
    roots = plot.roots_of(case)
    parts = plot.slice_parts(roots, (np.array([0, 0, -20e-3]),
                                     np.array([0, 0, 1.0])))
    drawn = sum(len(p.cells) for p in parts)
    code, out = run_plot(case, ["-latestTime", "-plane",
                                "0,0,-0.02,0,0,1"])
    checks.check("impactPlot_boundaryPlane", code == 0 and drawn == 35 * 20,
                 "the plane z = -20 mm (the mesh's boundary): exit %d, %d "
                 "cells drawn (one layer: %d)" % (code, drawn, 35 * 20))


def main():
    fc.require_apps("impactSetup", "impactFoam", "blockMesh")
    check_blend()
    try:
        check_line()
    except (fc.FoamError, plot.PlotError) as e:
        checks.fail("impactPlot_line", getattr(e, "summary", None) or str(e))
    cases = {}
    for geometry in ("axisymmetric", "planar", "threeD"):
        try:
            cases[geometry] = check_geometry(geometry)
        except (fc.FoamError, plot.PlotError) as e:
            checks.fail("impactPlot_" + geometry,
                        getattr(e, "summary", None) or str(e))
    case = cases.get("axisymmetric")
    if case:
        try:
            check_binary(case)
        except (fc.FoamError, plot.PlotError) as e:
            checks.fail("impactPlot_binary",
                        getattr(e, "summary", None) or str(e))
        check_field(case)
        check_animate(case)
    if cases.get("threeD"):
        check_boundary_plane(cases["threeD"])
        check_errors(case)
    checks.exit()


if __name__ == "__main__":
    main()
