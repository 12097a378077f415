#!/usr/bin/env python3
"""Fails when a string literal in src/ writes a count's noun as "thing(s)" or "child(ren)": every
count the tool prints goes through Counted (src/base/counted.hpp), "1 triangle", "2 triangles".

Run as: check_counts.py --source <repository>; CTest runs it (tests/CMakeLists.txt)."""

import argparse
import os
import re
import sys

LITERAL = re.compile(r'"(?:[^"\\\n]|\\.)*"')
EITHER_FORM = re.compile(r"[A-Za-z]\((s|es|ren)\)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--source", required=True)
    args = parser.parse_args()
    found = []
    checked = 0
    for folder, _, names in os.walk(os.path.join(args.source, "src")):
        for name in sorted(names):
            if not name.endswith((".cpp", ".hpp")):
                continue
            path = os.path.join(folder, name)
            checked += 1
            with open(path, encoding="utf-8") as f:
                for number, line in enumerate(f, start=1):
                    for literal in LITERAL.findall(line):
                        if EITHER_FORM.search(literal):
                            found.append("%s:%d: %s" % (os.path.relpath(path, args.source), number, literal))
    for place in found:
        print("check_counts: a noun in both forms, use Counted (base/counted.hpp): " + place, file=sys.stderr)
    if checked < 100:
        print("check_counts: only %d source files found under %s/src" % (checked, args.source), file=sys.stderr)
        return 1
    print("check_counts: %d source files, %d nouns in both forms" % (checked, len(found)))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
