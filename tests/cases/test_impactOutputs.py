#!/usr/bin/python3
"""impactDict's outputs (docs/impactSetup.md section 7): the time histories
follow the bodies as the user names and places them.

The projectileOnPlate template copied as a user would: the rod renamed
penetrator (phase slug), the plate armour (phase armour), the whole problem
moved 20 mm along +x (domain, plate; the gap places the rod), an outputs
block added, nothing else edited; `./Allrun -h 1 -end 2e-6` (1 mm cells).

Checks
  outputs_files         the four tables named in outputs are written, and
                        system/impactOutputs carries impactSetup's mark
  outputs_penetration   the penetration is measured from the moved armour's
                        face (x = 20 mm) along the penetrator's velocity:
                        at t = 0 it is minus the gap (0.5 mm, to 0.05 of a
                        cell), and at 1 and 2 us it equals the last place
                        on the axis row where alpha.slug falls through 1/2
                        (linear between cell centres), from the written
                        fields, to 1e-9 m
  outputs_motion        at 1 and 2 us the penetrator's mass and mean
                        velocity equal sum alpha rho V and the mass-weighted
                        U of the written fields (times 2 pi/sin(theta) on
                        the wedge) to 1e-8, its largest fragment's those of
                        the heaviest face-connected set of cells with
                        alpha >= 0.6 (fragmentAlpha), and the number of
                        such sets; at t = 0 the mass is impactSetup's exact
                        mass to 1e-5 (the solver's state holds the alphaMin
                        floor that 0/ does not: 1e-6 of it here) and the
                        largest fragment moves at -1500 m/s
  outputs_wallForce     the force of xMin on the armour before the impact's
                        wave reaches it is the ambient pressure on the whole
                        disc, p0 pi R^2 along +x (R = 20 mm), to 1e-9
  outputs_interval      the tables have a row every 1e-7 s (interval)
  outputs_defaults      the template as it is, without outputs: impactSetup
                        writes the energy budget, rodMotion, rodPenetration
                        from the plate's face (0 0 0) along (-1 0 0) and
                        wallForce
  outputs_error_<what>  a bad outputs entry stops impactSetup with a message
                        naming it: unknown type (with the nearest), unknown
                        body (with the nearest), unknown keyword in an entry,
                        unknown patch, a penetration line that misses its
                        target body
About 20 s.
"""
import math
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
import meshGeometry as mg                     # noqa: E402
from checks import Checks                     # noqa: E402

checks = Checks()
RUN = os.path.join(HERE, "..", "run", "impactOutputs")
TEMPLATE = "templates/projectileOnPlate"
SHIFT = 20e-3          # the problem moved along +x
GAP = 0.5e-3           # the template's gap between rod and plate
P0 = 1e5               # the ambient pressure
R_DOMAIN = 20e-3       # the domain's radius (the wall disc under the plate)
INTERVAL = 1e-7
FRAGMENT_ALPHA = 0.6   # off the fractions 1/2 and 0.45 of the rod's
                       # tip and side cells at t = 0 (1 mm cells)

OUTPUTS = """
outputs
{
    interval    %g;
    depth       { type penetration; body penetrator; into armour; }
    residual    { type motion; body penetrator; fragmentAlpha %g; }
    support     { type wallForce; patches (xMin); }
    energy      { type energy; }
}
""" % (INTERVAL, FRAGMENT_ALPHA)


def user_dict(text):
    """The template's impactDict as the user edits it: bodies and phases
    renamed, everything moved by SHIFT along x, and the outputs added."""
    subs = [
        (r"min\s+\(-10e-3 0 0\);", "min         (%g 0 0);" % (SHIFT - 10e-3)),
        (r"max\s+\(60e-3 20e-3 0\);", "max         (%g 20e-3 0);"
         % (SHIFT + 60e-3)),
        (r"\brod\n(\s*)\{", r"penetrator\n\1{"),
        (r"phase\s+rod;", "phase       slug;"),
        (r"gap\s+\{ to plate;", "gap         { to armour;"),
        (r"\bplate\n(\s*)\{", r"armour\n\1{"),
        (r"min\s+\(-10e-3 0 -1\);", "min         (%g 0 -1);"
         % (SHIFT - 10e-3)),
        (r"max\s+\(0 15e-3 1\);", "max         (%g 15e-3 1);" % SHIFT),
        (r"phase\s+plate;", "phase       armour;"),
    ]
    for pattern, new in subs:
        text, n = re.subn(pattern, new, text, count=1)
        if n != 1:
            raise fc.FoamError("template impactDict: no match for %s"
                               % pattern)
    i = text.rindex("// ****")
    return text[:i] + OUTPUTS + "\n" + text[i:]


def row_at(table, t):
    names, rows = table
    i = int(np.argmin(np.abs(rows[:, 0] - t)))
    if abs(rows[i, 0] - t) > 1e-9 * max(t, 1e-6):
        raise fc.FoamError("no row at t = %g (nearest %g)" % (t, rows[i, 0]))
    return dict(zip(names, rows[i]))


def fragments(m, inside):
    """Labels of the face-connected sets of cells where inside is true
    (-1 elsewhere)"""
    label = np.full(m.nCells, -1)
    own, nei = m.owner[:m.nInternalFaces], m.neighbour
    both = inside[own] & inside[nei]
    adj = [[] for _ in range(m.nCells)]
    for a, b in zip(own[both], nei[both]):
        adj[a].append(b)
        adj[b].append(a)
    n = 0
    for c in np.nonzero(inside)[0]:
        if label[c] >= 0:
            continue
        stack = [c]
        label[c] = n
        while stack:
            d = stack.pop()
            for e in adj[d]:
                if label[e] < 0:
                    label[e] = n
                    stack.append(e)
        n += 1
    return label, n


def axis_penetration(m, alpha, x0):
    """The last place along -x from x0, on the row of cells next to the
    axis, where alpha falls through 1/2 (linear between centres)"""
    r = np.hypot(m.C[:, 1], m.C[:, 2])
    row = np.nonzero(r <= r.min() * (1 + 1e-6))[0]
    s = x0 - m.C[row, 0]
    order = np.argsort(s)
    s, a = s[order], alpha[row][order]
    P = None
    for i in range(len(s) - 1):
        if a[i] >= 0.5 > a[i + 1]:
            P = s[i] + (a[i] - 0.5) / (a[i] - a[i + 1]) * (s[i + 1] - s[i])
    return P


def check_user_case():
    case = fc.copy_tutorial(TEMPLATE, "user", run_dir=RUN)
    path = os.path.join(case, "system", "impactDict")
    with open(path) as f:
        text = user_dict(f.read())
    with open(path, "w") as f:
        f.write(text)
    fc.run(case, ["./Allrun", "-h", "1", "-end", "2e-6"], log="log.Allrun")

    generated = os.path.join(case, "system", "impactOutputs")
    with open(generated) as f:
        marked = f.readline().startswith("// Generated by impactSetup")
    names = ["depth", "residual", "support", "energy"]
    present = [n for n in names if os.path.isfile(
        os.path.join(case, "postProcessing", n, "0", n + ".dat"))]
    checks.check("outputs_files", marked and present == names,
                 "tables %s of %s; impactOutputs marked: %s"
                 % (present, names, marked))

    m = mg.read_polymesh(case)
    toFull = mg.wedge_to_full(m)
    depth = fc.read_history(case, "depth")
    residual = fc.read_history(case, "residual")
    times = ["0", "1e-06", "2e-06"]

    # Penetration: minus the gap at the start, the fields' at the writes
    P0row = row_at(depth, 0.0)["P"]
    errs = []
    for t in times[1:]:
        alpha = fc.read_field(case, t, "alpha.slug")
        P = axis_penetration(m, alpha, SHIFT)
        errs.append(abs(row_at(depth, float(t))["P"] - P))
    checks.check("outputs_penetration",
                 abs(P0row + GAP) <= 0.05e-3 and max(errs) <= 1e-9,
                 "P(0) = %.6g m (minus the gap: %.6g), |P - fields| at 1, 2 "
                 "us: %.2e, %.2e m (bounds 5e-5, 1e-9)"
                 % (P0row, -GAP, errs[0], errs[1]))

    # Motion and the largest fragment
    worst = 0.0
    text = []
    for t in times[1:]:
        a = fc.read_field(case, t, "alpha.slug")
        rho = fc.read_field(case, t, "rho.slug")
        U = fc.read_field(case, t, "U")
        mc = a * rho * m.V
        mass = toFull * mc.sum()
        Ux = (mc * U[:, 0]).sum() / mc.sum()
        if np.any(np.abs(a - FRAGMENT_ALPHA) < 1e-8):
            raise fc.FoamError("t = %s: a cell's alpha.slug is within 1e-8 "
                               "of fragmentAlpha: which side it is on is "
                               "round-off" % t)
        label, n = fragments(m, a >= FRAGMENT_ALPHA)
        fm = np.bincount(label[label >= 0], weights=mc[label >= 0],
                         minlength=n)
        big = int(np.argmax(fm))
        sel = label == big
        fragMass = toFull * fm[big]
        fragUx = (mc[sel] * U[sel, 0]).sum() / fm[big]
        row = row_at(residual, float(t))
        errs = [abs(row["mass"] / mass - 1), abs(row["Ux"] / Ux - 1),
                abs(row["fragmentMass"] / fragMass - 1),
                abs(row["fragmentUx"] / fragUx - 1)]
        worst = max([worst] + errs)
        if row["fragments"] != n:
            worst = max(worst, 1.0)
        text.append("t %s: mass %.6g kg, Ux %.6g m/s, %d fragments, largest "
                    "%.6g kg at %.6g m/s" % (t, mass, Ux, n, fragMass,
                                             fragUx))
    with open(os.path.join(case, "log.impactSetup")) as f:
        setup = f.read()
    mExact = float(re.search(r"Body penetrator[^\n]*\n(?:[^\n]*\n)*?\s+mass "
                             r"([0-9.eE+-]+)", setup).group(1))
    start = row_at(residual, 0.0)
    checks.check("outputs_motion",
                 worst <= 1e-8 and abs(start["mass"] / mExact - 1) <= 1e-5
                 and abs(start["fragmentUx"] / -1500 - 1) <= 1e-12,
                 "; ".join(text) + "; largest relative difference from the "
                 "fields %.1e (bound 1e-8); at 0 mass %.10g against "
                 "impactSetup's %.10g, the largest fragment at %.15g m/s"
                 % (worst, start["mass"], mExact, start["fragmentUx"]))

    # The wall's force before the wave reaches it
    support = fc.read_history(case, "support")
    names, rows = support
    Fx = rows[1, names.index("xMin.Fx")]
    exact = P0 * math.pi * R_DOMAIN**2
    checks.check("outputs_wallForce", abs(Fx / exact - 1) <= 1e-9,
                 "xMin.Fx %.10g N at t = %.3g s against p0 pi R^2 = %.10g N"
                 % (Fx, rows[1, 0], exact))

    dt = np.diff(depth[1][:, 0])
    checks.check("outputs_interval",
                 len(dt) >= 19 and np.all(np.abs(dt - INTERVAL)
                                          <= 0.5 * INTERVAL),
                 "%d rows, spacing %.4g to %.4g s (interval %g)"
                 % (len(dt) + 1, dt.min(), dt.max(), INTERVAL))


def check_defaults():
    case = fc.copy_tutorial(TEMPLATE, "defaults", run_dir=RUN)
    fc.run(case, ["impactSetup", "-cellSize", "1e-3"])
    with open(os.path.join(case, "system", "impactOutputs")) as f:
        text = f.read()
    found = re.findall(r"^(\w+)\s*\n\{\s*\n\s*type\s+(\w+);", text, re.M)
    pen = re.search(r"rodPenetration\s*\{[^}]*point\s+\(\s*([^)]*)\)"
                    r"[^}]*direction\s+\(\s*([^)]*)\)", text)
    ok = found == [("energy", "energyBudget"), ("rodMotion", "bodyMotion"),
                   ("rodPenetration", "penetration"),
                   ("wallForce", "wallForce")] and pen is not None
    if ok:
        point = [float(v) for v in pen.group(1).split()]
        direction = [float(v) for v in pen.group(2).split()]
        ok = np.allclose(point, [0, 0, 0], atol=1e-12) and \
            np.allclose(direction, [-1, 0, 0], atol=1e-12)
    checks.check("outputs_defaults", ok, "tables %s; rodPenetration %s"
                 % (found, pen.groups() if pen else None))


ERRORS = [
    ("type", "outputs { d { type penetraton; body rod; into plate; } }",
     ["unknown type penetraton", "did you mean penetration"]),
    ("body", "outputs { m { type motion; body rood; } }",
     ["names rood", "not a body", "did you mean rod"]),
    ("keyword", "outputs { m { type motion; bdy rod; } }",
     ["bdy"]),
    ("patch", "outputs { w { type wallForce; patches (xMn); } }",
     ["no patch xMn"]),
    ("line", "outputs { d { type penetration; body rod; into plate; "
     "direction (1 0 0); } }", ["does not meet body plate"]),
]


def check_errors():
    for what, entry, expect in ERRORS:
        name = "outputs_error_" + what
        case = fc.copy_tutorial(TEMPLATE, "error_" + what, run_dir=RUN)
        path = os.path.join(case, "system", "impactDict")
        with open(path) as f:
            text = f.read()
        i = text.rindex("// ****")
        with open(path, "w") as f:
            f.write(text[:i] + entry + "\n" + text[i:])
        log = fc.run(case, ["impactSetup", "-cellSize", "2e-3"], check=False)
        with open(log) as f:
            out = " ".join(f.read().split())
        missing = [e for e in expect if e not in out]
        fatal = "FOAM FATAL" in out
        msg = re.search(r"(impactDict outputs[^.]*)", out)
        checks.check(name, fatal and not missing,
                     "%s; missing %s" % (msg.group(1)[:200] if msg else
                                         "no message", missing))


def main():
    fc.require_apps("impactSetup", "impactFoam", "blockMesh")
    for step in (check_user_case, check_defaults, check_errors):
        try:
            step()
        except fc.FoamError as e:
            checks.fail("outputs_" + step.__name__[6:], e.summary or str(e))
    checks.exit()


if __name__ == "__main__":
    main()
