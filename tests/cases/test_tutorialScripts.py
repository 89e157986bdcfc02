#!/usr/bin/python3
"""The tutorials' Allrun and Allclean scripts (etc/RunFunctions): one
command-line convention, rerun-safe, and committed files never touched.

  tutorialScripts_help        every tutorial's ./Allrun -help exits 0 and
                              lists its options; an unknown option and a
                              number option given a word stop with a
                              message naming them
  tutorialScripts_rerun_*     taylorBar run twice in one copy, -h 0.8 then
                              -h 0.4 (to 1 us): each run's mesh has the
                              cell count of its -h, its fields that many
                              values, no time directory of the first run
                              is left, and the second run's fields equal,
                              bit for bit, those of a run of -h 0.4 in a
                              fresh copy
  tutorialScripts_clean_*     after a short run and ./Allclean the copy
                              holds exactly the committed files, byte for
                              byte (taylorBar, clayImpact, taylorTest,
                              spallPlate, hypervelocityImpact, closedBox
                              on 2 processes, templates/projectileOnPlate,
                              longRodPenetration, rigidPenetration)
  tutorialScripts_keep_files  the template with a file of the user's in 0/
                              and a log.mine: ./Allrun and ./Allclean keep
                              both, and remove every log Allrun wrote
  tutorialScripts_keep_mesh   the same case made to use its own mesh (the
                              domain entry and impactSetup's blockMeshDict
                              removed): ./Allrun runs on it and ./Allclean
                              keeps it, byte for byte
About a minute.
"""
import filecmp
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))

import foamcase as fc  # noqa: E402
from checks import Checks  # noqa: E402

TIMEOUT = 600

# Short runs: (tutorial, options)
CLEAN_RUNS = [
    ("taylorBar", ["-h", "1.2", "-end", "1e-6"]),
    ("clayImpact", ["-h", "4"]),
    ("taylorTest", ["-h", "1.6", "-end", "1e-6", "-v", "200"]),
    ("spallPlate", ["-h", "0.1", "-end", "2e-7"]),
    ("hypervelocityImpact", ["-h", "2", "-end", "2e-7"]),
    ("closedBox", ["-np", "2", "-end", "3e-6"]),
    ("templates/projectileOnPlate", ["-h", "1", "-end", "2e-7"]),
    ("longRodPenetration", ["-h", "2", "-end", "2e-7"]),
    ("rigidPenetration", ["-h", "2", "-end", "2e-7"]),
]


def tutorials():
    """Every case directory with an Allrun under tutorials/impactFoam"""
    found = []
    for root, dirs, files in os.walk(fc.TUTORIALS_DIR):
        if "Allrun" in files:
            found.append(os.path.relpath(root, fc.TUTORIALS_DIR))
            dirs[:] = []
    return sorted(found)


def script(case, args):
    proc = subprocess.run(args, cwd=case, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True,
                          timeout=TIMEOUT)
    return proc.returncode, proc.stdout


def tree(path):
    """Relative paths of the files under path"""
    files = set()
    for root, dirs, names in os.walk(path):
        for n in names:
            files.add(os.path.relpath(os.path.join(root, n), path))
    return files


def same_as_committed(case, source):
    """(ok, why): the copy holds exactly the source's files, same bytes"""
    a, b = tree(case), tree(source)
    if a != b:
        return False, "extra %s, missing %s" % (sorted(a - b)[:6],
                                                 sorted(b - a)[:6])
    changed = [f for f in sorted(a) if not filecmp.cmp(
        os.path.join(case, f), os.path.join(source, f), shallow=False)]
    if changed:
        return False, "changed: %s" % changed[:6]
    return True, "%d files, all as committed" % len(a)


def check_help(checks):
    bad = []
    for t in tutorials():
        src = os.path.join(fc.TUTORIALS_DIR, t)
        code, out = script(src, ["./Allrun", "-help"])
        if code != 0 or "Usage: ./Allrun" not in out or "-help" not in out:
            bad.append("%s -help: exit %s" % (t, code))
            continue
        code, out = script(src, ["./Allrun", "-bogus"])
        if code == 0 or "unknown option -bogus" not in out:
            bad.append("%s -bogus: exit %s, %r" % (t, code, out[-200:]))
        if "-end <value>" in script(src, ["./Allrun", "-help"])[1]:
            code, out = script(src, ["./Allrun", "-end", "soon"])
            if code == 0 or "takes a number, not 'soon'" not in out:
                bad.append("%s -end soon: exit %s" % (t, code))
        if tree(src) & {"log.Allrun"} or any(
                fc.is_time_name(n) for n in os.listdir(src)):
            bad.append("%s: the tutorial directory holds run output" % t)
    checks.check("tutorialScripts_help", not bad,
                 "%d tutorials: -help lists the options, an unknown option"
                 " and a word for a number stop with their message%s"
                 % (len(tutorials()), "; " + "; ".join(bad) if bad else ""))


def field_size(case, time, name):
    """The internal field's number of values (ascii or binary)"""
    data = open(os.path.join(case, time, name), "rb").read()
    m = re.search(rb"internalField\s+nonuniform\s+List<\w+>\s+(\d+)", data)
    return int(m.group(1)) if m else None


def field_data(case, time, name):
    """The field's bytes from internalField on (the header names the case)"""
    data = open(os.path.join(case, time, name), "rb").read()
    return data[data.find(b"internalField"):]


def check_rerun(checks):
    case = fc.copy_tutorial("taylorBar", "tutorialScripts_rerun")
    fresh = fc.copy_tutorial("taylorBar", "tutorialScripts_fresh")
    results = {}
    for h, want in (("0.8", 45 * 13), ("0.4", 90 * 25)):
        code, out = script(case, ["./Allrun", "-h", h, "-end", "1e-6"])
        cells = fc.mesh_n_cells(case) if code == 0 else None
        dirs = fc.time_dirs(case)
        times = [t for t, _ in dirs]
        sizes = set()
        if code == 0 and times:
            for f in ("alpha.copper", "rho.copper", "p", "U"):
                sizes.add(field_size(case, dirs[-1][1], f))
        ok = code == 0 and cells == want and sizes == {want} \
            and times[-1] == 1e-6 and times[0] == 0 \
            and all(t <= 1e-6 for t in times)
        results[h] = times
        checks.check("tutorialScripts_rerun_h%s" % h, ok,
                     "./Allrun -h %s -end 1e-6 (after %s): exit %s, %s cells "
                     "(want %d), field sizes %s, times %s"
                     % (h, "nothing" if h == "0.8" else "-h 0.8", code, cells,
                        want, sorted(sizes), times[:3] + ["..."] + times[-1:]
                        if len(times) > 4 else times))
    code, _ = script(fresh, ["./Allrun", "-h", "0.4", "-end", "1e-6"])
    diffs = []
    if code == 0 and results.get("0.4"):
        for f in ("alpha.copper", "rho.copper", "p", "U", "A.copper"):
            if field_data(case, "1e-06", f) != field_data(fresh, "1e-06", f):
                diffs.append(f)
    checks.check("tutorialScripts_rerun_equal", code == 0 and not diffs,
                 "the second run against a fresh -h 0.4 run: fields at 1 us "
                 "%s" % ("identical (alpha, rho, p, U, A of copper)"
                         if not diffs and code == 0
                         else "differ: %s (exit %s)" % (diffs, code)))


def check_clean(checks):
    for t, opts in CLEAN_RUNS:
        src = os.path.join(fc.TUTORIALS_DIR, t)
        case = fc.copy_tutorial(t, "tutorialScripts_clean_"
                                + t.replace("/", "_"))
        code, out = script(case, ["./Allrun"] + opts)
        ran = code == 0 and len(fc.time_dirs(case)) > 1
        code2, _ = script(case, ["./Allclean"])
        ok, why = same_as_committed(case, src)
        checks.check("tutorialScripts_clean_" + os.path.basename(t), ran and code2 == 0 and ok,
                     "./Allrun %s: %s; ./Allclean: %s"
                     % (" ".join(opts), "ran" if ran else
                        "failed: " + out[-300:], why))


def check_keep(checks):
    """The user's files survive Allrun and Allclean: the template with a
    note in 0/ and a log of the user's (domain mode), and then with the
    user's own mesh (no domain entry: the mesh made once, the domain entry
    and impactSetup's blockMeshDict removed)."""
    case = fc.copy_tutorial("templates/projectileOnPlate",
                            "tutorialScripts_keep")
    mine = {"0/notes": "the user's notes\n", "log.mine": "the user's log\n"}
    for name, text in mine.items():
        os.makedirs(os.path.dirname(os.path.join(case, name)), exist_ok=True)
        with open(os.path.join(case, name), "w") as f:
            f.write(text)
    opts = ["-h", "2", "-end", "1e-7", "-noPlot"]
    code, out = script(case, ["./Allrun"] + opts)
    code2, _ = script(case, ["./Allclean"])
    kept = all(open(os.path.join(case, n)).read() == t
               for n, t in mine.items()
               if os.path.isfile(os.path.join(case, n)))
    kept = kept and all(os.path.isfile(os.path.join(case, n)) for n in mine)
    logs = sorted(n for n in os.listdir(case) if n.startswith("log."))
    checks.check("tutorialScripts_keep_files",
                 code == 0 and code2 == 0 and kept and logs == ["log.mine"],
                 "./Allrun %s exit %d, ./Allclean exit %d; the user's 0/notes "
                 "and log.mine kept: %s; logs left: %s"
                 % (" ".join(opts), code, code2, kept, logs))

    # The user's own mesh: impactDict without a domain
    code, out = script(case, ["impactSetup", "-cellSize", "2e-3"])
    os.remove(os.path.join(case, "system", "blockMeshDict"))
    path = os.path.join(case, "system", "impactDict")
    with open(path) as f:
        text = f.read()
    i = text.index("\ndomain\n")
    j = text.index("\n}\n", i) + 3
    with open(path, "w") as f:
        f.write(text[:i] + "\n" + text[j:])
    points = os.path.join(case, "constant", "polyMesh", "points")
    before = open(points).read()
    code2, out2 = script(case, ["./Allrun", "-end", "1e-7", "-noPlot"])
    ran = code2 == 0 and len(fc.time_dirs(case)) > 1
    code3, _ = script(case, ["./Allclean"])
    kept = os.path.isfile(points) and open(points).read() == before
    checks.check("tutorialScripts_keep_mesh",
                 code == 0 and ran and code3 == 0 and kept,
                 "impactDict without a domain on the user's mesh: ./Allrun "
                 "%s; ./Allclean exit %d; the mesh kept unchanged: %s"
                 % ("ran" if ran else "failed: " + out2[-300:], code3, kept))


def main():
    checks = Checks()
    missing = fc.require_apps("impactFoam", "blockMesh", "setFields")
    if missing:
        checks.fail("tutorialScripts_help", "missing: %s" % ", ".join(missing))
        checks.exit()
    check_help(checks)
    check_rerun(checks)
    check_clean(checks)
    check_keep(checks)
    checks.exit()


if __name__ == "__main__":
    main()
