#!/usr/bin/python3
"""V9 (docs/validation.md, docs/numerics.md 8): bad input and unphysical runs.

Base case: tests/cases/badInput/copperAir, a valid 1-D case (50 cells,
3 steps): a copper slab (solid, separable a = 1/2, mu 4.5e10, Von Mises
sigmaY 3e8) at x < 0.5 in contact with air, each phase with a trace of
1e-8 of the other. Each variant copies it, runs blockMesh and setFields
on the valid input, breaks one thing, and runs impactFoam.

Bad input (each must stop at start-up): impactFoam exits non-zero, the log
holds 'FOAM FATAL' (ERROR or IO ERROR) and the fatal message names the
problem (the keywords below, searched in the text after 'FOAM FATAL'), no
time directory other than 0 is written, and no file of the case's time
directories holds a NaN.

    a07           elasticity a 0.7 (hyperbolic only for a in [-1, 1/2])
    negativeMu    elasticity mu -4.5e10
    zeroSigmaY    vonMises sigmaY 0
    negSigmaY     vonMises sigmaY -3e8
    unknownPhase  an extra 0/alpha.steel with phases (copper air)
    alphaSum      alpha.copper = alpha.air = 0.6 everywhere
    missingField  no 0/rho.air
    unknownEoS    equationOfState type vanDerWaals
    badPhaseType  phase type liquid (only solid | fluid)
    jcWithoutCv   copper with a Johnson-Cook flow stress and an equation
                  of state without Cv (no temperature)
    jcBadN        Johnson-Cook n 0 (the message names n)
    jcTmBelowTr   Johnson-Cook Tm 200 below Tr 298
    tableNotIncreasing  yieldStress table with epsP 0, 0.1, 0.05
    tableNotFromZero    yieldStress table starting at epsP 0.01
    writeTWithoutCv     air with writeTemperature yes and no Cv
    mieGruneisenBeyondRhoMax
                  copper as Mie-Grueneisen (s 1.489: rhoMax = rho0/(1 -
                  1/s) = 27100) starting at rho.copper 30000
    unknownAlphaReconstruction, thincBeta, thincWithCompression
                  alphaReconstruction sharp; THINC beta 20; THINC with
                  alphaCompression 2
    unknownCobasisLimiter, unknownVelocityLimiter, unknownCobasisRotation,
    unknownWaveSpeeds
                  that discreteEquations entry set to "bogus" (the message
                  names the entry, the word and the valid words)
    unknownThincRange
                  THINCCoeffs { range bogus; } with THINC
    unknownPressureRelaxation
                  air with pressureRelaxation adiabatic (names the phase)
    massFractionMinor
                  massFractionMinor 2 in phaseProperties (a mass fraction
                  is below 1)
    unknownThreshold
                  alphaMinr 1e-3 in phaseProperties (an entry no rule reads:
                  the message names it and lists the valid ones)
    misspelledTopLevel, misspelledPhase, misspelledEquationOfState,
    misspelledElasticity, misspelledPlasticity, misspelledYieldStress,
    misspelledFailure, misspelledDiscreteEquations, misspelledMaterialFile
                  a misspelled entry in each kind of dictionary (strict
                  input): pVacum in phaseProperties, failur in a phase, Cvv
                  in an equationOfState, muu in elasticity, nn in
                  plasticity, epsDot in a Johnson-Cook yieldStress,
                  spallTim in failure, predictorRelaxaton in
                  discreteEquations, pressureRelaxaton in a material file
                  of constant/materials. The message names the dictionary,
                  the entry, its line and file (the material file for the
                  last), the nearest valid word and the valid ones.
    gasTraceRatio gasTraceRatio -1 in phaseProperties (a ratio of volumes
                  is not negative)
The valid base case must run to its end time (control), and its log
holds the block of defaults once, before the time loop, listing defaults
it uses (waveSpeeds Davis, n 0, pVacuum 1, ...) and none of the entries it
gives (defaultsPrintedOnce).

Unphysical runs (must stop during the run with a FatalError whose message
says 'unphysical state' and names the phase, the cell, the time and the
offending value and what the user may change ("What may help:"), after
writing the last good fields: the time directory
named in the message exists, is earlier than the failure time, is the
latest one, and holds finite fields with rho > 0 and p > -pInf for every
phase):
    copperLeavesAir   the copper slab moves away from the air at 5000 m/s
                      (faster than the air's escape speed 2c/(gamma - 1)
                      = 1710 m/s) with the vacuum floor switched off
                      (pVacuum -1): the gap is a vacuum and the air's
                      pressure goes negative.
    separation        copper at -5000 m/s, air at +5000 m/s, traces 1e-6
                      (at the default trace threshold alphaTrace 1e-6, so
                      both phases stay active in every cell), vacuum floor
                      off.
Runs that must complete (they stopped before a fix):
    vacuum            copperLeavesAir with the default settings: the air
                      torn open behind the copper takes the vacuum floor
                      (pVacuum, default 1 Pa); the run completes with finite
                      fields, the air's pressure at or above the floor and
                      the log reporting the floored cells.
    mieGruneisenRebound
                      copper as Mie-Grueneisen (docs/model.md 10.1, rho0 8900)
                      and the air at -3000 m/s onto a slip wall (the left
                      patch): a 240 GPa shock, then the hot copper
                      rebounds. The run completes, with finite fields and
                      copper admissible (rho < rhoMax, p > pMin(rho)) at
                      the end. It used to stop beyond rhoMax after mixed
                      cells had handed the copper a spurious tension of
                      1e15 Pa (the interface-pressure root is now
                      converged in volume too, docs/model.md section 11).
"""
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

BASE = os.path.join(HERE, "badInput", "copperAir")
PHASES = ("copper", "air")
P_INF = {"copper": 3.42e10, "air": 0.0}
RUN_TIMEOUT = 120

checks = Checks()


# --------------------------------------------------------------------------
# Editing the copied case
# --------------------------------------------------------------------------

def edit(case, rel, old, new, count=1):
    """Replace old by new (count times) in case/rel; the text must be
    there."""
    path = os.path.join(case, rel)
    with open(path) as f:
        text = f.read()
    if text.count(old) < count:
        raise fc.FoamError("%s: '%s' not found" % (path, old))
    with open(path, "w") as f:
        f.write(text.replace(old, new, count))


def set_uniform(case, field, value):
    """Set the internalField of 0/<field> to uniform value."""
    path = os.path.join(case, "0", field)
    with open(path) as f:
        text = f.read()
    new, n = re.subn(r"internalField\s+[^;]*;",
                     "internalField   uniform %s;" % value, text, count=1)
    if n != 1:
        raise fc.FoamError("%s: no internalField" % path)
    with open(path, "w") as f:
        f.write(new)


def copy_field(case, src, dst):
    with open(os.path.join(case, "0", src)) as f:
        text = f.read()
    text = re.sub(r"(object\s+)%s;" % re.escape(src), r"\g<1>%s;" % dst,
                  text)
    with open(os.path.join(case, "0", dst), "w") as f:
        f.write(text)


PP = "constant/phaseProperties"
FS = "system/fvSchemes"

# OFHC copper (docs/materials.md, etc/materials/OFHCcopper) in place of 'sigmaY 3e8;'
JC = ("yieldStress { type JohnsonCook; A 9e7; B 2.92e8; n 0.31; C 0.025; "
      "m 1.09; Tr 298; Tm 1356; }")

def mg_pmin(rho, rho0=8900.0, c0=3940.0, s=1.489, Gamma0=2.02):
    """Lowest admissible pressure of the Mie-Grueneisen copper of
    mie_gruneisen (c^2 = 0: -F(eta)/Gamma0, docs/model.md section 10.1)."""
    eta = 1 - rho0 / np.asarray(rho)
    K = rho0 * c0 ** 2
    comp = K * (1 + (s - Gamma0) * eta) / (1 - s * np.maximum(eta, 0)) ** 3
    return -np.where(eta >= 0, comp, K * (1 - Gamma0 * eta)) / Gamma0

# name: (modification of the prepared case, keyword patterns, description)
BAD_INPUT = [
    ("a07",
     lambda c: edit(c, PP, "a 0.5;", "a 0.7;"),
     [r"\ba\s*=\s*0\.7|\[-1, 1/2\]"], "a = 0.7"),
    ("negativeMu",
     lambda c: edit(c, PP, "mu 4.5e10;", "mu -4.5e10;"),
     [r"\bmu\b"], "mu = -4.5e10"),
    ("zeroSigmaY",
     lambda c: edit(c, PP, "sigmaY 3e8;", "sigmaY 0;"),
     [r"sigmaY"], "sigmaY = 0"),
    ("negSigmaY",
     lambda c: edit(c, PP, "sigmaY 3e8;", "sigmaY -3e8;"),
     [r"sigmaY"], "sigmaY = -3e8"),
    ("unknownPhase",
     lambda c: copy_field(c, "alpha.air", "alpha.steel"),
     [r"steel"], "extra 0/alpha.steel"),
    ("alphaSum",
     lambda c: (set_uniform(c, "alpha.copper", 0.6),
                set_uniform(c, "alpha.air", 0.6)),
     [r"\bsum"], "alphas 0.6 + 0.6"),
    ("missingField",
     lambda c: os.remove(os.path.join(c, "0", "rho.air")),
     [r"rho\.air"], "no 0/rho.air"),
    ("unknownEoS",
     lambda c: edit(c, PP, "type stiffenedGas; gamma 1.4;",
                    "type vanDerWaals; gamma 1.4;"),
     [r"vanDerWaals"], "equationOfState type vanDerWaals"),
    ("badPhaseType",
     lambda c: edit(c, PP, "type            fluid;",
                    "type            liquid;"),
     [r"liquid"], "phase type liquid"),
    ("jcWithoutCv",
     lambda c: edit(c, PP, "sigmaY 3e8;", JC),
     [r"copper", r"\bCv\b", r"temperature"],
     "Johnson-Cook copper without Cv"),
    ("jcBadN",
     lambda c: (edit(c, PP, "sigmaY 3e8;", JC),
                edit(c, PP, "n 0.31;", "n 0;"),
                edit(c, PP, "pInf 3.42e10; }", "pInf 3.42e10; Cv 383; }")),
     [r"copper", r"\bn = 0\b"], "Johnson-Cook n = 0"),
    ("jcTmBelowTr",
     lambda c: (edit(c, PP, "sigmaY 3e8;", JC),
                edit(c, PP, "Tm 1356;", "Tm 200;"),
                edit(c, PP, "pInf 3.42e10; }", "pInf 3.42e10; Cv 383; }")),
     [r"copper", r"\bTm = 200\b", r"\bTr\b"], "Johnson-Cook Tm 200 < Tr"),
    ("tableNotIncreasing",
     lambda c: edit(c, PP, "sigmaY 3e8;",
                    "yieldStress { type table; values ((0 3e8) (0.1 4e8) "
                    "(0.05 5e8)); }"),
     [r"copper", r"values", r"strictly increasing"],
     "table epsP 0, 0.1, 0.05"),
    ("tableNotFromZero",
     lambda c: edit(c, PP, "sigmaY 3e8;",
                    "yieldStress { type table; values ((0.01 3e8) "
                    "(0.1 4e8)); }"),
     [r"copper", r"values", r"epsP = 0\.01"], "table from epsP 0.01"),
    ("writeTWithoutCv",
     lambda c: edit(c, PP, "type stiffenedGas; gamma 1.4; pInf 0; }",
                    "type stiffenedGas; gamma 1.4; pInf 0; }\n"
                    "    writeTemperature yes;"),
     [r"\bair\b", r"writeTemperature", r"\bCv\b"],
     "air with writeTemperature yes, no Cv"),
    ("mieGruneisenBeyondRhoMax",
     lambda c: (edit(c, PP, "equationOfState { type stiffenedGas; gamma "
                     "4.22; pInf 3.42e10; }",
                     "equationOfState { type MieGruneisen; rho0 8900; "
                     "c0 3940; s 1.489; Gamma0 2.02; Cv 383; T0 298; }"),
                set_uniform(c, "rho.copper", 30000)),
     [r"copper", r"rho = 30000", r"rho < 27100\.4"],
     "Mie-Grueneisen copper starting at rho 30000 > rhoMax = 27100"),
    ("unknownAlphaReconstruction",
     lambda c: edit(c, FS, "riemannSolver   HLLC;",
                    "riemannSolver   HLLC; alphaReconstruction sharp;"),
     [r"alphaReconstruction", r"\bsharp\b", r"THINC"],
     "alphaReconstruction sharp"),
    ("thincBeta",
     lambda c: edit(c, FS, "riemannSolver   HLLC;",
                    "riemannSolver   HLLC; alphaReconstruction THINC;"
                    " THINCCoeffs { beta 20; }"),
     [r"THINCCoeffs", r"beta 20", r"\[0\.5, 10\]"],
     "THINC beta 20"),
    ("thincWithCompression",
     lambda c: edit(c, FS, "riemannSolver   HLLC;",
                    "riemannSolver   HLLC; alphaReconstruction THINC;"
                    " alphaCompression 2;"),
     [r"alphaCompression 2", r"THINC"],
     "THINC with alphaCompression 2"),
    ("massFractionMinor",
     lambda c: edit(c, PP, "phases (copper air);",
                    "phases (copper air);\nmassFractionMinor 2;"),
     [r"massFractionMinor \(2\)", r"< 1"],
     "massFractionMinor 2"),
    ("unknownThreshold",
     lambda c: edit(c, PP, "phases (copper air);",
                    "phases (copper air);\nalphaMinr 1e-3;"),
     [r"phaseProperties: unknown entry alphaMinr",
      r"did you mean alphaMin(or)?\?", r"alphaMinor", r"dustDensityRatio"],
     "alphaMinr 1e-3 (a misspelled threshold)"),
    ("gasTraceRatio",
     lambda c: edit(c, PP, "phases (copper air);",
                    "phases (copper air);\ngasTraceRatio -1;"),
     [r"gasTraceRatio >= 0, not -1"],
     "gasTraceRatio -1"),
]


def unknown_option(name, entry, valid):
    """A V9 case: discreteEquations `entry` set to an unknown word; the
    message names the entry, the word and the valid words."""
    return ("unknown" + name[0].upper() + name[1:],
            lambda c: edit(c, FS, "riemannSolver   HLLC;",
                           "riemannSolver   HLLC; %s bogus;" % entry),
            [r"discreteEquations: unknown %s bogus" % entry,
             r"valid: \(%s\)" % " ".join(valid)],
            "%s bogus" % entry)


BAD_INPUT += [
    unknown_option("cobasisLimiter", "cobasisLimiter", ["cellLimited", "none"]),
    unknown_option("velocityLimiter", "velocityLimiter",
                   ["cellLimited", "none"]),
    unknown_option("cobasisRotation", "cobasisRotation", ["discard", "keep"]),
    unknown_option("waveSpeeds", "waveSpeeds", ["pressureBased", "Davis"]),
    ("unknownThincRange",
     lambda c: edit(c, FS, "riemannSolver   HLLC;",
                    "riemannSolver   HLLC; alphaReconstruction THINC;"
                    " THINCCoeffs { range bogus; }"),
     [r"discreteEquations THINCCoeffs: unknown range bogus",
      r"valid: \(neighbours full\)"],
     "THINCCoeffs range bogus"),
    ("unknownPressureRelaxation",
     lambda c: edit(c, PP, "equationOfState { type stiffenedGas; gamma 1.4; "
                    "pInf 0; }",
                    "equationOfState { type stiffenedGas; gamma 1.4; "
                    "pInf 0; } pressureRelaxation adiabatic;"),
     [r"Phase air: unknown pressureRelaxation adiabatic",
      r"valid: \(constantPressure isentropic\)"],
     "air pressureRelaxation adiabatic"),
]


# A material library file in the case (constant/materials/myCopper): the
# copper of the base case, with one misspelled entry
MY_COPPER = """FoamFile { version 2.0; format ascii; class dictionary;
           object myCopper; }
type            solid;
equationOfState { type stiffenedGas; gamma 4.22; pInf 3.42e10; }
elasticity      { type separable; rho0 8900; mu 4.5e10; a 0.5; }
plasticity      { type vonMises; sigmaY 3e8; tau 0; }
pressureRelaxaton constantPressure;
"""


def my_copper(case):
    """The copper phase as `material myCopper;` from the case's library
    file, which misspells pressureRelaxation."""
    os.makedirs(os.path.join(case, "constant", "materials"), exist_ok=True)
    with open(os.path.join(case, "constant", "materials", "myCopper"),
              "w") as f:
        f.write(MY_COPPER)
    edit(case, PP, """    type            solid;
    equationOfState { type stiffenedGas; gamma 4.22; pInf 3.42e10; }
    elasticity      { type separable; rho0 8900; mu 4.5e10; a 0.5; }
    plasticity      { type vonMises; sigmaY 3e8; tau 0; }""",
         "    material        myCopper;")


def misspelled(name, modify, owner, entry, nearest, what):
    """A V9 case: a misspelled entry in one kind of dictionary; the message
    names the dictionary's owner, the entry and the nearest valid word."""
    return ("misspelled" + name, modify,
            [r"%s: unknown entry %s \(line \d+ of " % (re.escape(owner),
                                                       entry),
             r"did you mean %s\?" % nearest, r"Valid entries: \("],
            what)


# Strict input (docs/numerics.md appendix C): an entry no reader knows
# stops the run, in every dictionary impactFoam reads
BAD_INPUT += [
    misspelled("TopLevel",
               lambda c: edit(c, PP, "phases (copper air);",
                              "phases (copper air);\npVacum 1;"),
               "phaseProperties", "pVacum", "pVacuum",
               "phaseProperties pVacum 1"),
    misspelled("Phase",
               lambda c: edit(c, PP, "sigmaY 3e8; tau 0; }",
                              "sigmaY 3e8; tau 0; }\n"
                              "    failur { type spall; sigmaSpall 1e9; }"),
               "Phase copper", "failur", "failure",
               "copper failur { type spall; ... }"),
    misspelled("EquationOfState",
               lambda c: edit(c, PP, "gamma 1.4; pInf 0; }",
                              "gamma 1.4; pInf 0; Cvv 718; }"),
               "Phase air, equationOfState", "Cvv", "Cv",
               "air equationOfState Cvv 718"),
    misspelled("Elasticity",
               lambda c: edit(c, PP, "a 0.5;", "a 0.5; muu 4.5e10;"),
               "Phase copper, elasticity", "muu", "mu",
               "copper elasticity muu"),
    misspelled("Plasticity",
               lambda c: edit(c, PP, "tau 0;", "tau 0; nn 0.5;"),
               "Phase copper, plasticity", "nn", "n",
               "copper plasticity nn 0.5"),
    misspelled("YieldStress",
               lambda c: (edit(c, PP, "sigmaY 3e8;",
                               JC.replace("Tm 1356;",
                                          "Tm 1356; epsDot 1;")),
                          edit(c, PP, "pInf 3.42e10; }",
                               "pInf 3.42e10; Cv 383; }")),
               "Phase copper, plasticity yieldStress", "epsDot", "epsDot0",
               "Johnson-Cook yieldStress epsDot 1"),
    misspelled("Failure",
               lambda c: edit(c, PP, "sigmaY 3e8; tau 0; }",
                              "sigmaY 3e8; tau 0; }\n    failure { type "
                              "spall; sigmaSpall 1e9; spallTim 1e-7; }"),
               "Phase copper, failure", "spallTim", "spallTime",
               "copper failure spall with spallTim"),
    misspelled("DiscreteEquations",
               lambda c: edit(c, FS, "riemannSolver   HLLC;",
                              "riemannSolver   HLLC; predictorRelaxaton no;"),
               "discreteEquations", "predictorRelaxaton",
               "predictorRelaxation",
               "discreteEquations predictorRelaxaton no"),
    ("misspelledMaterialFile",
     my_copper,
     [r"Phase copper: unknown entry pressureRelaxaton \(line 7 of "
      r"[^\n]*constant/materials/myCopper\)",
      r"did you mean pressureRelaxation\?"],
     "constant/materials/myCopper with pressureRelaxaton"),
]


def set_velocities(u_copper, u_air):
    def modify(case):
        edit(case, "system/setFieldsDict",
             "volVectorFieldValue U               (0 0 0)",
             "volVectorFieldValue U               (%g 0 0)" % u_air)
        edit(case, "system/setFieldsDict",
             "volVectorFieldValue U               (10 0 0)",
             "volVectorFieldValue U               (%g 0 0)" % u_copper)
        fc.set_entry(case, "system/controlDict", "endTime", "2e-4")
        fc.set_entry(case, "system/controlDict", "writeInterval", "1e-5")
    return modify


def traces(value):
    def modify(case):
        edit(case, "system/setFieldsDict", "1e-8", "%g" % value, count=2)
        edit(case, "system/setFieldsDict", "0.99999999", "%.10g"
             % (1 - value), count=2)
    return modify


def mie_gruneisen(case):
    """Copper as the Mie-Grueneisen solid of docs/model.md 10.1 (rho0 8900 to
    match its elasticity), the left patch a slip wall."""
    edit(case, PP, "equationOfState { type stiffenedGas; gamma 4.22; "
         "pInf 3.42e10; }",
         "equationOfState { type MieGruneisen; rho0 8900; c0 3940; "
         "s 1.489; Gamma0 2.02; Cv 383; T0 298; }")
    edit(case, "system/blockMeshDict", "type patch;", "type wall;")
    edit(case, "0.orig/U", "zeroGradient", "slip")


# name: (modifications before setFields, description, patterns the
# message must hold besides the common ones)
def run_to_completion(tag, name, modifications):
    """Set up and run a case that must complete: (case, log), or
    (None, None) after recording the failure under tag."""
    try:
        case = prepare(name, modifications)
    except (fc.FoamError, OSError) as e:
        checks.fail(tag, "could not set up the case: %s"
                    % getattr(e, "summary", e))
        return None, None
    code, log = run_impactfoam(case)
    if code != 0:
        checks.fail(tag, "exit code %s: %s" % (code, one_line(
            fatal_message(log) or log[-400:])))
        return None, None
    return case, log


def vacuum_off(case):
    """The vacuum floor switched off: a torn gas stops the run."""
    edit(case, PP, "phases (copper air);", "phases (copper air);\npVacuum -1;")


UNPHYSICAL = [
    ("copperLeavesAir", [set_velocities(-5000.0, 0.0), vacuum_off],
     "copper at -5000 m/s leaving air at rest (pVacuum -1)", []),
    ("separation", [set_velocities(-5000.0, 5000.0), traces(1e-6),
                    vacuum_off],
     "copper at -5000 m/s, air at +5000 m/s, traces 1e-6 (pVacuum -1)", []),
]


def check_vacuum():
    """copperLeavesAir with the default vacuum floor: completes, the torn
    air floored at 1 Pa (reported in the log), finite fields."""
    tag = "V9_vacuumFloorByDefault"
    case, log = run_to_completion(tag, "vacuum",
                                  [set_velocities(-5000.0, 0.0)])
    if case is None:
        return
    floored = re.findall(r"vacuum floor \(pVacuum\) in (\d+) cells", log)
    t = fc.latest_time(case)
    fields = [fc.read_field(case, t, f) for f in
              ("alpha.air", "rho.air", "p.air", "p.copper", "U")]
    finite = all(np.all(np.isfinite(f)) for f in fields)
    a, rho, p = fields[0], fields[1], fields[2]
    m = a > 1e-6
    checks.check(tag, finite and len(floored) > 0 and p[m].min() > 0.5
                 and rho[m].min() > 0,
                 "t = %s: fields finite %s; floor reported in %d steps (up "
                 "to %s cells); air (alpha > 1e-6) p >= %.4g Pa, rho >= "
                 "%.3g" % (t, finite, len(floored),
                           max([int(n) for n in floored] or [0]),
                           p[m].min(), rho[m].min()))


def check_removed_threshold():
    """massFractionTrace, an entry no longer read: the run completes and
    the log warns, naming the entry and the rule that replaced it."""
    tag = "V9_removedThresholdWarns"
    case, log = run_to_completion(
        tag, "removedThreshold",
        [lambda c: edit(c, PP, "phases (copper air);",
                        "phases (copper air);\nmassFractionTrace 1e-5;")])
    if case is None:
        return
    warned = re.search(r"massFractionTrace is no longer read[^\n]*\n?[^\n]*"
                       r"massFractionMinor", log)
    checks.check(tag, warned is not None,
                 "warning in the log: %s" % (one_line(warned.group(0))
                                             if warned else "none"))


def check_rebound():
    """Mie-Grueneisen copper and air at -3000 m/s onto a wall: a 240 GPa
    shock, then the hot copper rebounds; the run must complete with finite,
    admissible states (the interface-pressure root converged in volume:
    before, mixed cells handed the copper a spurious tension of 1e15 Pa
    and the run stopped beyond rhoMax)."""
    tag = "V9_mieGruneisenRebound"
    case, log = run_to_completion(
        tag, "mieGruneisenRebound",
        [mie_gruneisen, set_velocities(-3000.0, -3000.0)])
    if case is None:
        return
    t = fc.latest_time(case)
    a = fc.read_field(case, t, "alpha.copper")
    rho = fc.read_field(case, t, "rho.copper")
    p = fc.read_field(case, t, "p.copper")
    U = fc.read_field(case, t, "U")[:, 0]
    m = a > 1e-3
    rhoMax = 8900.0 / (1 - 1 / 1.489)
    finite = all(np.all(np.isfinite(f)) for f in (a, rho, p, U))
    admissible = (np.all(rho[m] > 0) and np.all(rho[m] < rhoMax)
                  and np.all(p[m] > mg_pmin(rho[m])))
    checks.check(tag, finite and admissible and U[m].max() > 0,
                 "t = %s: fields finite %s; copper (alpha > 1e-3) rho "
                 "%.5g-%.5g (rhoMax %.6g), p %.4g-%.4g Pa above pMin(rho): "
                 "%s; largest copper velocity %.0f m/s (rebounding)"
                 % (t, finite, rho[m].min(), rho[m].max(), rhoMax,
                    p[m].min(), p[m].max(), admissible, U[m].max()))


# --------------------------------------------------------------------------
# Running and inspecting
# --------------------------------------------------------------------------

def prepare(name, before_setfields=()):
    """Copy the base case to run/V9_<name>, apply the modifications that
    act on the set-up dictionaries, run blockMesh and setFields."""
    case = fc.copy_tutorial(BASE, "V9_" + name)
    for modify in before_setfields:
        modify(case)
    fc.run(case, ["blockMesh"])
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))
    fc.run(case, ["setFields"])
    return case


def run_impactfoam(case):
    """impactFoam in case; returns (exit code or None on timeout, log)."""
    logpath = os.path.join(case, "log.impactFoam")
    env = dict(os.environ)
    env["PWD"] = os.path.abspath(case)
    with open(logpath, "w") as logf:
        try:
            proc = subprocess.run(["impactFoam"], cwd=case, stdout=logf,
                                  stderr=subprocess.STDOUT, env=env,
                                  timeout=RUN_TIMEOUT)
            code = proc.returncode
        except subprocess.TimeoutExpired:
            code = None
    with open(logpath, errors="replace") as f:
        return code, f.read()


def fatal_message(log):
    """Text from the first 'FOAM FATAL' line on ('' if none)."""
    i = log.find("FOAM FATAL")
    return log[i:] if i >= 0 else ""


def one_line(text, n=3):
    lines = [l.strip() for l in text.splitlines() if l.strip()
             and not l.strip().startswith("-->")]
    return " | ".join(lines[:n])


_NAN = re.compile(r"(?<![\w.])[-+]?(nan|inf)(?![\w.])", re.I)


def files_with_nan(case):
    """Files of the case's time directories holding a nan or inf token."""
    bad = []
    for _, name in fc.time_dirs(case):
        d = os.path.join(case, name)
        for root, _, files in os.walk(d):
            for fn in files:
                path = os.path.join(root, fn)
                try:
                    with open(path, errors="replace") as f:
                        text = fc.strip_comments(f.read())
                except OSError:
                    continue
                if _NAN.search(text):
                    bad.append(os.path.relpath(path, case))
    return bad


def check_bad_input(name, modify, patterns, what):
    tag = "V9_" + name
    try:
        case = prepare(name)
        modify(case)
    except (fc.FoamError, OSError) as e:
        checks.fail(tag, "could not set up the case: %s"
                    % getattr(e, "summary", e))
        return
    code, log = run_impactfoam(case)
    msg = fatal_message(log)
    missing = [p for p in patterns if not re.search(p, msg)]
    times = [n for _, n in fc.time_dirs(case)]
    nan = files_with_nan(case)
    problems = []
    if code is None:
        problems.append("timed out")
    elif code == 0:
        problems.append("exit code 0")
    if not msg:
        problems.append("no FOAM FATAL in the log")
    elif missing:
        problems.append("fatal message does not match %s" % missing)
    if times != ["0"]:
        problems.append("time directories written: %s" % " ".join(times))
    if nan:
        problems.append("NaN/Inf in %s" % " ".join(nan))
    summary = one_line(msg) if msg else fc.log_summary(log)
    checks.check(tag, not problems,
                 "%s: exit code %s; %s%s"
                 % (what, code, summary,
                    ("; PROBLEMS: " + "; ".join(problems)) if problems
                    else ""))


def check_control():
    tag = "V9_control"
    try:
        case = prepare("control")
    except fc.FoamError as e:
        checks.fail(tag, e.summary)
        return
    code, log = run_impactfoam(case)
    end = float(fc.get_entry(case, "system/controlDict", "endTime"))
    times = [t for t, _ in fc.time_dirs(case)]
    ok = code == 0 and "FOAM FATAL" not in log and times \
        and abs(times[-1] - end) <= 1e-9 * end and not files_with_nan(case)
    checks.check(tag, ok, "valid base case: exit code %s, time directories "
                 "%s (end time %g)" % (code, " ".join("%g" % t
                                                      for t in times), end))
    check_defaults(log)


# Defaults the base case takes (it gives riemannSolver, tau and the
# phases' equations of state, and nothing else)
DEFAULTS_USED = [
    "discreteEquations: waveSpeeds Davis",
    "discreteEquations: order 2",
    "Phase copper, plasticity: n 0",
    "Phase air: pressureRelaxation constantPressure",
    "phaseProperties: pVacuum 1",
]
GIVEN = ["riemannSolver", "tau", "gamma"]


def check_defaults(log):
    """The defaults block: printed once, before the time loop, listing
    defaults the run uses and no entry the case gives."""
    tag = "V9_defaultsPrintedOnce"
    header = "Defaults used (not given in the input):"
    count = log.count(header)
    block = []
    if count:
        for line in log[log.find(header) + len(header):].splitlines()[1:]:
            if not line.startswith("    "):
                break
            block.append(line.strip())
    missing = [d for d in DEFAULTS_USED if d not in block]
    given = [l for l in block if l.split(": ", 1)[-1].split()[0] in GIVEN]
    before_loop = 0 <= log.find(header) < log.find("Starting time loop")
    checks.check(tag, count == 1 and not missing and not given
                 and before_loop,
                 "block printed %d time(s)%s, %d default(s) listed; "
                 "missing %s; given entries listed %s"
                 % (count, " before the time loop" if before_loop else "",
                    len(block), missing or "none", given or "none"))


_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def check_first_order_courant():
    """discreteEquations order 1 with maxCo 0.8: the first-order scheme is
    stable only up to 0.5 (docs/numerics.md 6.1); the solver warns and every
    step's Courant number is at most 0.5."""
    tag = "V9_firstOrderCourant"
    try:
        case = prepare("firstOrderCourant")
        fc.set_entry(case, "system/fvSchemes", "discreteEquations/order", 1)
        fc.set_entry(case, "system/controlDict", "maxCo", 0.8)
    except fc.FoamError as e:
        checks.fail(tag, e.summary)
        return
    code, log = run_impactfoam(case)
    co = [float(c) for c in re.findall(r"Courant Number max = (%s)" % _NUM,
                                       log)]
    warned = "is above 0.5, the stability limit" in log
    ok = code == 0 and warned and co and max(co) <= 0.5 * (1 + 1e-9)
    checks.check(tag, ok, "order 1, maxCo 0.8: exit code %s, warning %s, "
                 "%d steps, largest Courant number %s (bound 0.5)"
                 % (code, "given" if warned else "missing", len(co),
                    "%.6g" % max(co) if co else "-"))




def check_unphysical(name, modifications, what, patterns=()):
    tag = "V9_unphysical_" + name
    try:
        case = prepare("unphysical_" + name, modifications)
    except (fc.FoamError, OSError) as e:
        checks.fail(tag, "could not set up the case: %s"
                    % getattr(e, "summary", e))
        return
    code, log = run_impactfoam(case)
    msg = fatal_message(log)
    head = msg.split("From function")[0]
    problems = []
    if code is None:
        problems.append("timed out")
    elif code == 0:
        problems.append("exit code 0 (the run did not stop)")
    if not msg:
        problems.append("no FOAM FATAL in the log")
    if not re.search(r"unphysical state", head, re.I):
        problems.append("message does not say 'unphysical state'")
    for pattern in patterns:
        if not re.search(pattern, head):
            problems.append("message does not match %s" % pattern)
    if "What may help:" not in head:
        problems.append("message says nothing of what the user can change")
    m_phase = re.search(r"phase\s+(%s)\b" % "|".join(PHASES), head)
    m_cell = re.search(r"cell\s+(\d+)", head)
    m_time = re.search(r"time\s+(%s)" % _NUM, head)
    m_value = re.search(r"([A-Za-z][\w().]*)\s*=\s*(%s)" % _NUM, head)
    for m, item in ((m_phase, "phase"), (m_cell, "cell"), (m_time, "time"),
                    (m_value, "value")):
        if m is None:
            problems.append("message names no %s" % item)
    m_good = re.search(r"last good fields were written at time\s+(%s)"
                       % _NUM, head)
    good_info = ""
    if m_good is None:
        problems.append("message names no time of the last good fields")
    else:
        t_good = float(m_good.group(1))
        times = fc.time_dirs(case)
        try:
            good = fc.find_time(case, t_good)
        except fc.FoamError as e:
            good = None
            problems.append(str(e))
        if good is not None:
            if times[-1][1] != good:
                problems.append("a later time directory %s exists"
                                % times[-1][1])
            if m_time and not t_good < float(m_time.group(1)):
                problems.append("last good time %g not before the failure "
                                "time %s" % (t_good, m_time.group(1)))
            nan = files_with_nan(case)
            if nan:
                problems.append("NaN/Inf in %s" % " ".join(nan))
            try:
                mins = []
                for ph in PHASES:
                    rho = fc.read_field(case, good, "rho." + ph)
                    p = fc.read_field(case, good, "p." + ph)
                    mins.append("%s: min rho %.3g, min p %.4g"
                                % (ph, rho.min(), p.min()))
                    if ph == "copper" and name.startswith("mieGruneisen"):
                        lowest = mg_pmin(rho)
                    else:
                        lowest = -P_INF[ph]
                    if not (np.all(np.isfinite(rho)) and rho.min() > 0
                            and np.all(np.isfinite(p))
                            and np.all(p > lowest)):
                        problems.append("last good fields of %s are not "
                                        "physical (%s)" % (ph, mins[-1]))
                good_info = "last good fields at %s (%s)" % (good,
                                                              "; ".join(mins))
            except fc.FoamError as e:
                problems.append("cannot read the last good fields: %s"
                                % e.summary)
    summary = one_line(head, 2) if head else fc.log_summary(log)
    checks.check(tag, not problems,
                 "%s: exit code %s; %s%s%s"
                 % (what, code, summary,
                    ("; " + good_info) if good_info else "",
                    ("; PROBLEMS: " + "; ".join(problems)) if problems
                    else ""))


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields")
    if missing:
        checks.fail("V9_run", "%s not found on PATH (impactFoam not built "
                    "or environment not sourced: . etc/bashrc)"
                    % " ".join(missing))
        checks.exit()
    check_control()
    check_first_order_courant()
    for name, modify, patterns, what in BAD_INPUT:
        check_bad_input(name, modify, patterns, what)
    for name, modifications, what, patterns in UNPHYSICAL:
        check_unphysical(name, modifications, what, patterns)
    check_rebound()
    check_vacuum()
    check_removed_threshold()
    checks.exit()


if __name__ == "__main__":
    main()
