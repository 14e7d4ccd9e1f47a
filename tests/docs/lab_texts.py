#!/usr/bin/env python3
"""Checks that the lab texts, the instructor notes and the project's README agree with the code and
with the recorded runs they quote.

    lab_texts.py [ROOT]

A figure a text takes from the code carries a marker right after it, invisible when rendered:

    at least 99.5 %<!-- = labs/09_shadow_volumes/lab.cpp:kMinAgreement*100 -->

The marker names a file, a constant defined in it (`NAME = value` or `NAME{value}`, C++ or GLSL; or a
lab's preset, `preset(NAME).key`) and an optional scale. The figure before the marker must equal the constant times the scale, to the digits the
text prints (rounded: 0.048 % stands for anything in [0.0475, 0.0485)). A measured figure names a
recorded run instead (docs/measured/lab_NN.json, made by `tests/docs/measured.py record`; CTest
docs.measured_replay proves the deterministic ones still hold for the current code):

    acne 0.048 %<!-- @ lab_00.json:/runs/solution/result/metrics/interior/acne_rate*100 -->

Student texts (labs/NN_*/README.md) must also have a task section ("Your task" or "Your part") and a
"How to see it" section (the window's panel shows both), a "The check" section whose limits all carry
markers and a "Sources" section, and must not mention issues. In the student texts and the
instructor notes (labs/NN_*/INSTRUCTOR.md) every figure that looks measured (a decimal point, a per cent sign, a
thousands separator or an exponent; not inside `code`) must carry a marker of either kind. The
project's README.md is held to its markers. Exit 0 when every text agrees, 1 otherwise (each
disagreement printed with its file and line).
"""
import json
import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2]
NUMBER = r"[-+]?(?:\d{1,3}(?:,\d{3})+|\d+)(?:\.\d+)?(?:e[-+]?\d+)?"
MARKED = re.compile(r"(" + NUMBER + r")\s*(?:%|deg|texels?|px|x)?\s*<!-- = ([^:\s]+):(\w+(?:\[\d+\])?|preset\([^)]*\)\.[\w.]+)(?:\*([-+0-9.e]+))? -->")
MEASURED = re.compile(r"(" + NUMBER + r")\s*(?:%|deg|texels?|px|x|ms|s|MB)?\s*<!-- @ ([^:\s]+):(/\S*?)(?:\*([-+0-9.e]+))? -->")
MARKER = re.compile(r"<!-- [=@] [^>]*-->")
# A figure that looks measured: a decimal point, an exponent, a thousands separator or a per cent sign.
LOOKS_MEASURED = re.compile(r"(?<![\w.])(?:\d+(?:\.\d+)?\s*%|\d{1,3}(?:,\d{3})+(?:\.\d+)?|\d*\.\d+(?:e[-+]?\d+)?|\d+e[-+]?\d+)(?![\w.])")


def constant(path, name):
    text = path.read_text(encoding="utf-8")
    preset = re.fullmatch(r"preset\(([^)]*)\)\.([\w.]+)", name)
    if preset:  # a lab's preset: {"name", "description", {{"key", "value"}, ...}}
        m = re.search(r'\{"' + re.escape(preset.group(1)) + r'",\s*"(?:[^"\\]|\\.)*",\s*\{(.*?)\}\}', text, re.DOTALL)
        value = m and re.search(r'\{"' + re.escape(preset.group(2)) + r'",\s*"([-+0-9.e]+)"', m.group(1))
        if not value:
            raise LookupError(f"no preset {preset.group(1)} setting {preset.group(2)} in {path.relative_to(ROOT)}")
        return float(value.group(1))
    element = re.fullmatch(r"(\w+)\[(\d+)\]", name)
    if element:  # an element of a constant array: NAME[N] = {a, b, ...}
        m = re.search(r"\b" + element.group(1) + r"(?:\[\d*\])?\s*(?:=\s*)?\{([^{}]*)\}", text)
        items = m.group(1).split(",") if m else []
        if int(element.group(2)) >= len(items):
            raise LookupError(f"no constant {name} in {path.relative_to(ROOT)}")
        return float(items[int(element.group(2))].strip().rstrip("f"))
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
    if float(digits) == 0 and "." not in mantissa:
        return value == 0  # a bare 0 means none, not "less than a half"
    # Strictly within half a unit of the last printed digit: 99 is not 99.5 (print enough digits).
    return abs(float(digits) - value) < 0.5 * step - 1e-12 * abs(value)


def resolve(data, pointer):
    """The value a JSON pointer (/a/0/b; ~1 is /, ~0 is ~) names in data."""
    node = data
    for part in pointer.strip("/").split("/"):
        part = part.replace("~1", "/").replace("~0", "~")
        node = node[int(part)] if isinstance(node, list) else node[part]
    return node


def measured_value(file, pointer):
    node = resolve(json.loads((ROOT / "docs" / "measured" / file).read_text(encoding="utf-8")), pointer)
    if isinstance(node, bool) or not isinstance(node, (int, float)):
        raise LookupError(f"{file}:{pointer} is not a number")
    return float(node)


def texts():
    """(path, kind): the student texts, the instructor notes and the project's README."""
    for readme in sorted(ROOT.glob("labs/[0-9][0-9]_*/README.md")):
        yield readme, "student"
    for notes in sorted(ROOT.glob("labs/[0-9][0-9]_*/INSTRUCTOR.md")):
        yield notes, "instructor"
    if (ROOT / "README.md").exists():
        yield ROOT / "README.md", "project"


def measured_markers():
    """Every measured marker: (file:line, printed figure, JSON file, pointer, scale)."""
    for path, _ in texts():
        for i, line in enumerate(path.read_text(encoding="utf-8").splitlines()):
            for m in MEASURED.finditer(line):
                printed, file, pointer, scale = m.groups()
                yield f"{path.relative_to(ROOT)}:{i + 1}", printed, file, pointer, float(scale) if scale else 1.0


def without_code(line):
    return re.sub(r"`[^`]*`", "", line)


def check_text(readme, kind="student"):
    problems = []
    lines = readme.read_text(encoding="utf-8").splitlines()
    where = lambda i: f"{readme.relative_to(ROOT)}:{i + 1}"
    section = ""
    sections = set()
    fenced = False
    for i, line in enumerate(lines):
        if line.startswith("```"):
            fenced = not fenced
            continue
        if line.startswith("## "):
            section = line[3:].strip()
            sections.add(section.split(" (")[0])
        if kind == "student" and re.search(r"\bissues?\b", line, re.IGNORECASE):
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
        for m in MEASURED.finditer(line):
            printed, file, pointer, scale = m.groups()
            try:
                value = measured_value(file, pointer) * (float(scale) if scale else 1.0)
            except (LookupError, OSError, KeyError, IndexError, ValueError) as e:
                problems.append(f"{where(i)}: {file}:{pointer}: {e!r}")
                continue
            if not agrees(printed, value):
                problems.append(f"{where(i)}: the text says {printed}, the recorded run {file}:{pointer} has {value:g}")
        if MARKER.search(line) and len(MARKED.findall(line)) + len(MEASURED.findall(line)) != len(MARKER.findall(line)):
            problems.append(f"{where(i)}: a marker without a figure right before it")
        if kind in ("instructor", "student") and not fenced:
            bare = MARKER.sub("", MARKED.sub("", MEASURED.sub("", without_code(line))))
            bare = re.sub(r"\b(?:GLSL|OpenGL) \d\.\d+", "", bare)  # a specification's version
            for m in LOOKS_MEASURED.finditer(bare):
                problems.append(f"{where(i)}: a figure with no marker to the code or a recorded run: {m.group(0)}")
        if kind == "student" and section.startswith("The check") and line.startswith("|") and not line.startswith("|---"):
            limit = line.strip("|").split("|")[-1]
            bare = MARKER.sub("", limit)
            if re.search(r"\d", bare) and not MARKER.search(limit):
                problems.append(f"{where(i)}: a limit in the check's table without a marker to the code: {limit.strip()}")
    if kind == "student":
        for needed in ("Your task" if "Your task" in sections else "Your part", "How to see it", "The check", "Sources"):
            if needed not in sections:
                problems.append(f"{readme.relative_to(ROOT)}: no '## {needed}' section")
    return problems


def main():
    found = list(texts())
    if not any(kind == "student" for _, kind in found):
        print("lab_texts: no lab texts found", file=sys.stderr)
        return 2
    problems = [p for path, kind in found for p in check_text(path, kind)]
    for p in problems:
        print(p)
    tied = measured = 0
    for path, _ in found:
        text = path.read_text(encoding="utf-8")
        tied += len(MARKED.findall(text))
        measured += len(MEASURED.findall(text))
    print(f"{len(found)} texts, {tied} figures tied to the code, {measured} to recorded runs, {len(problems)} disagreements")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
