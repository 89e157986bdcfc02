#!/usr/bin/python3
"""taylorTest helper (standard library only): the specimen's initial state
from its material's equation of state, a stopping-time estimate, and its
final shape from rodProfile's output.

  specimen.py state -L0 <m> -v <m/s> -T0 <K> [-p0 <Pa>] [-case <dir>]
      prints  rho <kg/m3>, sigma <Pa>, tStop <s>, T <K> (one per line):
      rho    the density of the specimen's material at rest at (p0, T0), from
             its equation of state (MieGruneisen: p_ref(rho) = p0 -
             rho0 Gamma0 Cv (T0 - T0ref), docs/materials.md; stiffenedGas
             with Cv: rho = (p0 + pInf)/((gamma - 1) Cv T0); without a
             temperature (no Cv): the elastic rho0, T0 is not used);
      sigma  a representative flow stress: the yield stress at equivalent
             plastic strain 0.5, plastic strain rate 1e3/s and T0;
      tStop  rho L0 v / sigma: the time a force sigma A0 on the wall takes
             to stop the specimen's momentum rho A0 L0 v. The wall force is
             larger (the contact grows into the mushroom and the front
             hardens), so the specimen stops earlier.
  specimen.py shape [-case <dir>] [-L0 <m>]
      prints the final length Lf, the foot's radius Rf at the impact face
      (rodProfile's faceRadius: the outline of the first two cell rows
      extended to the face, where the measured specimens' largest radius
      lies) and the radius at f Lf (f = 0.2, 0.25, 1/3, 1/2, 2/3) of the last time rodProfile
      processed (postProcessing/rodProfile/specimen.csv and profile_*.csv),
      in mm, and writes them to postProcessing/shape.csv.

The specimen's dictionary is resolved as impactFoam does (phaseMaterial.H):
constant/materials/<name>, then $IMPACTFOAM_DIR/etc/materials/<name>, then
the keywords of the phase's own dictionary on top.
"""
import csv
import math
import os
import re
import sys

FRACTIONS = (0.2, 0.25, 1.0 / 3.0, 0.5, 2.0 / 3.0)
FRACTION_NAMES = ("0.2", "0.25", "0.333", "0.5", "0.667")


# --------------------------------------------------------------------------
# OpenFOAM dictionaries (the subset the material files use)
# --------------------------------------------------------------------------

def _tokens(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    text = re.sub(r"^\s*#[^\n]*", " ", text, flags=re.M)
    return re.findall(r'"[^"]*"|[{}();]|[^\s{}();]+', text)


def _parse(tokens, i=0):
    d = {}
    while i < len(tokens):
        t = tokens[i]
        if t == "}":
            return d, i + 1
        key = t.strip('"')
        i += 1
        if i < len(tokens) and tokens[i] == "{":
            sub, i = _parse(tokens, i + 1)
            d[key] = sub
            continue
        value, depth = [], 0
        while i < len(tokens) and not (tokens[i] == ";" and depth == 0):
            depth += tokens[i] == "("
            depth -= tokens[i] == ")"
            value.append(tokens[i])
            i += 1
        d[key] = " ".join(value)
        i += 1
    return d, i


def read_dict(path):
    with open(path) as f:
        d, _ = _parse(_tokens(f.read()))
    d.pop("FoamFile", None)
    return d


def merge_onto(base, top):
    """phaseMaterial::mergeOnto: top wins; sub-dictionaries of the same type
    (or without a type in top) are merged, others replaced."""
    for k, v in top.items():
        if isinstance(v, dict) and isinstance(base.get(k), dict) \
                and ("type" not in v or v["type"] == base[k].get("type")):
            merge_onto(base[k], v)
        else:
            base[k] = v
    return base


def material_places(name, case):
    root = os.environ.get("IMPACTFOAM_DIR", "")
    return [os.path.join(case, "constant", "materials", name),
            os.path.join(root, "etc", "materials", name) if root
            else "$IMPACTFOAM_DIR/etc/materials/" + name]


def phase_dict(case, phase="specimen"):
    props = read_dict(os.path.join(case, "constant", "phaseProperties"))
    d = props[phase]
    # ./Allrun -material writes constant/specimenMaterial, included by the
    # specimen's dictionary
    chosen = os.path.join(case, "constant", "specimenMaterial")
    if phase == "specimen" and os.path.isfile(chosen):
        d.update(read_dict(chosen))
    if "material" not in d:
        return d
    for path in material_places(d["material"], case):
        if os.path.isfile(path):
            return merge_onto(read_dict(path), d)
    sys.exit("specimen.py: phase %s: unknown material %s; searched %s"
             % (phase, d["material"], ", ".join(material_places(
                 d["material"], case))))


# --------------------------------------------------------------------------
# Initial state and flow stress
# --------------------------------------------------------------------------

def _f(d, k, default=None):
    if k not in d:
        if default is None:
            raise KeyError(k)
        return default
    return float(d[k])


def rest_density(ph, p0, T0):
    """Density at rest at (p0, T0) and the temperature used (None when the
    equation of state has no temperature)."""
    eos = ph["equationOfState"]
    kind = eos["type"]
    if kind == "MieGruneisen":
        rho0, c0, s = _f(eos, "rho0"), _f(eos, "c0"), _f(eos, "s")
        G0, Cv, Tref = _f(eos, "Gamma0"), _f(eos, "Cv"), _f(eos, "T0")
        target = p0 - rho0 * G0 * Cv * (T0 - Tref)      # = p_ref(rho)

        def p_ref(rho):
            eta = 1.0 - rho0 / rho
            if eta >= 0:
                return rho0 * c0 * c0 * eta / (1.0 - s * eta) ** 2
            return rho0 * c0 * c0 * eta
        lo, hi = 0.5 * rho0, rho0 / (1.0 - 0.5 / s)
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if p_ref(mid) < target:
                lo = mid
            else:
                hi = mid
        return 0.5 * (lo + hi), T0
    if kind == "stiffenedGas":
        if "Cv" in eos:
            gamma, pInf, Cv = _f(eos, "gamma"), _f(eos, "pInf"), \
                _f(eos, "Cv")
            return (p0 + pInf) / ((gamma - 1.0) * Cv * T0), T0
        return _f(ph["elasticity"], "rho0"), None
    sys.exit("specimen.py: equation of state %s: no rest density rule" % kind)


def flow_stress(ph, T, epsP=0.5, rate=1e3):
    pl = ph.get("plasticity", {})
    if pl.get("type", "none") != "vonMises":
        sys.exit("specimen.py: the specimen has no Von Mises plasticity")
    ys = pl.get("yieldStress")
    if ys is None:
        s0 = _f(pl, "sigmaY0") if "sigmaY0" in pl else _f(pl, "sigmaY")
        return s0 + _f(pl, "H", 0.0) * epsP
    kind = ys["type"]
    if kind == "constant":
        return _f(ys, "sigmaY")
    if kind == "linear":
        return _f(ys, "sigmaY0") + _f(ys, "H") * epsP
    if kind == "table":
        nums = [float(x) for x in re.findall(r"[-+0-9.eE]+", ys["values"])]
        pts = list(zip(nums[0::2], nums[1::2]))
        for (e0, s0), (e1, s1) in zip(pts, pts[1:]):
            if e0 <= epsP <= e1:
                return s0 + (s1 - s0) * (epsP - e0) / (e1 - e0)
        return pts[-1][1]
    if kind == "JohnsonCook":
        A, B, n = _f(ys, "A"), _f(ys, "B"), _f(ys, "n")
        C, m = _f(ys, "C"), _f(ys, "m")
        Tr, Tm, e0 = _f(ys, "Tr"), _f(ys, "Tm"), _f(ys, "epsDot0")
        Th = min(max(((T if T is not None else Tr) - Tr) / (Tm - Tr), 0.0),
                 1.0)
        return (A + B * epsP ** n) * (1 + C * math.log(max(rate / e0, 1.0))) \
            * (1 - Th ** m)
    sys.exit("specimen.py: yieldStress %s: no flow stress rule" % kind)


# --------------------------------------------------------------------------
# Final shape
# --------------------------------------------------------------------------

def read_rod_table(case, phase="specimen"):
    path = os.path.join(case, "postProcessing", "rodProfile", phase + ".csv")
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def last_profile(case, phase="specimen"):
    d = os.path.join(case, "postProcessing", "rodProfile")
    times = [n for n in os.listdir(d) if os.path.isdir(os.path.join(d, n))]
    t = max(times, key=float)
    z, r = [], []
    with open(os.path.join(d, t, "profile_" + phase + ".csv")) as f:
        for row in csv.DictReader(f):
            z.append(float(row["z"]))
            r.append(float(row["radius"]))
    return t, z, r


def radius_at(z, r, zq):
    pts = sorted(zip(z, r))
    for (z0, r0), (z1, r1) in zip(pts, pts[1:]):
        if z0 <= zq <= z1:
            return r0 + (r1 - r0) * (zq - z0) / (z1 - z0) if z1 > z0 else r0
    return float("nan")


def shape(case):
    """Lf, Rf, [W(f Lf)] in m at the last processed time, and that time."""
    tab = read_rod_table(case)
    t, z, r = last_profile(case)
    Lf = tab["length"][-1]
    Rf = tab["faceRadius"][-1]
    return Lf, Rf, [radius_at(z, r, f * Lf) for f in FRACTIONS], float(t)


# --------------------------------------------------------------------------

def _options(argv):
    opts = {}
    for k, v in zip(argv[0::2], argv[1::2]):
        opts[k.lstrip("-")] = v
    return opts


def main(argv):
    if not argv or argv[0] not in ("state", "shape"):
        sys.exit(__doc__)
    opts = _options(argv[1:])
    case = opts.get("case", ".")
    if argv[0] == "state":
        ph = phase_dict(case)
        p0 = float(opts.get("p0", 1e5))
        rho, T = rest_density(ph, p0, float(opts["T0"]))
        sigma = flow_stress(ph, T)
        tstop = rho * float(opts["L0"]) * float(opts["v"]) / sigma
        print("rho %.10g" % rho)
        print("sigma %.6g" % sigma)
        print("tStop %.6g" % tstop)
        print("T %s" % ("none" if T is None else "%g" % T))
        return 0
    Lf, Rf, W, t = shape(case)
    lines = ["time_s,%.6g" % t, "Lf_mm,%.4f" % (Lf * 1e3),
             "Rf_mm,%.4f" % (Rf * 1e3)]
    lines += ["Wf_%s_mm,%.4f" % (n, w * 1e3)
              for n, w in zip(FRACTION_NAMES, W)]
    with open(os.path.join(case, "postProcessing", "shape.csv"), "w") as f:
        f.write("quantity,value\n" + "\n".join(lines) + "\n")
    print("Final shape at t = %g s:" % t)
    print("  length Lf          %.3f mm" % (Lf * 1e3))
    print("  foot radius Rf     %.3f mm (at the impact face)" % (Rf * 1e3))
    for n, w in zip(FRACTION_NAMES, W):
        print("  radius at %-5s Lf %.3f mm" % (n, w * 1e3))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
