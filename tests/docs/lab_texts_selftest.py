#!/usr/bin/env python3
"""lab_texts.py must fail when a text and the code or a recorded run disagree: mutations of a copy of
labs/, docs/measured/ and README.md.

    lab_texts_selftest.py ROOT
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(sys.argv[1])
CHECKER = pathlib.Path(__file__).with_name("lab_texts.py")

MUTATIONS = [
    # (file, old, new, what the checker must print)
    ("labs/09_shadow_volumes/README.md", "99.5 %<!--", "99 %<!--", "the text says 99,"),
    ("labs/04_light_bleeding/lab.cpp", "kMaxBleedingRatio = 0.25", "kMaxBleedingRatio = 0.3", "kMaxBleedingRatio = 0.3"),
    ("labs/06_pcf/README.md", "## How to see it", "## Seeing it", "no '## How to see it' section"),
    ("labs/08_point_light/README.md", "## Sources", "## Reading", "no '## Sources' section"),
    # The instructor notes: a figure no marker ties, a quoted figure changed, a recorded value changed.
    ("labs/06_pcf/INSTRUCTOR.md", "## Costs", "A leak of 0.5 % was seen.\n\n## Costs", "no marker to the code or a recorded run: 0.5 %"),
    ("labs/04_light_bleeding/INSTRUCTOR.md", "1.724<!-- @ lab_04.json:/runs/solution/result/metrics/stacked_blur4_unfixed/",
     "1.9<!-- @ lab_04.json:/runs/solution/result/metrics/stacked_blur4_unfixed/", "the text says 1.9, the recorded run lab_04.json"),
    ("docs/measured/lab_09.json", '"interior_agreement": 0.0005110269467045736', '"interior_agreement": 0.0105110269467045736', "the recorded run lab_09.json"),
    ("README.md", "fewer than 500<!--", "fewer than 400<!--", "the text says 400"),
    # A preset's value changed in the code; an untied figure in a student's text.
    ("labs/04_light_bleeding/lab.cpp", '{{"vsm.bleed_delta", "0.125"}, ', '{{"vsm.bleed_delta", "0.15"}, ',
     "preset(course).vsm.bleed_delta = 0.15"),
    ("labs/14_msm/README.md", "of half the weight at depth 0", "of 0.5 of the weight at depth 0", "no marker to the code or a recorded run: 0.5"),
    # Whole numbers: an untied one in a student's text and in an instructor note; an integer constant and
    # an element of a nested initializer changed in a lab.cpp.
    ("labs/05_moment_blur/README.md", "## How to see it", "A 512 map shows it best.\n\n## How to see it",
     "a whole number with no marker to the code or a recorded run: 512"),
    ("labs/06_pcf/lab.cpp", "constexpr int kMapSize = 64;", "constexpr int kMapSize = 128;", "kMapSize = 128"),
    ("labs/07_spot_light/lab.cpp", "kHeldOutDistance[] = {6.0f, 9.0f}", "kHeldOutDistance[] = {6.0f, 10.0f}",
     "kHeldOutDistance[1] = 10"),
    ("labs/06_pcf/INSTRUCTOR.md", "## Costs", "Also timed at 1280 wide.\n\n## Costs",
     "a whole number with no marker to the code or a recorded run: 1280"),
    # A table cell split in two by an edit.
    ("labs/01_bias_tuning/README.md", "| doubling the slope slider: growth", "| doubling the slope slider: | growth",
     "a table row with 3 columns under a header with 2"),
    # The README's corpus table: a count changed.
    ("README.md", "| 6 pcf | 2<!--", "| 6 pcf | 3<!--", "the text says 3, tests/answers/06_pcf/right holds 2 answers"),
]


def run(root):
    return subprocess.run([sys.executable, str(CHECKER), str(root)], capture_output=True, text=True)


def copy_texts(tmp):
    """What the texts name: the product rooms (app/, core/, oracle/, renderer/, grading/, labs/), shaders/, docs/measured/, docs/*.json (the benchmark's recorded
    runs), README.md, the test sources whose constants a text quotes and the exam corpus whose answers the README
    counts."""
    for folder in ("app", "core", "oracle", "renderer", "grading", "labs", "shaders", "docs/measured"):
        shutil.copytree(ROOT / folder, pathlib.Path(tmp) / folder)
    (pathlib.Path(tmp) / "tests").mkdir()
    for source in ROOT.glob("tests/*.cpp"):
        shutil.copy(source, pathlib.Path(tmp) / "tests" / source.name)
    shutil.copytree(ROOT / "tests" / "answers", pathlib.Path(tmp) / "tests" / "answers")
    shutil.copy(ROOT / "README.md", pathlib.Path(tmp) / "README.md")
    for run in (ROOT / "docs").glob("*.json"):
        shutil.copy(run, pathlib.Path(tmp) / "docs" / run.name)


def main():
    clean = run(ROOT)
    if clean.returncode != 0:
        print("the unmodified texts do not pass:\n" + clean.stdout)
        return 1
    failures = 0
    # One copy for all mutations: each is made on the copy and undone before the next (the file's text
    # written back), so every run sees the copy that passed above with that one change.
    with tempfile.TemporaryDirectory() as tmp:
        copy_texts(tmp)
        copied = run(tmp)
        if copied.returncode != 0:
            print("the unmodified copy does not pass:\n" + copied.stdout)
            return 1
        for file, old, new, expected in MUTATIONS:
            path = pathlib.Path(tmp) / file
            text = path.read_text(encoding="utf-8")
            if old not in text:
                print(f"{file}: '{old}' not found: the self-test is out of date")
                failures += 1
                continue
            path.write_text(text.replace(old, new, 1), encoding="utf-8")
            out = run(tmp)
            path.write_text(text, encoding="utf-8")
            if out.returncode != 1 or expected not in out.stdout:
                print(f"{file}: '{old}' -> '{new}' not caught (exit {out.returncode}):\n{out.stdout}")
                failures += 1
    print(f"{len(MUTATIONS) - failures} of {len(MUTATIONS)} mutations caught")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
