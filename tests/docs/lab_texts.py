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
thousands separator or an exponent; not inside `code`) must carry a marker of either kind. So must
every whole number there (map sizes, degrees, radii, positions, counts), except what NOT_FIGURES lists:
lab numbers and references to labs, list numbering, the names of parts, tasks and passes, spec versions,
GLSL's guaranteed offsets [-8, 7], a power's exponent (the 2 of 1024^2), and 0 and 1; nor inside code
(code spans, fenced or indented blocks) or in the Sources section (years, chapters and pages of
citations).

A count of the exam corpus's answers names its folders (a glob), counted as check_corpus.py does:

    143<!-- # tests/answers/*/wrong --> wrong answers

The project's README.md and the corpus's (tests/answers/README.md) are held to their markers. Exit 0 when every text agrees, 1 otherwise (each
disagreement printed with its file and line).
"""
import functools
import json
import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2]
NUMBER = r"(?:(?<![\w>)])[-+])?(?:\d{1,3}(?:,\d{3})+|\d+)(?:\.\d+)?(?:e[-+]?\d+)?"
MARKED = re.compile(r"(" + NUMBER + r")\s*(?:%|deg|texels?|px|x)?\s*<!-- = ([^:\s]+):(\w+(?:\[\d+\])*|preset\([^)]*\)\.[\w.]+)(?:\*([-+0-9.e]+))? -->")
MEASURED = re.compile(r"(" + NUMBER + r")\s*(?:%|deg|texels?|px|x|ms|s|MB)?\s*<!-- @ ([^:\s]+):(/\S*?)(?:\*([-+0-9.e]+))? -->")
# A count of the exam corpus's answers: the folders (a glob under the project) hold that many answers, each
# counted once as check_corpus.py does (files NAME__SLOT; one answer may fill several slots).
COUNTED = re.compile(r"(" + NUMBER + r")\s*<!-- # (tests/answers/[^\s>]+) -->")
MARKER = re.compile(r"<!-- [=@#] [^>]*-->")
# A figure that looks measured: a decimal point, an exponent, a thousands separator or a per cent sign.
LOOKS_MEASURED = re.compile(r"(?<![\w.])(?:\d+(?:\.\d+)?\s*%|\d{1,3}(?:,\d{3})+(?:\.\d+)?|\d*\.\d+(?:e[-+]?\d+)?|\d+e[-+]?\d+)(?![\w.])")
# A whole number (map sizes, degrees, radii, positions, counts): a figure too, unless it is one of these.
INTEGER = re.compile(r"(?<![\w.^])\d+(?![\w.]|,\d)")
NOT_FIGURES = [  # (what it is, the pattern taken out before whole numbers are looked for)
    ("a lab's number or a reference to a lab", re.compile(r"\b[Ll]abs? \d+(?:(?:, | and | or |-)\d+)*")),
    ("list numbering", re.compile(r"^\s*\d+\.\s")),
    ("the name of a part of the task, a course task or a render pass",
     re.compile(r"\b(?:[Pp]arts?|[Tt]asks?|[Pp]ass(?:es)?|[Ss]teps?) \d+(?:(?:, | and | or )\d+)*")),
    ("a specification's version", re.compile(r"\b(?:GLSL|OpenGL) \d\.\d+")),
    ("the texel offsets GLSL guarantees, a fact of the specification", re.compile(r"\[-8, 7\]")),
    ("a power's exponent (1024^2 is a square map; the 2 is notation)", re.compile(r"\^\d+")),
    ("0 and 1, the unit values (none/all, shadowed/lit, the ends of [0, 1], n . l = 1, +-1, a vector's component)",
     re.compile(r"(?<![\w.^])[-+]?[01](?![\w.]|,\d)")),
]


def initializer(text, start):
    """The brace initializer that starts after the "{" before text[start]: (nested lists of item strings,
    the index of its closing brace)."""
    items, item, i = [], "", start
    while text[i] != "}":
        if text[i] == "{":
            inner, i = initializer(text, i + 1)
            items.append(inner)
            item = None  # the braces were the item
        elif text[i] == ",":
            if item:
                items.append(item.strip())
            item = ""
        elif item is not None:
            item += text[i]
        i += 1
    if item and item.strip():
        items.append(item.strip())
    return items, i


@functools.lru_cache(maxsize=None)
def read(path):
    """A file's text, read once per run: hundreds of markers name the same few files."""
    return path.read_text(encoding="utf-8")


@functools.lru_cache(maxsize=None)
def recorded(file):
    """A recorded run, decoded once per run (764 markers name 15 files)."""
    return json.loads(read(ROOT / "docs" / "measured" / file))


def constant(path, name):
    text = read(path)
    preset = re.fullmatch(r"preset\(([^)]*)\)\.([\w.]+)", name)
    if preset:  # a lab's preset: {"name", "description", {{"key", "value"}, ...}}
        m = re.search(r'\{"' + re.escape(preset.group(1)) + r'",\s*"(?:[^"\\]|\\.)*",\s*\{(.*?)\}\}', text, re.DOTALL)
        value = m and re.search(r'\{"' + re.escape(preset.group(2)) + r'",\s*"([-+0-9.e]+)"', m.group(1))
        if not value:
            raise LookupError(f"no preset {preset.group(1)} setting {preset.group(2)} in {path.relative_to(ROOT)}")
        return float(value.group(1))
    element = re.fullmatch(r"(\w+)((?:\[\d+\])+)", name)
    if element:  # an element of a constant array or aggregate, nested as deep as the braces: NAME[i][j]
        m = re.search(r"\b" + element.group(1) + r"(?:\[\d*\])?\s*(?:=\s*)?\{", text)
        node = initializer(text, m.end())[0] if m else []
        for index in map(int, re.findall(r"\d+", element.group(2))):
            if not isinstance(node, list) or index >= len(node):
                raise LookupError(f"no constant {name} in {path.relative_to(ROOT)}")
            node = node[index]
        try:  # a number (1.5f, 40.0f) or a quoted choice ("1024")
            return float(node.strip('"').rstrip("f")) if isinstance(node, str) else float("nan")
        except ValueError:
            raise LookupError(f"{name} in {path.relative_to(ROOT)} is not a number: {node}") from None
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


def number(node, name):
    """A recorded value as a number; a choice parameter's value is a string of digits (shadow.map_size "1024")."""
    if isinstance(node, str) and re.fullmatch(r"[-+]?\d+(?:\.\d+)?", node):
        return float(node)
    if isinstance(node, bool) or not isinstance(node, (int, float)):
        raise LookupError(f"{name} is not a number")
    return float(node)


def measured_value(file, pointer):
    node = resolve(recorded(file), pointer)
    return number(node, f"{file}:{pointer}")


def answers_in(pattern):
    """How many answers the corpus folders matching pattern hold (NAME__SLOT files, one per NAME). A pattern
    whose last part names files (`tests/answers/00_basic_shadow_map/wrong/*__gl_shadow_target.cpp`) counts
    the answers that give that slot."""
    if "__" in pattern.rsplit("/", 1)[-1]:
        files = [f for f in sorted(ROOT.glob(pattern)) if f.is_file()]
        if not files:
            raise LookupError(f"no corpus file {pattern}")
        return len({(f.parent, f.name.partition("__")[0]) for f in files})
    folders = [f for f in sorted(ROOT.glob(pattern)) if f.is_dir()]
    if not folders:
        raise LookupError(f"no corpus folder {pattern}")
    return sum(len({p.name.partition("__")[0] for p in f.glob("*__*")}) for f in folders)


def texts():
    """(path, kind): the student texts, the instructor notes and the project's README."""
    for readme in sorted(ROOT.glob("labs/[0-9][0-9]_*/README.md")):
        yield readme, "student"
    for notes in sorted(ROOT.glob("labs/[0-9][0-9]_*/INSTRUCTOR.md")):
        yield notes, "instructor"
    if (ROOT / "README.md").exists():
        yield ROOT / "README.md", "project"
    if (ROOT / "tests/answers/README.md").exists():  # the corpus's own text: held to its markers
        yield ROOT / "tests/answers/README.md", "corpus"


def measured_markers():
    """Every measured marker: (file:line, printed figure, JSON file, pointer, scale)."""
    for path, _ in texts():
        for i, line in enumerate(read(path).splitlines()):
            for m in MEASURED.finditer(line):
                printed, file, pointer, scale = m.groups()
                yield f"{path.relative_to(ROOT)}:{i + 1}", printed, file, pointer, float(scale) if scale else 1.0


def without_code(line):
    return re.sub(r"`[^`]*`", "", line)


def whole_numbers(bare):
    """The whole numbers in a line (code, markers and their figures already taken out) that are figures."""
    bare = re.sub(r"(\d)x(\d)", r"\1 x \2", LOOKS_MEASURED.sub(" ", bare))  # 960x540: two figures
    for _, pattern in NOT_FIGURES:
        bare = pattern.sub(" ", bare)
    return [m.group(0) for m in INTEGER.finditer(bare)]


def check_text(readme, kind="student"):
    problems = []
    lines = read(readme).splitlines()
    where = lambda i: f"{readme.relative_to(ROOT)}:{i + 1}"
    section = ""
    sections = set()
    fenced = indented = False
    columns = 0
    for i, line in enumerate(lines):
        if line.startswith("```"):
            fenced = not fenced
            continue
        # An indented code block (four spaces after a blank line): code, like a fenced one.
        indented = line.startswith("    ") and (indented or i == 0 or not lines[i - 1].strip())
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
        for m in COUNTED.finditer(line):
            printed, pattern = m.groups()
            try:
                value = answers_in(pattern)
            except LookupError as e:
                problems.append(f"{where(i)}: {e}")
                continue
            if not agrees(printed, value):
                problems.append(f"{where(i)}: the text says {printed}, {pattern} holds {value} answers")
        if MARKER.search(line) and len(MARKED.findall(line)) + len(MEASURED.findall(line)) + len(COUNTED.findall(line)) != len(MARKER.findall(line)):
            problems.append(f"{where(i)}: a marker without a figure right before it")
        if kind in ("instructor", "student") and not fenced and not indented:
            bare = MARKER.sub("", COUNTED.sub("", MARKED.sub("", MEASURED.sub("", without_code(line)))))
            bare = re.sub(r"\b(?:GLSL|OpenGL) \d\.\d+", "", bare)  # a specification's version
            for m in LOOKS_MEASURED.finditer(bare):
                problems.append(f"{where(i)}: a figure with no marker to the code or a recorded run: {m.group(0)}")
            if not section.startswith("Sources"):  # citations: years, chapters and pages are not figures
                for number in whole_numbers(bare):
                    problems.append(f"{where(i)}: a whole number with no marker to the code or a recorded run: {number}")
        if line.startswith("|"):  # every row of a table has its header's columns (an edit may split a cell)
            cells = MARKER.sub("", without_code(line)).strip().strip("|").count("|") + 1
            columns = columns if i > 0 and lines[i - 1].startswith("|") else cells
            if cells != columns:
                problems.append(f"{where(i)}: a table row with {cells} columns under a header with {columns}")
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
    tied = measured = counted = 0
    for path, _ in found:
        text = read(path)
        tied += len(MARKED.findall(text))
        measured += len(MEASURED.findall(text))
        counted += len(COUNTED.findall(text))
    print(f"{len(found)} texts, {tied} figures tied to the code, {measured} to recorded runs, {counted} to the exam corpus, "
          f"{len(problems)} disagreements")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
