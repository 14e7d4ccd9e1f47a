#!/usr/bin/env python3
"""Hostile submissions for `shadowlab grade` (issue 33's cheat corpus), and the check of what the grader
made of them.

    python3 tests/hostile_submissions.py make OUT KIND...   # OUT/submissions/<one per kind>, OUT/expected.json
    python3 tests/hostile_submissions.py check GRADES OUT/expected.json

Each kind is one submission graded on labs 0 and 2, with the status each lab must get and words its
message must hold (the message as the student reads it: paths relative to the submission, bytes that
are not UTF-8 shown as \\xNN, control characters escaped):

  right, wrong, absent, syntax   normal students: passed; failed; missing; compile_error (GLSL, the
                                 file named relative to the submission)
  latin1_archive_name            the archive's own name is not UTF-8 (b'\\xffname.tar'): graded as _name
  latin1_entry                   an entry's name is not UTF-8 (an extra file): graded
  control_entry                  a link entry named with \\xff, ESC, CR and LF: refused, the name escaped
  latin1_bytes                   \\xff\\xfe in the exercise, quoted by the compiler: compile_error
  formula_name                   '+formula.zip': a name a spreadsheet would compute (CSV: '+formula)
  sparse_1g                      GNU tar --sparse, a 1 GB hole: refused
  sparse_4g                      PAX 1.0 sparse, a 4 GB hole: refused
  liar_tar                       a tar header declaring 1 GB for 10 KB of data: refused
  liar_zip_big                   a zip header declaring 1 GB for 1 KB stored: refused before writing
  liar_zip_small                 a zip header declaring 8 MB for 1 KB stored: refused (it would be a hole)
  huge_file                      a folder whose exercise.cpp is 1 GB (sparse on disk): refused unread
  file_for_folder                a zip with a file where labs/ goes: refused, libarchive's message
                                 without the grading machine's path
  not_archive                    'notes.rar': neither a folder nor an archive, named without its path
  cpp_main                       lab 2 with a main() of its own that forges lab 0's record (lab 0 is the
                                 stock exercise, failed) and writes beside the class: compile_error
                                 (the screen), and nothing forged or written
  cpp_dup                        lab 2 replacing dup(), which the host calls before its own filter:
                                 compile_error
  cpp_digraph_include            lab 2 including the solution's source as %:include: compile_error, the
                                 file not found (the build's sandbox has no renderer sources)
  cpp_escape_at_call             lab 2 whose exercise function forges lab 0's record and writes beside
                                 the class when called (it passes every screen): crashed, SIGSYS

`check` reads results.json, results.csv, junit.xml, gradescope/<student>/results.json and every
students/*/lab_NN.json: each is valid UTF-8 without raw ESC or CR; every status and message as
expected; the CSV one line per row, 12 fields each; JUnit parses and counts failures, errors and
skipped (missing); Gradescope scores 1 exactly for passed; no student-visible message names the
folder the submissions or grades are in. Exits 1 on any difference, printing each.
"""
import csv
import glob
import io
import json
import os
import struct
import subprocess
import sys
import tarfile
import xml.etree.ElementTree as ET
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LAB0 = "labs/00_basic_shadow_map/exercise.glsl"
LAB2 = "labs/02_ortho_fit/exercise.cpp"
LAB0_GL = "labs/00_basic_shadow_map/gl_shadow_target.cpp"  # lab 0's OpenGL part: the solution is the renderer's
MISSING0 = ("missing", [LAB0 + ": not in the submission"])


def right_cpp():
    return open(sorted(glob.glob(ROOT + "/tests/answers/02_ortho_fit/right/*__exercise.cpp"))[0], "rb").read()


def wrong_cpp():
    return open(sorted(glob.glob(ROOT + "/tests/answers/02_ortho_fit/wrong/*__exercise.cpp"))[0], "rb").read()


def solution_glsl():
    return open(ROOT + "/labs/00_basic_shadow_map/solution.glsl", "rb").read()


def solution_gl():
    return open(ROOT + "/renderer/shadow_target.cpp", "rb").read()


def folder(path, files):
    for rel, data in files.items():
        os.makedirs(os.path.dirname(os.path.join(path, rel)), exist_ok=True)
        with open(os.path.join(path, rel), "wb") as f:
            f.write(data)
    os.makedirs(os.path.join(path, "labs"), exist_ok=True)


def tar_with(path, entries, fmt=tarfile.GNU_FORMAT):
    """entries: [(name as str, latin-1 for raw bytes; data bytes or None with a TarInfo type)]."""
    with open(path, "wb") as f, tarfile.open(fileobj=f, mode="w", format=fmt, encoding="latin-1") as t:
        for name, data in entries:
            info = tarfile.TarInfo(name)
            if isinstance(data, bytes):
                info.size = len(data)
                t.addfile(info, io.BytesIO(data))
            else:
                info.type, info.linkname = tarfile.SYMTYPE, data
                t.addfile(info)


def sparse_tar(path, work, size, extra_args):
    """A tar of a submission whose exercise.cpp is the right answer followed by a hole up to `size`."""
    folder(work, {LAB2: right_cpp()})
    os.truncate(os.path.join(work, LAB2), size)
    subprocess.run(["tar", "--sparse"] + extra_args + ["-cf", path, "labs"], cwd=work, check=True)


def lying_zip(path, declared):
    """A stored zip of the right answer whose headers (local and central) declare `declared` bytes."""
    with zipfile.ZipFile(path, "w", zipfile.ZIP_STORED) as z:
        z.writestr(LAB2, right_cpp())
    b = bytearray(open(path, "rb").read())
    b[22:26] = struct.pack("<I", declared)  # the local header's uncompressed size
    central = b.find(b"PK\x01\x02")
    b[central + 24:central + 28] = struct.pack("<I", declared)
    open(path, "wb").write(bytes(b))


def refused(words):
    return {"0": ("failed", ["submission refused: ", words]), "2": ("failed", ["submission refused: ", words])}


def make(out, kind):
    """Writes submission `kind` under out/submissions; returns (student name, {lab: (status, words)})."""
    subs = os.path.join(out, "submissions")
    work = os.path.join(out, "work", kind)
    if kind == "right":
        folder(os.path.join(subs, kind), {LAB0: solution_glsl(), LAB0_GL: solution_gl(), LAB2: right_cpp()})
        return kind, {"0": ("passed", []), "2": ("passed", [])}
    if kind == "wrong":
        folder(os.path.join(subs, kind), {LAB0: open(ROOT + "/" + LAB0, "rb").read(), LAB2: wrong_cpp()})
        return kind, {"0": ("failed", ["criteria failed"]), "2": ("failed", ["criteria failed"])}
    if kind == "absent":
        folder(os.path.join(subs, kind), {LAB0: solution_glsl(), LAB0_GL: solution_gl()})
        return kind, {"0": ("passed", []), "2": ("missing", [LAB2 + ": not in the submission"])}
    if kind == "syntax":
        text = solution_glsl().rstrip(b"\n") + b"\nthis is not code;\n"
        folder(os.path.join(subs, kind), {LAB0: text, LAB2: right_cpp()})
        line = text.count(b"\n")
        return kind, {"0": ("compile_error", ["%s:%d:" % (LAB0, line)]), "2": ("passed", [])}
    if kind == "latin1_archive_name":
        os.makedirs(subs, exist_ok=True)
        with open(os.path.join(subs, "").encode() + b"\xffname.tar", "wb") as f, tarfile.open(fileobj=f, mode="w") as t:
            data = right_cpp()
            info = tarfile.TarInfo(LAB2)
            info.size = len(data)
            t.addfile(info, io.BytesIO(data))
        return "_name", {"0": MISSING0, "2": ("passed", [])}
    if kind == "latin1_entry":
        tar_with(os.path.join(subs, kind + ".tar"), [(LAB2, right_cpp()), ("labs/02_ortho_fit/notes\xff.txt", b"x")])
        return kind, {"0": MISSING0, "2": ("passed", [])}
    if kind == "control_entry":
        tar_with(os.path.join(subs, kind + ".tar"), [("labs/\xff\x1b[31mred\r\nline", "/etc/passwd")])
        return kind, refused("entry 'labs/\\xff\\x1b[31mred\\x0d\nline' is a link")
    if kind == "latin1_bytes":
        tar_with(os.path.join(subs, kind + ".tar"), [(LAB2, b"#error bad \xff\xfe byte\n" + right_cpp())])
        return kind, {"0": MISSING0, "2": ("compile_error", ["#error bad \\xff\\xfe byte", LAB2 + ":1:"])}
    if kind == "formula_name":
        with zipfile.ZipFile(os.path.join(subs, "+formula.zip"), "w") as z:
            z.writestr(LAB2, right_cpp())
        return "+formula", {"0": MISSING0, "2": ("passed", [])}
    if kind == "sparse_1g":
        sparse_tar(os.path.join(subs, kind + ".tar"), work, 1 << 30, [])
        return kind, refused("is a sparse file")
    if kind == "sparse_4g":
        sparse_tar(os.path.join(subs, kind + ".tar"), work, 4 << 30, ["--format=pax", "--sparse-version=1.0"])
        return kind, refused("is a sparse file")
    if kind == "liar_tar":
        data = right_cpp()
        info = tarfile.TarInfo(LAB2)
        info.size = 1 << 30
        with open(os.path.join(subs, kind + ".tar"), "wb") as f:
            f.write(info.tobuf(format=tarfile.GNU_FORMAT) + data + b"\0" * (10240 - len(data)))
        return kind, refused("declares 1024 MB, more than the 16 MB a file may have")
    if kind == "liar_zip_big":
        lying_zip(os.path.join(subs, kind + ".zip"), 1 << 30)
        return kind, refused("declares 1024 MB, more than the 16 MB a file may have")
    if kind == "liar_zip_small":
        lying_zip(os.path.join(subs, kind + ".zip"), 8 << 20)
        return kind, refused("fewer than the 8388608 its header declares")
    if kind == "huge_file":
        folder(os.path.join(subs, kind), {LAB2: right_cpp()})
        os.truncate(os.path.join(subs, kind, LAB2), 1 << 30)
        return kind, {"0": MISSING0, "2": ("failed", [LAB2 + ": larger than the 16 MB a file may have"])}
    if kind == "file_for_folder":
        with zipfile.ZipFile(os.path.join(subs, kind + ".zip"), "w") as z:
            z.writestr("labs", "a file where the labs folder goes")
            z.writestr(LAB2, right_cpp())
        return kind, refused("Could not stat " + LAB2)
    if kind == "not_archive":
        with open(os.path.join(subs, "notes.rar"), "w") as f:
            f.write("not a zip or tar")
        return "notes.rar", refused("notes.rar: neither a folder nor a .zip/.tar archive")
    if kind.startswith("cpp_"):
        return kind, cpp_attack(out, subs, kind)
    raise SystemExit("hostile_submissions: unknown kind " + kind)


# What a hostile C++ exercise tries: lab 0's record in its own output folder (the check's TMPDIR is a
# folder beside it) forged as passed, and a file written beside the class.
ESCAPE = r"""
  if (const char* tmp = std::getenv("TMPDIR")) {
    if (std::FILE* f = std::fopen((std::string(tmp) + "/../lab_00.json").c_str(), "w"))
      std::fputs("{\"lab\": 0, \"status\": \"passed\", \"message\": \"forged\"}", f);
  }
  if (std::FILE* f = std::fopen("%s", "w")) std::fputs("escaped", f);
"""


def cpp_attack(out, subs, kind):
    escaped = os.path.join(os.path.abspath(out), "escaped_" + kind)
    escape = (ESCAPE % escaped).encode()
    head = b"#include <cstdio>\n#include <cstdlib>\n#include <string>\n#include <fcntl.h>\n#include <unistd.h>\n"
    right = right_cpp()
    if kind == "cpp_main":
        text, labs2 = head + right + b"\nint main() {" + escape + b"  return 0;\n}\n", ("compile_error", ["defines main"])
    elif kind == "cpp_dup":
        text = head + right + b"\nextern \"C\" int dup(int fd) {" + escape + b"  return fcntl(fd, F_DUPFD, 0);\n}\n"
        labs2 = ("compile_error", ["defines dup"])
    elif kind == "cpp_digraph_include":
        text, labs2 = b'%:include "core/light.cpp"\n' + right, ("compile_error", ["core/light.cpp: No such file"])
    elif kind == "cpp_escape_at_call":
        at = right.index(b"{", right.index(b"ortho_fit_exercise(")) + 1
        text, labs2 = head + right[:at] + escape + right[at:], ("crashed", ["SIGSYS"])
    else:
        raise SystemExit("hostile_submissions: unknown kind " + kind)
    folder(os.path.join(subs, kind), {LAB0: open(ROOT + "/" + LAB0, "rb").read(), LAB2: text})
    MUST_NOT_EXIST.append(escaped)
    return {"0": ("failed", ["criteria failed"]), "2": labs2}


MUST_NOT_EXIST = []


def main_make(out, kinds):
    os.makedirs(os.path.join(out, "submissions"), exist_ok=True)
    expected = {}
    for kind in kinds:
        student, labs = make(out, kind)
        expected[student] = {"kind": kind, "labs": {lab: {"status": s, "words": w} for lab, (s, w) in labs.items()}}
    with open(os.path.join(out, "expected.json"), "w") as f:
        json.dump({"students": expected, "folders": [os.path.abspath(out)], "must_not_exist": MUST_NOT_EXIST}, f, indent=1)


def read_utf8(path, problems):
    """The file's text; a problem when it is not valid UTF-8 or holds a raw ESC or CR."""
    data = open(path, "rb").read()
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        problems.append("%s: not valid UTF-8: %s" % (path, e))
        return data.decode("utf-8", "replace")
    for c in ("\x1b", "\r"):
        if c in text:
            problems.append("%s: a raw %r" % (path, c))
    return text


def check_json_reports(grades, expected, folders, problems):
    report = json.loads(read_utf8(os.path.join(grades, "results.json"), problems))
    if report.get("version") != 2 or "missing" not in report.get("statuses", []):
        problems.append("results.json: version %r, statuses %r" % (report.get("version"), report.get("statuses")))
    got = {s["name"]: s for s in report["students"]}
    for name, e in expected.items():
        labs = {str(r["lab"]): r for r in got.get(name, {}).get("labs", [])}
        for lab, want in e["labs"].items():
            r = labs.get(lab, {})
            message = r.get("message", "")
            where = "%s (%s) lab %s" % (name, e["kind"], lab)
            if r.get("status") != want["status"]:
                problems.append("%s: status %s, expected %s: %s" % (where, r.get("status"), want["status"], message[:300]))
            for w in want["words"]:
                if w not in message:
                    problems.append("%s: the message lacks %r: %s" % (where, w, message[:300]))
            for f in folders:
                if f in message or any(f in c.get("sentence", "") for c in r.get("criteria", [])):
                    problems.append("%s: the message names the grading machine's %s: %s" % (where, f, message[:300]))
        gs_path = os.path.join(grades, "gradescope", name, "results.json")
        if not os.path.isfile(gs_path):
            problems.append("%s: no Gradescope results" % name)
            continue
        gs = json.loads(read_utf8(gs_path, problems))
        for t in gs["tests"]:
            want = e["labs"].get(t["number"], {}).get("status")
            if t["score"] != (1 if want == "passed" else 0) or not t["output"].startswith(str(want) + ": "):
                problems.append("%s: Gradescope test %r for %s" % (name, t, want))
    for path in glob.glob(os.path.join(grades, "students", "*", "*.json")):
        json.loads(read_utf8(path, problems))
    return report


def check_csv_junit(grades, expected, problems):
    text = read_utf8(os.path.join(grades, "results.csv"), problems)
    rows = list(csv.reader(io.StringIO(text)))
    if len(rows) != text.count("\n") or any(len(r) != 12 for r in rows):
        problems.append("results.csv: %d rows in %d lines, field counts %s" % (
            len(rows), text.count("\n"), sorted({len(r) for r in rows})))
    statuses = {}
    for r in rows[1:]:
        statuses.setdefault((r[0], r[1]), set()).add(r[3])
    for name, e in expected.items():
        shown = "'" + name if name[:1] in "=+-@" else name
        for lab, want in e["labs"].items():
            if statuses.get((shown, lab)) != {want["status"]}:
                problems.append("results.csv %s lab %s: %s, expected %s" % (shown, lab, statuses.get((shown, lab)), want["status"]))
    root = ET.fromstring(read_utf8(os.path.join(grades, "junit.xml"), problems))
    all_status = [w["status"] for e in expected.values() for w in e["labs"].values()]
    want = {"tests": len(all_status), "skipped": all_status.count("missing"), "errors": all_status.count("grader_error"),
            "failures": sum(1 for s in all_status if s not in ("passed", "missing", "grader_error"))}
    got = {k: int(root.get(k, -1)) for k in want}
    if got != want or len(root.findall(".//skipped")) != want["skipped"]:
        problems.append("junit.xml: %s, expected %s" % (got, want))


def main_check(grades, expected_path):
    spec = json.load(open(expected_path))
    problems = []
    check_json_reports(grades, spec["students"], spec["folders"] + [os.path.abspath(grades)], problems)
    check_csv_junit(grades, spec["students"], problems)
    problems += ["written outside --out by a student's code: " + p for p in spec.get("must_not_exist", []) if os.path.exists(p)]
    for p in problems:
        print("PROBLEM:", p)
    print("%d hostile and normal submissions: %s" % (len(spec["students"]), "%d problems" % len(problems) if problems else "as expected"))
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "make":
        main_make(sys.argv[2], sys.argv[3:])
    elif len(sys.argv) == 4 and sys.argv[1] == "check":
        sys.exit(main_check(sys.argv[2], sys.argv[3]))
    else:
        sys.exit(__doc__)
