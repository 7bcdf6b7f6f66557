#!/usr/bin/env python3
"""Fails when a Catch2 TEST_CASE name would not run under ctest.

catch_discover_tests registers each test case by its name, and ctest's command line splits a
name at ';' (CMake's list separator); an escape such as \\n in the name reaches Catch2's filter
as another string. Either way the registered test runs a filter that matches nothing, Catch2
prints "No tests ran" and exits 0, so the test case passes without running (checked: both did,
for nine test cases, until this check). An escaped quote is handled and allowed. Usage: check_test_names.py --root DIR [--root DIR ...] [--expect N] (folders of test sources)."""
import argparse
import pathlib
import re
import sys

NAME = re.compile(r'TEST_CASE\(\s*"((?:[^"\\]|\\.)*)"')


def problems(root):
    for path in sorted(pathlib.Path(root).rglob("*.cpp")):
        text = path.read_text(encoding="utf-8", errors="replace")
        for m in NAME.finditer(text):
            name = m.group(1)
            line = text.count("\n", 0, m.start()) + 1
            bad = [";"] if ";" in name else []
            bad += sorted({"\\" + e for e in re.findall(r'\\(.)', name) if e != '"'})
            if bad:
                yield f"{path}:{line}: TEST_CASE \"{name}\": {', '.join(repr(b) for b in bad)} in the name: ctest would run a filter matching nothing and pass"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--root", required=True, action="append")
    ap.add_argument("--expect", type=int, default=0, help="the self-check: exactly this many planted names found")
    args = ap.parse_args()
    found = [p for root in args.root for p in problems(root)]
    for p in found:
        print(p)
    if len(found) != args.expect:
        print(f"check_test_names: {len(found)} problem(s), expected {args.expect}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
