#!/usr/bin/env python3
"""Checks a `shadowlab grade` output folder against tests/make_submissions.py's expected.json.

    python3 tests/check_grades.py OUT EXPECTED.json [--strict]

Checks, for every student and lab: the status in results.json; that a compile error names the
student's file and line; that a refused submission says why; results.csv has the same statuses;
gradescope/<student>/results.json has one test per lab worth 1 point, scored 1 exactly when passed;
junit.xml counts the same failures, errors and skipped (missing) labs. Prints a table of statuses (expected -> got) and every
difference; exits 1 on any.

One kind of difference is the check's, not the grading's: a wrong (or half-stock) answer that the
lab's check accepts (expected failed, got passed with every criterion met). Those are listed apart as
"check accepts a wrong answer" (issue 13 tracks them) and fail the run only with --strict; the grading
pipeline itself (status, message, files, counts) must be exact.
"""
import csv
import json
import os
import sys
import xml.etree.ElementTree as ET


def main():
    args = [a for a in sys.argv[1:] if a != "--strict"]
    strict = "--strict" in sys.argv[1:]
    out, expected_path = args[0], args[1]
    gaps = []
    expected = json.load(open(expected_path))["students"]
    report = json.load(open(os.path.join(out, "results.json")))
    problems = []
    if report.get("schema") != "shadowlab-grade" or report.get("version") != 2:
        problems.append("results.json: schema/version %r/%r" % (report.get("schema"), report.get("version")))
    got = {s["name"]: s for s in report["students"]}
    table = {}
    for name, e in sorted(expected.items()):
        s = got.get(name)
        if s is None:
            problems.append("%s: missing from results.json" % name)
            continue
        labs = {str(r["lab"]): r for r in s["labs"]}
        for lab, want in sorted(e["labs"].items(), key=lambda kv: int(kv[0])):
            r = labs.get(lab)
            status = r["status"] if r else "absent"
            key = (want["status"], status)
            table[key] = table.get(key, 0) + 1
            where = "%s lab %s (%s, %s)" % (name, lab, want["kind"], want.get("variant", ""))
            if status == "passed" and want["status"] == "failed" and want["kind"] in ("wrong", "stock"):
                gaps.append("%s: %s passes" % (where, want.get("variant", want["kind"])))
                continue
            if status != want["status"]:
                problems.append("%s: expected %s, got %s: %s" % (where, want["status"], status,
                                                                 (r or {}).get("message", "")[:300]))
                continue
            message = r.get("message", "")
            if "line" in want and "%s:%d" % (want["file"], want["line"]) not in message:
                problems.append("%s: the compile error does not name %s:%d: %s" % (where, want["file"], want["line"], message[:300]))
            if want["kind"] == "refused" and "refused" not in message:
                problems.append("%s: a refused submission's message does not say so: %s" % (where, message[:200]))
        # The reports must agree with results.json (a check gap included).
        for lab, want in e["labs"].items():
            if lab in labs and labs[lab]["status"] == "passed" and want["status"] == "failed" and want["kind"] in ("wrong", "stock"):
                want["status"] = "passed"
        # Gradescope: one test per lab, 1 point when passed.
        gs_path = os.path.join(out, "gradescope", name, "results.json")
        if not os.path.isfile(gs_path):
            problems.append("%s: no %s" % (name, gs_path))
            continue
        gs = json.load(open(gs_path))
        tests = {t["number"]: t for t in gs["tests"]}
        for lab, want in e["labs"].items():
            t = tests.get(lab)
            passed = want["status"] == "passed"
            if not t or t["max_score"] != 1 or t["score"] != (1 if passed else 0) or t["status"] != ("passed" if passed else "failed"):
                problems.append("%s lab %s: Gradescope test %r does not match %s" % (name, lab, t, want["status"]))
        want_score = sum(1 for w in e["labs"].values() if w["status"] == "passed")
        if gs["score"] != want_score:
            problems.append("%s: Gradescope score %s, expected %d" % (name, gs["score"], want_score))

    # The CSV: every (student, lab) row carries the same status as the JSON.
    rows = {}
    with open(os.path.join(out, "results.csv")) as f:
        for row in csv.DictReader(f):
            rows.setdefault((row["student"], row["lab"]), set()).add(row["status"])
    for name, e in expected.items():
        for lab, want in e["labs"].items():
            if rows.get((name, lab)) != {want["status"]}:
                problems.append("results.csv %s lab %s: statuses %s, expected %s" % (name, lab, rows.get((name, lab)), want["status"]))

    # JUnit: failures = labs neither passed, missing nor grader errors; errors = grader errors; skipped = missing.
    root = ET.parse(os.path.join(out, "junit.xml")).getroot()
    statuses = [w["status"] for e in expected.values() for w in e["labs"].values()]
    want = {"tests": len(statuses), "failures": sum(1 for s in statuses if s not in ("passed", "missing", "grader_error")),
            "errors": statuses.count("grader_error"), "skipped": statuses.count("missing")}
    got = {k: int(root.get(k, -1)) for k in want}
    if got != want:
        problems.append("junit.xml: %s, expected %s" % (got, want))

    print("expected -> got: count")
    for (want, status), n in sorted(table.items()):
        print("  %-14s -> %-14s %5d%s" % (want, status, n, "" if want == status else "   <-- wrong"))
    for g in gaps:
        print("CHECK ACCEPTS A WRONG ANSWER:", g)
    for p in problems:
        print("PROBLEM:", p)
    if strict:
        problems += gaps
    print("%d students, %d labs: %s; %d wrong answers accepted by their check" % (
        len(expected), len(statuses), "grading as expected" if not problems else "%d problems" % len(problems), len(gaps)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
