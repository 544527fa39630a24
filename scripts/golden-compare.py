#!/usr/bin/env python3
"""Compare two dumps of the golden outputs number by number (standard library only).

A change that should keep the numbers (a refactor that reorders floating-point operations)
is blessed only with this comparison quoted in its commit. Dump the outputs of both builds:

    git worktree add /tmp/old <commit before>   # build the old binary there
    (cd /tmp/old && POUNDING_GOLDEN_DUMP=/tmp/golden-old cargo test -p pounding-cli --test cli golden)
    POUNDING_GOLDEN_DUMP=/tmp/golden-new cargo test -p pounding-cli --test cli golden
    python3 scripts/golden-compare.py /tmp/golden-old /tmp/golden-new --tol 1e-9

For every file of every case: identical bytes, or (text) the same sequence of non-numeric
tokens and the same number of numeric tokens, integer tokens (counts, indices, statuses as
numbers) identical, and every other number within the relative tolerance. The relative
difference of a pair is |a - b| / max(|a|, |b|); a second measure divides by the largest
magnitude of the same CSV column (or of the file, for other text) so that a value near zero
(a gap of 1e-17 m that became -3e-18 m) is judged against the scale of its series. Both are
reported; the exit status uses the first unless --scaled is given. Binary files (figures) must
be identical. Exit status 0: within tolerance; 1: not; 2: bad arguments.
"""
import argparse
import math
import os
import re
import sys

NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?|[-+]?(?:inf|NaN|nan)")


def tokens(text):
    """Split text into (kind, token, line, column) with kind 'num' or 'text'."""
    out = []
    for ln, line in enumerate(text.split("\n"), 1):
        cells = line.split(",")
        pos = 0
        for col, cell in enumerate(cells):
            last = 0
            for m in NUMBER.finditer(cell):
                # a number glued to a word (deck1, c0, segment3) is part of the word
                before = cell[m.start() - 1] if m.start() > 0 else ""
                after = cell[m.end()] if m.end() < len(cell) else ""
                if before.isalpha() or before == "_" or after.isalpha() and after not in "eE":
                    continue
                if cell[last:m.start()]:
                    out.append(("text", cell[last:m.start()], ln, col))
                out.append(("num", m.group(0), ln, col))
                last = m.end()
            if cell[last:]:
                out.append(("text", cell[last:], ln, col))
            out.append(("text", ",", ln, col))
            pos += len(cell) + 1
        out.append(("text", "\n", ln, -1))
    return out


def is_int(tok):
    return re.fullmatch(r"[-+]?\d+", tok) is not None


def compare_text(old, new, name, report):
    a, b = tokens(old), tokens(new)
    if len(a) != len(b):
        report["problems"].append(f"{name}: {len(a)} tokens before, {len(b)} now")
        return
    csv = name.endswith(".csv")
    scale = {}
    for kind, tok, _, col in a + b:
        if kind == "num":
            v = abs(float(tok))
            if math.isfinite(v):
                key = col if csv else None
                scale[key] = max(scale.get(key, 0.0), v)
    for (ka, ta, ln, col), (kb, tb, _, _) in zip(a, b):
        if ka != kb or (ka == "text" and ta != tb):
            report["problems"].append(f"{name}:{ln}: text token {ta!r} became {tb!r}")
            return
        if ka != "num" or ta == tb:
            if ka == "num":
                report["numbers"] += 1
            continue
        report["numbers"] += 1
        report["changed"] += 1
        if is_int(ta) and is_int(tb):
            report["problems"].append(f"{name}:{ln}: integer {ta} became {tb}")
            continue
        x, y = float(ta), float(tb)
        if not (math.isfinite(x) and math.isfinite(y)):
            report["problems"].append(f"{name}:{ln}: {ta} became {tb}")
            continue
        d = abs(x - y)
        rel = d / max(abs(x), abs(y))
        s = scale.get(col if csv else None, 0.0)
        scaled = d / max(abs(x), abs(y), s)
        where = f"{name}:{ln} (column {col + 1}): {ta} -> {tb}"
        if rel > report["max_rel"][0]:
            report["max_rel"] = (rel, where)
        if scaled > report["max_scaled"][0]:
            report["max_scaled"] = (scaled, where)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("old")
    p.add_argument("new")
    p.add_argument("--tol", type=float, default=1e-9)
    p.add_argument("--scaled", action="store_true", help="judge by the column-scaled measure")
    args = p.parse_args()
    for d in (args.old, args.new):
        if not os.path.isdir(d):
            print(f"error: {d} is not a directory", file=sys.stderr)
            sys.exit(2)
    report = {"problems": [], "numbers": 0, "changed": 0, "max_rel": (0.0, ""),
              "max_scaled": (0.0, ""), "files": 0, "identical": 0}
    names = set()
    for root in (args.old, args.new):
        for dirpath, _, files in os.walk(root):
            for f in files:
                names.add(os.path.relpath(os.path.join(dirpath, f), root))
    for name in sorted(names):
        pa, pb = os.path.join(args.old, name), os.path.join(args.new, name)
        if not (os.path.exists(pa) and os.path.exists(pb)):
            report["problems"].append(f"{name}: only in {'old' if os.path.exists(pa) else 'new'}")
            continue
        report["files"] += 1
        a, b = open(pa, "rb").read(), open(pb, "rb").read()
        if a == b:
            report["identical"] += 1
            try:
                report["numbers"] += sum(1 for t in tokens(a.decode()) if t[0] == "num")
            except UnicodeDecodeError:
                pass
            continue
        try:
            ta, tb = a.decode(), b.decode()
        except UnicodeDecodeError:
            report["problems"].append(f"{name}: binary file differs")
            continue
        compare_text(ta, tb, name, report)
    print(f"files: {report['files']} ({report['identical']} byte-identical)")
    print(f"numbers: {report['numbers']} ({report['changed']} differ)")
    print(f"largest relative difference: {report['max_rel'][0]:.3e}  {report['max_rel'][1]}")
    print(f"largest difference relative to its column's scale: "
          f"{report['max_scaled'][0]:.3e}  {report['max_scaled'][1]}")
    for pr in report["problems"]:
        print("PROBLEM:", pr)
    judged = report["max_scaled"][0] if args.scaled else report["max_rel"][0]
    ok = not report["problems"] and judged <= args.tol
    print("within tolerance" if ok else f"NOT within tolerance {args.tol:g}")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
