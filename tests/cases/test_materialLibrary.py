#!/usr/bin/python3
"""The material library (docs/materials.md): `material <name>;` in a phase's
dictionary of constant/phaseProperties.

Base case: V9's tests/cases/badInput/copperAir (1-D copper slab in contact
with air, 3 steps), its phases rewritten:

    inline          copper { <body of etc/materials/copperStiffenedGas> }
                    air    { <body of etc/materials/air> }
    library         copper { material copperStiffenedGas; }
                    air    { material air; }
    overrideInline  inline, with mu 4.6e10 in copper's elasticity
    override        copper { material copperStiffenedGas;
                             elasticity { mu 4.6e10; } }, air from the library
    caseLocal       copper { material copperStiffenedGas; } with the case's
                    own constant/materials/copperStiffenedGas (the library
                    text with mu 4.6e10), which must win over the library's

Checks:
    libraryEqualsInline   every field file of every time directory of
                          'library' is byte-identical to 'inline'
    overrideEqualsInline  'override' byte-identical to 'overrideInline', and
                          different from 'library' (the override acted)
    caseLocalFirst        'caseLocal' byte-identical to 'overrideInline'
    V9_unknownMaterial    copper { material unobtainium; }: impactFoam stops
                          at start-up (V9's bad-input rules: non-zero exit,
                          FOAM FATAL, no time directory but 0, no NaN) with a
                          message naming the phase, the entry material, the
                          name and both places searched
"""
import filecmp
import os
import re
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import foamcase as fc                         # noqa: E402
import test_V9_badInput as v9                 # noqa: E402

checks = v9.checks
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
LIBRARY = os.path.join(ROOT, "etc", "materials")
PP = "constant/phaseProperties"
MU = "mu 4.6e10;"


def library_body(name):
    """The text of a library entry without its comments."""
    with open(os.path.join(LIBRARY, name)) as f:
        return fc.strip_comments(f.read())


def set_phases(case, copper, air):
    """Replace the copper and air dictionaries of the case's
    phaseProperties by the given bodies."""
    path = os.path.join(case, PP)
    with open(path) as f:
        text = f.read()
    for name, body in (("copper", copper), ("air", air)):
        text, n = re.subn(r"\n%s\n\{.*?\n\}\n" % name,
                          "\n%s\n{\n%s\n}\n" % (name, body), text,
                          count=1, flags=re.S)
        if n != 1:
            raise fc.FoamError("%s: no phase %s" % (path, name))
    with open(path, "w") as f:
        f.write(text)


def with_mu(body):
    new, n = re.subn(r"mu\s+[^;]+;", MU, body, count=1)
    if n != 1:
        raise fc.FoamError("no mu in the copper entry")
    return new


def run_variant(name, copper, air, local=None):
    """Prepare, edit and run one variant; returns the case or None."""
    try:
        case = v9.prepare("materials_" + name)
        set_phases(case, copper, air)
        if local:
            d = os.path.join(case, "constant", "materials")
            os.makedirs(d, exist_ok=True)
            for fname, text in local.items():
                with open(os.path.join(d, fname), "w") as f:
                    f.write(text)
    except (fc.FoamError, OSError) as e:
        checks.fail("materials_" + name, "could not set up the case: %s"
                    % getattr(e, "summary", e))
        return None
    code, log = v9.run_impactfoam(case)
    if code != 0 or "FOAM FATAL" in log:
        checks.fail("materials_" + name, "impactFoam failed (exit code %s): "
                    "%s" % (code, v9.one_line(v9.fatal_message(log))
                            or fc.log_summary(log)))
        return None
    return case


def field_files(case):
    """{time/name: path} of every file in the time directories."""
    out = {}
    for _, t in fc.time_dirs(case):
        for fn in sorted(os.listdir(os.path.join(case, t))):
            p = os.path.join(case, t, fn)
            if os.path.isfile(p):
                out[t + "/" + fn] = p
    return out


def compare(a, b):
    """(identical, summary) of the field files of two cases."""
    fa, fb = field_files(a), field_files(b)
    if sorted(fa) != sorted(fb):
        return False, "different files: %s vs %s" % (
            sorted(set(fa) - set(fb))[:5], sorted(set(fb) - set(fa))[:5])
    differ = [k for k in sorted(fa)
              if not filecmp.cmp(fa[k], fb[k], shallow=False)]
    times = sorted({k.split("/")[0] for k in fa}, key=float)
    if differ:
        return False, "%d of %d files differ (%s)" % (
            len(differ), len(fa), ", ".join(differ[:4]))
    return True, "%d files in %d time directories (%s) byte-identical" % (
        len(fa), len(times), " ".join(times))


def main():
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields")
    if missing:
        checks.fail("materials_run", "%s not found on PATH (. etc/bashrc)"
                    % " ".join(missing))
        checks.exit()

    copper = library_body("copperStiffenedGas")
    air = library_body("air")
    inline = run_variant("inline", copper, air)
    library = run_variant("library", "    material copperStiffenedGas;",
                          "    material air;")
    if inline and library:
        ok, msg = compare(library, inline)
        checks.check("libraryEqualsInline", ok,
                     "material copperStiffenedGas/air against the same "
                     "entries inline: " + msg)

    over_inline = run_variant("overrideInline", with_mu(copper), air)
    override = run_variant("override", "    material copperStiffenedGas;\n"
                           "    elasticity { %s }" % MU, "    material air;")
    if over_inline and override:
        ok, msg = compare(override, over_inline)
        acted = library and not compare(override, library)[0]
        checks.check("overrideEqualsInline", ok and bool(acted),
                     "material + elasticity { %s } against the edited entry "
                     "inline: %s; differs from the plain library run: %s"
                     % (MU, msg, bool(acted)))

    local_text = with_mu(copper)
    local = run_variant("caseLocal", "    material copperStiffenedGas;",
                        "    material air;",
                        local={"copperStiffenedGas": local_text})
    if local and over_inline:
        ok, msg = compare(local, over_inline)
        checks.check("caseLocalFirst", ok,
                     "constant/materials/copperStiffenedGas (mu 4.6e10) "
                     "taken before the library's: " + msg)

    v9.check_bad_input(
        "unknownMaterial",
        lambda c: set_phases(c, "    material unobtainium;",
                             "    material air;"),
        [r"\bcopper\b", r"\bmaterial\b", r"unobtainium",
         r"constant/materials", r"etc/materials"],
        "material unobtainium")
    checks.exit()


if __name__ == "__main__":
    main()
