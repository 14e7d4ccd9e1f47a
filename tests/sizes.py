#!/usr/bin/env python3
"""Size limits of product code (issue 37): no function over 80 lines and no file over 600, unless its comment
says why.

Lists every C++ function definition longer than 80 lines (from its name's line to its closing brace, as
Universal Ctags reports them: --fields=+ne) and every source file longer than 600 lines in the product rooms
(core/ oracle/ renderer/ grading/ labs/ app/; *.h and *.cpp; not tests/, not shaders/, not third-party code,
which lives outside these rooms). Each must carry a marker that says why, else this fails naming it:
  - a function: `// size: <reason>` in the comment lines right above its definition (the lines between it
    and the previous code, template lines included);
  - a file: `// size: <reason>` in its first 10 lines.
A marker without a reason does not count.

Usage: tests/sizes.py [ROOT]      checks ROOT (default: this checkout)
       tests/sizes.py --self-test builds a tree with an 81-line function and a 601-line file and requires
                                  that it fails on both, also when the marker has no reason, and passes
                                  once each carries a marker (and that 80 and 600 lines pass without one)
"""
import json
import os
import re
import subprocess
import sys
import tempfile

ROOMS = ["core", "oracle", "renderer", "grading", "labs", "app"]
MAX_FUNCTION = 80
MAX_FILE = 600
MARKER = re.compile(r"//\s*size:\s*(\S.*)$")


def sources(root):
    found = []
    for room in ROOMS:
        for dirpath, _, names in os.walk(os.path.join(root, room)):
            for name in names:
                if name.endswith((".h", ".cpp")):
                    found.append(os.path.relpath(os.path.join(dirpath, name), root))
    return sorted(found)


def functions(root, files):
    """(path, name, first line, last line) of every function definition ctags finds."""
    if not files:
        return []
    try:
        out = subprocess.run(
            ["ctags", "--languages=C++", "--langmap=C++:+.h", "--kinds-C++=f", "--fields=+ne",
             "--output-format=json", "-f", "-", *files],
            cwd=root, check=True, capture_output=True, text=True).stdout
    except FileNotFoundError:
        sys.exit("sizes: no ctags command: Universal Ctags finds where functions end (scripts/setup installs it)")
    found = []
    for line in out.splitlines():
        tag = json.loads(line)
        if tag.get("_type") == "tag" and tag.get("kind") == "function" and "end" in tag:
            found.append((tag["path"], tag["name"], tag["line"], tag["end"]))
    return found


def marked_above(lines, first):
    """Whether the comment lines right above line `first` (1-based) hold a marker with a reason: up from the
    line above the function's name, through its comment and the start of its declaration (template line,
    return type), to the first blank line or the end of the code before it."""
    for i in range(first - 2, max(first - 42, -1), -1):
        text = lines[i].strip()
        if text.startswith("//"):
            if MARKER.search(text):
                return True
        elif text == "" or text.endswith((";", "}", "{")):
            return False
    return False


def violations(root):
    files = sources(root)
    text = {}
    for f in files:
        with open(os.path.join(root, f), encoding="utf-8") as fh:
            text[f] = fh.read().splitlines()
    bad = []
    for f in files:
        n = len(text[f])
        if n > MAX_FILE and not any(MARKER.search(l) for l in text[f][:10]):
            bad.append(f"{f}: {n} lines (over {MAX_FILE}) and no `// size: <reason>` in its first 10 lines")
    for path, name, first, last in functions(root, files):
        n = last - first + 1
        if n > MAX_FUNCTION and not marked_above(text[path], first):
            bad.append(f"{path}:{first}: {name} is {n} lines (over {MAX_FUNCTION}) and no `// size: <reason>` "
                       "comment right above it")
    return sorted(bad)


def self_test():
    def tree(function_lines, file_lines, function_marker, file_marker):
        root = tempfile.mkdtemp(prefix="sizes-")
        os.makedirs(os.path.join(root, "core"))
        body = ["  x += %d;" % i for i in range(function_lines - 2)]
        fn = ([function_marker] if isinstance(function_marker, str) else
              ["// size: one table, read top to bottom"] if function_marker else ["// Adds."]) + \
             ["int add(int x) {"] + body + ["}"]
        # A brace and a quote in a string and a comment must not end the function early.
        fn[2] = '  const char* s = "}"; // }'
        with open(os.path.join(root, "core", "long_function.cpp"), "w") as fh:
            fh.write("\n".join(["// A function.", "#include <cstdio>", ""] + fn) + "\n")
        head = ["// size: generated lines, a test's data"] if file_marker else ["// A file."]
        with open(os.path.join(root, "core", "long_file.h"), "w") as fh:
            fh.write("\n".join(head + ["int v%d = %d;" % (i, i) for i in range(file_lines - 1)]) + "\n")
        return root

    failures = []
    over = violations(tree(MAX_FUNCTION + 1, MAX_FILE + 1, False, False))
    if not any("add is 81 lines" in v for v in over):
        failures.append("an unmarked 81-line function was not reported: %s" % over)
    if not any("long_file.h: 601 lines" in v for v in over):
        failures.append("an unmarked 601-line file was not reported: %s" % over)
    marked = violations(tree(MAX_FUNCTION + 1, MAX_FILE + 1, True, True))
    if marked:
        failures.append("marked ones were reported: %s" % marked)
    empty = violations(tree(MAX_FUNCTION + 1, MAX_FILE, "// size:   ", False))
    if not any("add is 81 lines" in v for v in empty):
        failures.append("a marker without a reason was taken as one: %s" % empty)
    at_limit = violations(tree(MAX_FUNCTION, MAX_FILE, False, False))
    if at_limit:
        failures.append("80 lines and 600 lines were reported: %s" % at_limit)
    for f in failures:
        print("sizes self-test:", f, file=sys.stderr)
    if failures:
        return 1
    print("sizes self-test: an 81-line function and a 601-line file fail (also under a marker without a reason), "
          "marked or at the limit they pass")
    return 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    bad = violations(root)
    for v in bad:
        print("sizes:", v, file=sys.stderr)
    if bad:
        return 1
    print(f"sizes: no function over {MAX_FUNCTION} lines and no file over {MAX_FILE} without a reason "
          f"({len(sources(root))} files in {' '.join(ROOMS)})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
