#!/usr/bin/env python3
"""Compares two `shadowlab check --lab all --json` results figure by figure (every metric, criterion,
limit and condition; times left out) and prints what differs. Exit 0 when nothing but the listed
parameter keys differ, 1 otherwise.

    shadowlab-old check --lab all --impl solution --json before.json
    shadowlab     check --lab all --impl solution --json after.json
    scripts/compare_check_figures.py before.json after.json [--new-param light.size]
"""
import argparse
import json
import re
import sys


def flat(j, prefix=""):
    out = {}
    if isinstance(j, dict):
        for k, v in j.items():
            out.update(flat(v, f"{prefix}/{k}"))
    elif isinstance(j, list):
        for i, v in enumerate(j):
            out.update(flat(v, f"{prefix}/{i}"))
    else:
        out[prefix] = j
    return out


def timing(key):
    """Times differ from run to run: `seconds`, and any key with an `ms` word (gpu_ms_blur_x, cpu_ms)."""
    last = key.rsplit("/", 1)[-1]
    return "seconds" in key or re.search(r"(^|_)ms($|_)", last) is not None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("before")
    ap.add_argument("after")
    ap.add_argument("--new-param", action="append", default=[],
                    help="a parameter the newer binary declares (its appearance under /parameters is expected)")
    args = ap.parse_args()
    before = json.load(open(args.before))["labs"]
    after = json.load(open(args.after))["labs"]
    if [r["lab"] for r in before] != [r["lab"] for r in after]:
        print("the two runs graded different labs")
        return 1
    figures, expected, differ = 0, 0, []
    for x, y in zip(before, after):
        fx = {k: v for k, v in flat(x).items() if not timing(k)}
        fy = {k: v for k, v in flat(y).items() if not timing(k)}
        for k in sorted(set(fx) | set(fy)):
            figures += 1
            if fx.get(k) == fy.get(k):
                continue
            if k in {f"/parameters/{p}" for p in args.new_param} and k not in fx:
                expected += 1
                continue
            differ.append((x["lab"], k, fx.get(k), fy.get(k)))
    print(f"{len(before)} labs, {figures} figures: {len(differ)} differ"
          + (f" ({expected} new parameter entries expected)" if expected else ""))
    for lab, k, a, b in differ[:50]:
        print(f"  lab {lab} {k}: {a} -> {b}")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
