"""PASS/FAIL reporting for tests/cases/test_*.py scripts (the protocol of
tests/runTests.py: one line per check, "PASS <name>: <numbers>" or
"FAIL <name>: <why>", non-zero exit status if any check failed)."""
import sys


class Checks(object):
    def __init__(self):
        self.failed = 0
        self.passed = 0

    def check(self, name, ok, msg):
        """Report one check; returns ok."""
        ok = bool(ok)
        print("%s %s: %s" % ("PASS" if ok else "FAIL", name,
                             " ".join(str(msg).split())))
        sys.stdout.flush()
        if ok:
            self.passed += 1
        else:
            self.failed += 1
        return ok

    def fail(self, name, msg):
        return self.check(name, False, msg)

    def note(self, text):
        """Information lines (not checks), indented so the runner does not
        count them."""
        for line in str(text).splitlines():
            print("  " + line)
        sys.stdout.flush()

    def exit(self):
        sys.exit(1 if self.failed or not self.passed else 0)
