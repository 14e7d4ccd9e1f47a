#!/usr/bin/env python3
"""Checks that the lab texts (labs/NN_*/README.md) agree with the code they describe.

    lab_texts.py [ROOT]

A figure a text takes from the code carries a marker right after it, invisible when rendered:

    at least 99.5 %<!-- = labs/09_shadow_volumes/lab.cpp:kMinAgreement*100 -->

The marker names a file, a constant defined in it (`NAME = value` or `NAME{value}`, C++ or GLSL) and an
optional scale. The figure before the marker must equal the constant times the scale, to the digits the
text prints. Each text must also have a task section ("Your task" or "Your part") and a "How to see it"
section (the window's panel shows both), a "The check" section whose limits all carry markers and a
"Sources" section, and must not mention issues (it is the student's text). Exit 0 when every
text agrees, 1 otherwise (each disagreement printed with its file and line).
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2]
NUMBER = r"[-+]?(?:\d{1,3}(?:,\d{3})+|\d+)(?:\.\d+)?(?:e[-+]?\d+)?"
MARKED = re.compile(r"(" + NUMBER + r")\s*(?:%|deg|texels?|px|x)?\s*<!-- = ([^:\s]+):(\w+)(?:\*([-+0-9.e]+))? -->")
MARKER = re.compile(r"<!-- = [^>]*-->")


def constant(path, name):
    text = path.read_text(encoding="utf-8")
    m = re.search(r"\b" + name + r"\b(?:\[\])?\s*(?:=\s*|\{)\s*([-+]?[0-9][0-9.eE+-]*)f?\s*[;,})]", text)
    if not m:
        raise LookupError(f"no constant {name} in {path.relative_to(ROOT)}")
    return float(m.group(1))


def agrees(printed, value):
    digits = printed.replace(",", "")
    mantissa = digits.split("e")[0]
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    exponent = int(digits.split("e")[1]) if "e" in digits else 0
    step = 10.0 ** (exponent - decimals)
    # Strictly within half a unit of the last printed digit: 99 is not 99.5 (print enough digits).
    return abs(float(digits) - value) < 0.5 * step - 1e-12 * abs(value)


def check_text(readme):
    problems = []
    lines = readme.read_text(encoding="utf-8").splitlines()
    where = lambda i: f"{readme.relative_to(ROOT)}:{i + 1}"
    section = ""
    sections = set()
    for i, line in enumerate(lines):
        if line.startswith("## "):
            section = line[3:].strip()
            sections.add(section.split(" (")[0])
        if re.search(r"\bissues?\b", line, re.IGNORECASE):
            problems.append(f"{where(i)}: a student's text mentions an issue")
        for m in MARKED.finditer(line):
            printed, file, name, scale = m.groups()
            try:
                value = constant(ROOT / file, name) * (float(scale) if scale else 1.0)
            except (LookupError, OSError) as e:
                problems.append(f"{where(i)}: {e}")
                continue
            if not agrees(printed, value):
                problems.append(f"{where(i)}: the text says {printed}, {file} has {name} = {value:g}")
        if MARKER.search(line) and len(MARKED.findall(line)) != len(MARKER.findall(line)):
            problems.append(f"{where(i)}: a marker without a figure right before it")
        if section.startswith("The check") and line.startswith("|") and not line.startswith("|---"):
            limit = line.strip("|").split("|")[-1]
            bare = MARKER.sub("", limit)
            if re.search(r"\d", bare) and not MARKER.search(limit):
                problems.append(f"{where(i)}: a limit in the check's table without a marker to the code: {limit.strip()}")
    for needed in ("Your task" if "Your task" in sections else "Your part", "How to see it", "The check", "Sources"):
        if needed not in sections:
            problems.append(f"{readme.relative_to(ROOT)}: no '## {needed}' section")
    return problems


def main():
    readmes = sorted(ROOT.glob("labs/[0-9][0-9]_*/README.md"))
    if not readmes:
        print("lab_texts: no lab texts found", file=sys.stderr)
        return 2
    problems = [p for r in readmes for p in check_text(r)]
    for p in problems:
        print(p)
    marked = sum(len(MARKED.findall(r.read_text(encoding="utf-8"))) for r in readmes)
    print(f"{len(readmes)} lab texts, {marked} figures tied to the code, {len(problems)} disagreements")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
