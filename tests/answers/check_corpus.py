#!/usr/bin/env python3
"""Grades the exam corpus (tests/answers) with `shadowlab check --submission` and holds the verdicts.

    check_corpus.py BIN [--lab N[,N...]] [--answer NAME] [--markdown FILE] [--keep DIR] [--jobs J]

Every answer becomes a submission folder: the answer's files in their exercise slots, the solution's files
in the slots the answer does not give. A wrong answer must not pass, and must fail on a criterion its
`// fails:` header line names (shell-style patterns over the criteria's metric names, e.g.
`chebyshev.*`; `compile_error` for an answer whose point is not to build, `crashed` or `timed_out` for a hostile
one the sandbox stops); a right answer must pass.
Exit 0 when every answer is graded as expected, 1 otherwise (each misgrade printed), 2 on a usage error.
"""
import argparse
import concurrent.futures
import fnmatch
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
ANSWERS = ROOT / "tests" / "answers"


def labs_of(binary):
    out = subprocess.run([binary, "labs", "--json"], check=True, capture_output=True, text=True).stdout
    return {lab["number"]: lab for lab in json.loads(out)["labs"]}


def header(path, key):
    """The value of the `// key: ...` line among the first lines of an answer file, or None."""
    with open(path, encoding="utf-8") as f:
        for _, line in zip(range(6), f):
            line = line.strip()
            if line.startswith("// " + key + ":"):
                return line[len(key) + 4:].strip()
    return None


def answers_of(lab, only=None):
    """{(kind, name): {exercise file name: path}} for one lab's corpus folder."""
    folder = ANSWERS / f"{lab['number']:02d}_{lab['slug']}"
    found = {}
    for kind in ("wrong", "right"):
        for path in sorted((folder / kind).glob("*__*")):
            name, _, slot = path.name.partition("__")
            if only and name != only:
                continue
            found.setdefault((kind, name), {})[slot] = path
    return found


def make_submission(lab, files, root):
    """A folder laid out like the project: the answer's files, the solution's in the other slots."""
    exercises = lab["exercise_files"] + lab.get("gl_exercise_files", [])  # GL exercises (lab 0's) as slots
    solutions = lab["solution_files"] + lab.get("gl_solution_files", [])
    for exercise, solution in zip(exercises, solutions):
        target = root / exercise
        target.parent.mkdir(parents=True, exist_ok=True)
        name = pathlib.Path(exercise).name
        shutil.copyfile(files.get(name, ROOT / solution), target)
    unknown = set(files) - {pathlib.Path(e).name for e in exercises}
    if unknown:
        raise SystemExit(f"lab {lab['number']}: answer files for no exercise slot: {sorted(unknown)}")


def grade(binary, lab, kind, name, files, keep, scene=None):
    with tempfile.TemporaryDirectory(prefix="shadowlab-answer-") as tmp:
        tmp = pathlib.Path(tmp)
        make_submission(lab, files, tmp / "submission")
        report = tmp / "check.json"
        run = subprocess.run([binary, "check", "--lab", str(lab["number"]), "--submission", str(tmp / "submission"),
                              "--json", str(report)] + (["--scene", str(scene)] if scene else []),
                             capture_output=True, text=True)
        if not report.exists():
            return {"status": "no report", "failed": [], "output": run.stdout + run.stderr, "exit": run.returncode}
        result = json.loads(report.read_text())["labs"][0]
        if keep:
            keep.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(report, keep / f"{lab['number']:02d}_{kind}_{name}.json")
    failed = [c["metric"] for c in result.get("criteria", []) if not c["passed"]]
    return {"status": result["status"], "failed": failed, "output": run.stdout, "exit": run.returncode,
            "error": result.get("error", "")}


def verdict(kind, expected, outcome, foreign=False):
    """None when graded as expected, else what went wrong. On a scene not the lab's own (foreign) a wrong answer
    must fail, on any criterion: its named one was chosen on the lab's scene."""
    status = outcome["status"]
    if kind == "right":
        return None if status == "passed" else f"a right answer is graded {status}: {outcome['failed'] or outcome.get('error', '')}"
    if status == "passed":
        return "a wrong answer passes"
    if status == "grader_error" or status == "no report":
        return f"grader error: {outcome.get('error') or outcome['output'][-400:]}"
    if expected is None:
        return "no `// fails:` line names the criterion this mistake must fail"
    patterns = expected.split()
    if status in ("compile_error", "crashed", "timed_out"):  # a hostile answer names the sandbox's status
        return None if status in patterns else f"{status}: {outcome.get('error', '')[:300]}"
    if foreign or any(fnmatch.fnmatch(metric, p) for metric in outcome["failed"] for p in patterns):
        return None
    return f"fails, but not on {expected}: failed {outcome['failed']}"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("binary")
    parser.add_argument("--lab", help="comma-separated lab numbers (default: every lab with answers)")
    parser.add_argument("--answer", help="one answer's name")
    parser.add_argument("--markdown", type=pathlib.Path, help="write the labs x verdicts table here")
    parser.add_argument("--keep", type=pathlib.Path, help="keep every check's JSON in this folder")
    parser.add_argument("--jobs", type=int, default=1, help="checks run side by side (default 1)")
    parser.add_argument("--scene", type=pathlib.Path,
                        help="grade on this glTF file instead of the lab's scene (check --scene): right answers must "
                             "pass, wrong ones fail on any criterion")
    parser.add_argument("--kind", choices=("wrong", "right"), help="only the wrong or only the right answers")
    args = parser.parse_args()
    labs = labs_of(args.binary)
    numbers = [int(n) for n in args.lab.split(",")] if args.lab else sorted(labs)
    for n in numbers:
        if n not in labs:
            print(f"check_corpus: no lab {n}", file=sys.stderr)
            return 2
    jobs = []
    for n in numbers:
        for (kind, name), files in answers_of(labs[n], args.answer).items():
            if args.kind and kind != args.kind:
                continue
            expected = None
            for path in files.values():
                expected = expected or header(path, "fails")
            jobs.append((labs[n], kind, name, files, expected))
    if not jobs:
        print("check_corpus: no answers found", file=sys.stderr)
        return 2
    env_jobs = max(1, args.jobs)
    with concurrent.futures.ThreadPoolExecutor(env_jobs) as pool:
        outcomes = list(pool.map(lambda j: grade(args.binary, j[0], j[1], j[2], j[3], args.keep, args.scene), jobs))
    misgraded = 0
    table = {}
    for (lab, kind, name, _, expected), outcome in zip(jobs, outcomes):
        problem = verdict(kind, expected, outcome, foreign=args.scene is not None)
        row = table.setdefault(lab["number"], {"right": [0, 0], "wrong": [0, 0], "slug": lab["slug"]})
        row[kind][1] += 1
        row[kind][0] += problem is None
        mark = "ok  " if problem is None else "MISGRADED"
        print(f"{mark} lab {lab['number']} {kind:5} {name:36} {outcome['status']:13} {' '.join(outcome['failed'][:3])}")
        if problem:
            misgraded += 1
            print(f"      {problem}")
    lines = ["| lab | right answers accepted | wrong answers rejected (on their criterion) |", "|---|---|---|"]
    total = {"right": [0, 0], "wrong": [0, 0]}
    for n in sorted(table):
        row = table[n]
        for k in total:
            total[k][0] += row[k][0]
            total[k][1] += row[k][1]
        # Each count carries the marker tests/docs/lab_texts.py checks against the corpus folders (hidden in
        # the README); graded counts equal the folders' when no answer is misgraded.
        r, w = (f"<!-- # tests/answers/{n:02d}_{row['slug']}/{k} -->" for k in ("right", "wrong"))
        lines.append(f"| {n} {row['slug'].replace('_', ' ')} | {row['right'][0]}{r} / {row['right'][1]}{r} | "
                     f"{row['wrong'][0]}{w} / {row['wrong'][1]}{w} |")
    r, w = (f"<!-- # tests/answers/*/{k} -->" for k in ("right", "wrong"))
    lines.append(f"| **all** | **{total['right'][0]}{r} / {total['right'][1]}{r}** | "
                 f"**{total['wrong'][0]}{w} / {total['wrong'][1]}{w}** |")
    print(re.sub(r"<!-- # [^>]* -->", "", "\n".join(lines)))
    if args.markdown:
        args.markdown.write_text("\n".join(lines) + "\n")
    print(f"{misgraded} misgraded of {len(jobs)}")
    return 1 if misgraded else 0


if __name__ == "__main__":
    sys.exit(main())
