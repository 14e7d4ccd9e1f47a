#!/usr/bin/env python3
"""lab_texts.py must fail when a text and the code disagree: three mutations of a copy of labs/.

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
]


def run(root):
    return subprocess.run([sys.executable, str(CHECKER), str(root)], capture_output=True, text=True)


def main():
    clean = run(ROOT)
    if clean.returncode != 0:
        print("the unmodified texts do not pass:\n" + clean.stdout)
        return 1
    failures = 0
    for file, old, new, expected in MUTATIONS:
        with tempfile.TemporaryDirectory() as tmp:
            shutil.copytree(ROOT / "labs", pathlib.Path(tmp) / "labs")
            path = pathlib.Path(tmp) / file
            text = path.read_text(encoding="utf-8")
            if old not in text:
                print(f"{file}: '{old}' not found: the self-test is out of date")
                failures += 1
                continue
            path.write_text(text.replace(old, new, 1), encoding="utf-8")
            out = run(tmp)
            if out.returncode != 1 or expected not in out.stdout:
                print(f"{file}: '{old}' -> '{new}' not caught (exit {out.returncode}):\n{out.stdout}")
                failures += 1
    print(f"{len(MUTATIONS) - failures} of {len(MUTATIONS)} mutations caught")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
