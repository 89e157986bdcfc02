#!/usr/bin/python3
"""impactFoam test runner (standard library only).

Runs
  - the GoogleTest unit tests (platforms/.../bin/impactFoamUnitTests), each
    GoogleTest case counted on its own;
  - every tests/cases/test_*.py script. A script prints one line per check,
    "PASS <name>: <measured numbers>" or "FAIL <name>: <why>", and exits
    non-zero when any check failed. A script that exits non-zero without a
    FAIL line, or runs past its time limit, counts as one failure.
and prints one closing line "N passed, N failed".

Usage: runTests.py [-j N] [name-filter ...]
"""
import concurrent.futures
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TIMEOUT = 1800  # seconds per case script


def run_unit_tests():
    exe = os.path.join(os.environ["IMPACTFOAM_APPBIN"], "impactFoamUnitTests")
    report = os.path.join(HERE, "run", "unitTests.json")
    if os.path.exists(report):
        os.remove(report)
    proc = subprocess.run([exe, "--gtest_output=json:" + report],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True)
    results = []
    try:
        with open(report) as f:
            data = json.load(f)
        for suite in data["testsuites"]:
            for case in suite["testsuite"]:
                name = "unit/%s.%s" % (suite["name"], case["name"])
                failures = case.get("failures", [])
                msg = failures[0]["failure"].splitlines()[0] if failures else ""
                results.append((name, not failures, msg))
    except (OSError, ValueError, KeyError):
        results.append(("unit/impactFoamUnitTests", False,
                        "no report; output:\n" + proc.stdout[-3000:]))
    if proc.returncode != 0 and all(ok for _, ok, _ in results):
        results.append(("unit/impactFoamUnitTests", False,
                        "exit code %d" % proc.returncode))
    return results


def run_case_script(path):
    name = os.path.splitext(os.path.basename(path))[0]
    t0 = time.time()
    try:
        proc = subprocess.run(["/usr/bin/python3", path], cwd=HERE,
                              stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True,
                              timeout=TIMEOUT)
        out, code = proc.stdout, proc.returncode
    except subprocess.TimeoutExpired as e:
        out = (e.stdout or b"").decode() if isinstance(e.stdout, bytes) \
            else (e.stdout or "")
        return name, [("case/%s" % name, False,
                       "timed out after %d s" % TIMEOUT)], out, time.time() - t0
    results = []
    for line in out.splitlines():
        for tag, ok in (("PASS ", True), ("FAIL ", False)):
            if line.startswith(tag):
                check, _, msg = line[len(tag):].partition(":")
                results.append(("case/%s/%s" % (name, check.strip()), ok,
                                msg.strip()))
    if code != 0 and all(ok for _, ok, _ in results):
        results.append(("case/%s" % name, False, "exit code %d" % code))
    return name, results, out, time.time() - t0


def main(argv):
    jobs = 2
    filters = []
    i = 0
    while i < len(argv):
        if argv[i] == "-j":
            jobs = int(argv[i + 1])
            i += 2
        else:
            filters.append(argv[i])
            i += 1
    os.makedirs(os.path.join(HERE, "run"), exist_ok=True)

    def wanted(name):
        return not filters or any(f in name for f in filters)

    results = []
    if wanted("unit"):
        unit = run_unit_tests()
        for name, ok, msg in unit:
            if not ok:
                print("FAIL %s: %s" % (name, msg))
        print("unit tests: %d passed, %d failed"
              % (sum(ok for _, ok, _ in unit), sum(not ok for _, ok, _ in unit)))
        results += unit

    scripts = sorted(
        os.path.join(HERE, "cases", f)
        for f in os.listdir(os.path.join(HERE, "cases"))
        if f.startswith("test_") and f.endswith(".py") and wanted(f))
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        for name, res, out, secs in pool.map(run_case_script, scripts):
            print("---- %s (%.0f s)" % (name, secs))
            for rname, ok, msg in res:
                print("%s %s: %s" % ("PASS" if ok else "FAIL", rname, msg))
            if not all(ok for _, ok, _ in res):
                print("  output of %s (last lines):" % name)
                for line in out.splitlines()[-25:]:
                    print("    " + line)
            results += res

    passed = sum(ok for _, ok, _ in results)
    failed = len(results) - passed
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed or not results else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
