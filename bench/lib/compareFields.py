#!/usr/bin/python3
"""Compare the fields of the last common time of two OpenFOAM cases.

Usage: compareFields.py caseA caseB
Prints, per field, max |a - b| / max |a| over the internal field; exit 1 if
any exceeds 1e-12 (or a field is missing), 0 otherwise.
"""
import os
import re
import struct
import sys


def times(case):
    out = []
    for d in os.listdir(case):
        try:
            out.append((float(d), d))
        except ValueError:
            pass
    return dict(out)


NCOMP = {"scalar": 1, "vector": 3, "symmTensor": 6, "tensor": 9}


def internal_field(path):
    """The internal field's values (ascii or binary format), or None"""
    raw = open(path, "rb").read()
    m = re.search(rb"internalField\s+uniform\s+([^;]+);", raw)
    if m:
        return [float(x) for x in re.findall(rb"[-+0-9.eE]+", m.group(1))]
    m = re.search(rb"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(",
                  raw)
    if not m:
        return None
    n = int(m.group(2)) * NCOMP[m.group(1).decode()]
    start = m.end()
    if b"format      binary" in raw[:start] or b"format binary" in raw[:start]:
        return list(struct.unpack("<%dd" % n, raw[start:start + 8 * n]))
    end = raw.index(b"\n)\n", start)
    return [float(x) for x in
            re.findall(rb"[-+]?[0-9.]+(?:[eE][-+]?\d+)?", raw[start:end])]


def main(a, b):
    ta, tb = times(a), times(b)
    common = sorted(set(ta) & set(tb))
    if not common:
        print("no common time")
        return 1
    t = common[-1]
    da, db = os.path.join(a, ta[t]), os.path.join(b, tb[t])
    worst = 0.0
    bad = False
    print("time %s" % ta[t])
    for name in sorted(os.listdir(da)):
        pa, pb = os.path.join(da, name), os.path.join(db, name)
        if not os.path.isfile(pa):
            continue
        if not os.path.isfile(pb):
            print("  %-24s only in A" % name)
            bad = True
            continue
        fa, fb = internal_field(pa), internal_field(pb)
        if fa is None or fb is None or len(fa) != len(fb):
            print("  %-24s not comparable" % name)
            continue
        scale = max(max(abs(x) for x in fa), 1e-300)
        diff = max(abs(x - y) for x, y in zip(fa, fb)) / scale
        worst = max(worst, diff)
        print("  %-24s %.3e" % (name, diff))
    for name in sorted(os.listdir(db)):
        if os.path.isfile(os.path.join(db, name)) and \
                not os.path.isfile(os.path.join(da, name)):
            print("  %-24s only in B" % name)
    for case in (a, b):
        p = os.path.join(case, "log.rodProfile")
        if os.path.exists(p):
            lines = [l for l in open(p).read().splitlines()
                     if l.startswith("Time ")]
            if lines:
                print("%s rodProfile: %s" % (case, lines[-1]))
    print("largest relative difference %.3e" % worst)
    return 1 if (bad or worst > 1e-12) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
