#!/usr/bin/env python3
"""Generates a class of student submissions for `shadowlab grade`, and the status every lab must get.

    python3 tests/make_submissions.py --out DIR --count 300 [--seed 1] [--labs 0,2,5]

Writes DIR/submissions/<name>[.zip|.tar.gz] and DIR/expected.json ({"students": {name: {lab: {...}}}}).
Each lab of each student is one of:
  right          a correct answer from tests/answers/<NN_slug>/right/ (or the lab's solution)  -> passed
  wrong          a plausible wrong answer from tests/answers/<NN_slug>/wrong/                  -> failed
  stock          the exercise as handed out                                                      -> failed
  missing        the file not submitted                                                          -> missing
  syntax_error   a right answer with a line that does not parse                                  -> compile_error
  semantic_error a right answer using an undeclared name inside the function                     -> compile_error
  endless_loop   a right answer that loops (nested loops, each too long to finish)               -> timed_out
  crash          (C++ only) a right answer that writes through a null pointer                    -> crashed
  forbidden_call (C++ only) a right answer that opens a file (grading lets it only compute)       -> crashed
and a few whole submissions are archives (zip, tar.gz, some wrapped in a folder), one of them with an
entry that leaves its folder (refused: every lab failed). The rare kinds come in fixed numbers so that
every status appears; everything is drawn from --seed, so a seed gives the same class every time.
Every file starts with a line naming the student, so no two students' files are byte-identical.
"""
import argparse
import io
import json
import os
import random
import re
import shutil
import sys
import tarfile
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "answers"))
from check_corpus import answers_of, header, labs_of  # the corpus's own reading of labs and answers  # noqa: E402


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


SIGNATURE = re.compile(r"^\s*(?:[\w:<>]+\s+)*?([\w:<>]+)\s+(\w+)\s*\(")


def entry_function(stock_text):
    """The name of the function the lab calls: the first one defined in the stock exercise file."""
    for line in stock_text.split("\n"):
        m = SIGNATURE.match(line)
        if m and not line.lstrip().startswith(("//", "#", "return")) and not line.rstrip().endswith(";"):
            return m.group(2)
    raise ValueError("no function in the stock exercise")


def function_start(lines, entry):
    """Index of the line after the opening brace of function `entry`, and its return type."""
    for i, line in enumerate(lines):
        m = SIGNATURE.match(line)
        if not m or m.group(2) != entry or line.lstrip().startswith("//") or line.rstrip().endswith(";"):
            continue
        for j in range(i, min(i + 6, len(lines))):
            if lines[j].rstrip().endswith("{"):
                return j + 1, m.group(1)
            if "{" in lines[j]:  # a one-line body: `float f(float z) { return z; }` split after its brace
                brace = lines[j].index("{") + 1
                lines[j:j + 1] = [lines[j][:brace], "  " + lines[j][brace:].strip()]
                return j + 1, m.group(1)
    raise ValueError("no definition of %s" % entry)


def broken(text, kind, cpp, entry):
    """A right answer made into the given kind of broken one, the damage in function `entry` (the one
    the lab calls); returns (text, the line to be reported, or None)."""
    lines = text.split("\n")
    if kind == "syntax_error":
        at = len(lines) if lines[-1] != "" else len(lines) - 1
        lines.insert(at, "this line is not code;" if not cpp else "this line is not C++;")
        return "\n".join(lines), at + 1
    start, ret = function_start(lines, entry)
    if kind == "semantic_error":
        lines.insert(start, "  float unused_value = undeclared_name;")
        return "\n".join(lines), start + 1
    if kind == "endless_loop" and not cpp:
        value = {"void": "", "float": "0.0", "int": "0", "bool": "false"}.get(ret, ret + "(0.0)")
        # llvmpipe stops any loop after 65,535 iterations in all (one counter per invocation), so an
        # endless loop is really a long one there; each iteration here is 32 dependent sines, which
        # takes minutes even for a function only the check's probes call.
        lines[start:start] = [
            "  float spin = 0.0;",
            "  for (int i = 0; i >= 0; ++i) {",
            "    spin = sin(spin + float(i));" + " spin = sin(spin * 1.0001 + 0.5);" * 31,
            "  }",
            "  if (spin == -7.0) return %s;" % value,
        ]
        return "\n".join(lines), None
    if kind == "endless_loop":
        lines.insert(start, "  for (volatile int k = 0; k >= 0; k = 1) {}")
        return "\n".join(lines), None
    if kind == "crash":
        lines.insert(start, "  { volatile int* p = nullptr; *p = 1; }")
        return "\n".join(lines), None
    if kind == "forbidden_call":
        lines.insert(start, '  if (std::FILE* f = std::fopen("/etc/hostname", "r")) std::fclose(f);')
        lines.insert(0, "#include <cstdio>")
        return "\n".join(lines), None
    raise ValueError(kind)


EXPECTED = {"right": "passed", "wrong": "failed", "stock": "failed", "missing": "missing",
            "syntax_error": "compile_error", "semantic_error": "compile_error", "endless_loop": "timed_out",
            "crash": "crashed", "forbidden_call": "crashed"}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--count", type=int, default=12)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--labs", default="all", help="all, or a comma-separated list of lab numbers")
    ap.add_argument("--bin", default=os.environ.get("SHADOWLAB_BIN", os.path.join(ROOT, "build", "app", "shadowlab")),
                    help="the shadowlab binary (for `shadowlab labs --json`)")
    args = ap.parse_args()
    rng = random.Random(args.seed)
    labs = {n: lab for n, lab in labs_of(args.bin).items() if lab["has_check"]}
    numbers = sorted(labs) if args.labs == "all" else [int(n) for n in args.labs.split(",")]
    cpp_labs = [n for n in numbers if any(f.endswith(".cpp") for f in labs[n]["exercise_files"])]
    glsl_labs = [n for n in numbers if n not in cpp_labs]

    # Per lab: the right and wrong answers on offer, each as the full set of the lab's files (the
    # corpus's rule: a file an answer does not give is the solution's).
    answers, unbuildable = {}, {}
    for n in numbers:
        exercises, solutions = labs[n]["exercise_files"], labs[n]["solution_files"]
        drop_in = all(sol.endswith(".glsl") for sol in solutions)  # GLSL solutions replace the exercise as is
        offered = {"right": [], "wrong": []}
        for (kind, name), given in sorted(answers_of(labs[n]).items()):
            # check_corpus's rule: `// fails: compile_error` marks an answer whose point is not to build.
            fails = next(filter(None, (header(p, "fails") for p in given.values())), None)
            # The status an answer's `// fails:` line names instead of a criterion (a hostile one's), if any.
            unbuildable[(n, name)] = next((w for w in (fails or "").split() if w in ("compile_error", "timed_out", "crashed")), None)
            files = {}
            # A GL exercise (lab 0's gl_shadow_target.cpp): the answer's, else the solution's, which builds
            # as an answer (the renderer's own file).
            for ex, sol in zip(labs[n].get("gl_exercise_files", []), labs[n].get("gl_solution_files", [])):
                files[ex] = (name, read(given.get(os.path.basename(ex), os.path.join(ROOT, sol))))
            for ex, sol in zip(exercises, solutions):
                path = given.get(os.path.basename(ex), os.path.join(ROOT, sol) if drop_in else None)
                if path is None:
                    break
                files[ex] = (name, read(path))
            else:
                offered[kind].append(files)
        if drop_in:
            slots = list(zip(exercises, solutions)) + list(zip(labs[n].get("gl_exercise_files", []), labs[n].get("gl_solution_files", [])))
            offered["right"].append({ex: ("solution", read(os.path.join(ROOT, sol))) for ex, sol in slots})
        answers[n] = offered
        if not offered["right"]:
            sys.exit("make_submissions: no right answer for lab %d in tests/answers" % n)

    # The rare kinds in fixed numbers, on students drawn from the seed (at least one each).
    count = args.count
    special = {}
    students = list(range(count))
    rng.shuffle(students)
    picks = iter(students)
    wanted = [("endless_loop", glsl_labs)] * max(1, count // 40)
    for kind, times in (("endless_loop", 1), ("crash", max(1, count // 100)), ("forbidden_call", 1), ("syntax_error", 1)):
        wanted += [(kind, cpp_labs)] * times
    for kind, where in wanted:  # a small class gets the first ones only
        student = next(picks, None)
        if where and student is not None:
            special[student] = (kind, rng.choice(where))
    refused = next(picks, None)
    forms = {next(picks, None): "zip", next(picks, None): "tar.gz"}  # at least one of each

    out = os.path.abspath(args.out)
    subs = os.path.join(out, "submissions")
    shutil.rmtree(subs, ignore_errors=True)
    os.makedirs(subs)
    expected = {}
    kinds = ["right"] * 50 + ["wrong"] * 30 + ["stock"] * 8 + ["missing"] * 3 + ["syntax_error"] * 5 + ["semantic_error"] * 4
    for s in range(count):
        name = "student%03d" % s
        files, record = {}, {}
        for n in numbers:
            exercises = labs[n]["exercise_files"]
            kind = special[s][0] if s in special and special[s][1] == n else rng.choice(kinds)
            if kind == "wrong" and not answers[n]["wrong"]:
                kind = "stock"
            chosen = rng.choice(answers[n]["wrong" if kind == "wrong" else "right"])
            carrier = rng.choice(exercises)  # the file a stock, missing or broken answer is about
            entry = {"kind": kind, "status": EXPECTED[kind], "file": carrier,
                     "variant": chosen[exercises[0]][0]}
            for ex in exercises:
                variant, text = chosen[ex]
                if ex == carrier and kind not in ("right", "wrong"):
                    if kind == "stock":
                        variant, text = "stock " + os.path.basename(ex), read(os.path.join(ROOT, ex))
                    elif kind == "missing":
                        continue
                    else:
                        stock = read(os.path.join(ROOT, ex))
                        text, line = broken(text, kind, ex.endswith(".cpp"), entry_function(stock))
                        variant = kind + " in " + variant
                        if line is not None:
                            entry["line"] = line + 1  # the name line below comes first
                    entry["variant"] = variant
                files[ex] = "// %s: %s\n%s" % (name, variant, text)
            for ex in labs[n].get("gl_exercise_files", []):  # as the answer gives it, never broken here
                variant, text = chosen[ex]
                files[ex] = "// %s: %s\n%s" % (name, variant, text)
            if kind == "wrong" and unbuildable[(n, chosen[exercises[0]][0])]:
                entry["status"] = unbuildable[(n, chosen[exercises[0]][0])]
            record[str(n)] = entry
        kind = "folder"
        r = rng.random()
        if s == refused:
            kind = "refused.zip"
            for entry in record.values():
                entry.update({"kind": "refused", "status": "failed"})
                entry.pop("line", None)
        elif forms.get(s) == "zip" or (s not in forms and r < 0.10):
            kind = "zip"
        elif forms.get(s) == "tar.gz" or (s not in forms and r < 0.15):
            kind = "tar.gz"
        wrapped = rng.random() < 0.5
        write_submission(subs, name, files, kind, wrapped)
        expected[name] = {"form": kind + (" (wrapped)" if wrapped and kind != "folder" else ""), "labs": record}
    with open(os.path.join(out, "expected.json"), "w") as f:
        json.dump({"seed": args.seed, "labs": numbers, "students": expected}, f, indent=1, sort_keys=True)
    tally = {}
    for e in expected.values():
        for lab in e["labs"].values():
            tally[lab["status"]] = tally.get(lab["status"], 0) + 1
    print("make_submissions: %d submissions in %s; labs expected: %s" % (count, subs, json.dumps(tally, sort_keys=True)))


def write_submission(subs, name, files, kind, wrapped):
    if kind == "folder":
        for rel, text in files.items():
            path = os.path.join(subs, name, rel)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w") as f:
                f.write(text)
        os.makedirs(os.path.join(subs, name, "labs"), exist_ok=True)
        return
    prefix = name + "/" if wrapped else ""
    if kind in ("zip", "refused.zip"):
        with zipfile.ZipFile(os.path.join(subs, name + ".zip"), "w", zipfile.ZIP_DEFLATED) as z:
            for rel, text in files.items():
                z.writestr(prefix + rel, text)
            if kind == "refused.zip":
                z.writestr("../../outside.txt", "an entry that leaves the folder")
        return
    with tarfile.open(os.path.join(subs, name + ".tar.gz"), "w:gz") as t:
        for rel, text in files.items():
            data = text.encode()
            info = tarfile.TarInfo(prefix + rel)
            info.size = len(data)
            t.addfile(info, io.BytesIO(data))


if __name__ == "__main__":
    main()
