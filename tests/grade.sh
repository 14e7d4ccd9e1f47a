#!/usr/bin/env bash
# End-to-end tests of class grading (`shadowlab grade`, `check --submission`), one case per CTest
# entry: tests/grade.sh BIN CASE
set -uo pipefail
bin="$1"; case_name="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
src="$(cd "$(dirname "$0")/.." && pwd)"
export SHADOWLAB_SETTINGS="$tmp/settings.json"
fail() { echo "FAIL: $*"; exit 1; }
expect_exit() {  # expect_exit CODE "stderr part" command...
  local want="$1" part="$2"; shift 2
  "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local got=$?
  [ "$got" -eq "$want" ] || fail "exit $got (expected $want) from: $* -- $(tail -3 "$tmp/stderr")"
  [ -z "$part" ] || grep -qF -- "$part" "$tmp/stderr" || fail "stderr lacks '$part': $(cat "$tmp/stderr")"
}
status_of() {  # status_of OUT STUDENT LAB
  python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['status'])" "$1/students/$2/lab_$(printf %02d "$3").json"
}
message_of() {
  python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['message'])" "$1/students/$2/lab_$(printf %02d "$3").json"
}
message_has() {  # message_has OUT STUDENT LAB WORDS: the lab's message contains WORDS
  local m; m="$(message_of "$1" "$2" "$3")"
  [[ "$m" == *"$4"* ]]
}
# lab2 NAME KIND: a submission folder $tmp/subs/NAME whose labs/02_ortho_fit/exercise.cpp is a right answer
# from the corpus, made broken in the given way (tests/make_submissions.py's broken(); "right": as is).
lab2() {
  local dir="$tmp/subs/$1/labs/02_ortho_fit"
  mkdir -p "$dir"
  python3 - "$src" "$2" "$dir/exercise.cpp" <<'PY'
import glob, sys
src, kind, out = sys.argv[1:4]
sys.path.insert(0, src + "/tests")
from make_submissions import broken
text = open(sorted(glob.glob(src + "/tests/answers/02_ortho_fit/right/*__exercise.cpp"))[0]).read()
if kind != "right":
    text, line = broken(text, kind, True, "ortho_fit_exercise")
    if line:
        print(line)
open(out, "w").write(text)
PY
}

stock() { mkdir -p "$tmp/subs/stock" && cp -r "$src/labs" "$tmp/subs/stock/"; }  # the exercises as handed out

case "$case_name" in
  grade_usage)  # usage errors exit 2 with one line naming the problem, before anything is graded
    mkdir -p "$tmp/a/alice/labs" "$tmp/b/alice/labs"
    expect_exit 2 "no submission given" "$bin" grade --out "$tmp/out"
    expect_exit 2 "--out" "$bin" grade "$tmp/a/alice"
    expect_exit 2 "nope: no such submission" "$bin" grade "$tmp/nope" --out "$tmp/out"
    expect_exit 2 "valid: all," "$bin" grade "$tmp/a/alice" --out "$tmp/out" --lab 42
    expect_exit 2 "two submissions would be reported as 'alice'" "$bin" grade "$tmp/a/alice" "$tmp/b/alice" --out "$tmp/out"
    expect_exit 2 "--jobs" "$bin" grade "$tmp/a/alice" --out "$tmp/out" --jobs 0
    expect_exit 2 "--timeout" "$bin" grade "$tmp/a/alice" --out "$tmp/out" --timeout 0
    expect_exit 2 "--cpu-time" "$bin" grade "$tmp/a/alice" --out "$tmp/out" --cpu-time -1
    expect_exit 2 "--memory" "$bin" grade "$tmp/a/alice" --out "$tmp/out" --memory 10
    expect_exit 2 "--images" "$bin" grade "$tmp/a/alice" --out "$tmp/out" --images some
    touch "$tmp/file"
    expect_exit 2 "cannot create the output folder" "$bin" grade "$tmp/a/alice" --out "$tmp/file/out"
    [ ! -e "$tmp/out/students" ] || fail "graded before refusing"
    ;;
  check_submission_cpp)  # lab 2 per student: the student's exercise.cpp is built on its own and called
    lab2 right right
    "$bin" check --lab 2 --impl exercise --submission "$tmp/subs/right" --json "$tmp/right.json" >"$tmp/out" 2>&1 || fail "a right answer failed: $(cat "$tmp/out")"
    # Each way of getting it wrong, its status in the JSON and the words that must be in the error.
    line=$(lab2 syntax syntax_error)
    lab2 semantic semantic_error >/dev/null
    lab2 crash crash
    lab2 forbidden forbidden_call
    lab2 loop endless_loop
    mkdir -p "$tmp/subs/solution/labs/02_ortho_fit" "$tmp/subs/include/labs/02_ortho_fit" "$tmp/subs/ctor/labs/02_ortho_fit"
    printf '#include "labs/02_ortho_fit/ortho_fit.h"\nnamespace shadowlab {\nLightView ortho_fit_exercise(const Bounds& b, const glm::vec3& d) { return fit_light_ortho(b, d); }\n}\n' \
      >"$tmp/subs/solution/labs/02_ortho_fit/exercise.cpp"
    sed '1i #include "renderer/light.cpp"' "$tmp/subs/right/labs/02_ortho_fit/exercise.cpp" >"$tmp/subs/include/labs/02_ortho_fit/exercise.cpp"
    sed '1i #include <vector>\nstatic std::vector<int> table(64);' "$tmp/subs/right/labs/02_ortho_fit/exercise.cpp" >"$tmp/subs/ctor/labs/02_ortho_fit/exercise.cpp"
    while IFS='|' read -r name status words; do
      "$bin" check --lab 2 --impl exercise --submission "$tmp/subs/$name" --json "$tmp/$name.json" >"$tmp/out" 2>&1
      code=$?
      [ "$code" -eq 1 ] || fail "$name: exit $code, expected 1: $(cat "$tmp/out")"
      python3 - "$tmp/$name.json" "$status" "$words" <<'PY' || fail "$name: $(cat "$tmp/out")"
import json, sys
lab = json.load(open(sys.argv[1]))["labs"][0]
assert lab.get("status") == sys.argv[2], (lab.get("status"), sys.argv[2], lab.get("error"))
assert sys.argv[3] in lab.get("error", ""), (sys.argv[3], lab.get("error"))
PY
    done <<EOF
syntax|compile_error|labs/02_ortho_fit/exercise.cpp:$line:
semantic|compile_error|undeclared_name
crash|crashed|SIGSEGV
forbidden|crashed|SIGSYS
loop|timed_out|the exercise did not return within
solution|compile_error|calls shadowlab::fit_light_ortho
include|compile_error|may include only
ctor|compile_error|runs before the exercise is called
EOF
    ;;
  grade_archives)  # zip and tar submissions, wrapped or not; entries that escape, links and bombs refused
    lab2 right right
    (cd "$tmp/subs/right" && zip -qr "$tmp/plain.zip" labs) || fail "zip"
    tar czf "$tmp/wrapped.tar.gz" -C "$tmp/subs" right || fail "tar"
    python3 - "$tmp" <<'PY'
import io, sys, tarfile, zipfile
tmp = sys.argv[1]
with zipfile.ZipFile(tmp + "/escape.zip", "w") as z:
    z.writestr("labs/02_ortho_fit/exercise.cpp", "x")
    z.writestr("../../escaped.txt", "outside")
with zipfile.ZipFile(tmp + "/absolute.zip", "w") as z:
    z.writestr("/tmp/absolute-entry.txt", "outside")
with tarfile.open(tmp + "/link.tar", "w") as t:
    info = tarfile.TarInfo("labs/02_ortho_fit/exercise.cpp"); info.type = tarfile.SYMTYPE; info.linkname = "/etc/passwd"
    t.addfile(info)
with zipfile.ZipFile(tmp + "/bomb.zip", "w", zipfile.ZIP_DEFLATED) as z:
    z.writestr("labs/02_ortho_fit/exercise.cpp", b"//" + b" " * (40 << 20))
open(tmp + "/junk.zip", "w").write("not an archive")
PY
    mkdir "$tmp/t"  # the grader's temporary folders (unpacked archives, lab 2's builds) go here, and must go
    TMPDIR="$tmp/t" "$bin" grade "$tmp"/{plain.zip,wrapped.tar.gz,escape.zip,absolute.zip,link.tar,bomb.zip,junk.zip} --lab 2 --out "$tmp/out" >"$tmp/log" 2>&1
    [ $? -eq 1 ] || fail "exit $? (expected 1): $(cat "$tmp/log")"
    [ "$(status_of "$tmp/out" plain 2)" = passed ] || fail "plain.zip: $(message_of "$tmp/out" plain 2)"
    [ "$(status_of "$tmp/out" wrapped 2)" = passed ] || fail "wrapped.tar.gz: $(message_of "$tmp/out" wrapped 2)"
    for refused in "escape|leaves the submission's folder" "absolute|absolute path" "link|is a link" "bomb|more than the 16 MB a file may have" "junk|cannot open as zip or tar"; do
      name="${refused%%|*}" words="${refused#*|}"
      [ "$(status_of "$tmp/out" "$name" 2)" = failed ] || fail "$name: $(status_of "$tmp/out" "$name" 2)"
      message_has "$tmp/out" "$name" 2 "submission refused: " || fail "$name: $(message_of "$tmp/out" "$name" 2)"
      message_has "$tmp/out" "$name" 2 "$words" || fail "$name: $(message_of "$tmp/out" "$name" 2)"
    done
    [ ! -e "$tmp/escaped.txt" ] && [ ! -e "$(dirname "$tmp")/escaped.txt" ] && [ ! -e /tmp/absolute-entry.txt ] || fail "an entry was written outside"
    [ -z "$(ls -A "$tmp/t")" ] || fail "temporary folders left behind: $(ls -A "$tmp/t")"
    true
    ;;
  grade_killed_cleanup)  # a run killed mid-lab leaves nothing in the temporary folder; the next run cleans up after it
    lab2 endless endless_loop
    (cd "$tmp/subs/endless" && zip -qr "$tmp/endless.zip" labs) || fail "zip"
    mkdir "$tmp/t"
    TMPDIR="$tmp/t" "$bin" grade "$tmp/endless.zip" --lab 2 --out "$tmp/out" >"$tmp/log" 2>&1 &
    pid=$!
    # Killed while lab 2's program runs (its answer never comes): the archive is unpacked, the exercise built.
    for _ in $(seq 600); do
      pgrep -f -- "--json $tmp/out" >/dev/null && [ -d "$tmp/out/students/endless/lab_02.tmp" ] && break
      sleep 0.1
    done
    sleep 2
    kill -9 "$pid"; wait "$pid" 2>/dev/null
    sleep 1
    pgrep -f -- "--json $tmp/out" >/dev/null && fail "a check process outlived the killed grade"
    [ -z "$(ls -A "$tmp/t")" ] || fail "temporary folders left in TMPDIR by the killed run: $(ls -A "$tmp/t")"
    [ -d "$tmp/out/students/endless/unpacked" ] || fail "the killed run's unpacked archive is not where the next run looks"
    TMPDIR="$tmp/t" "$bin" grade "$tmp/endless.zip" --lab 2 --out "$tmp/out" >"$tmp/log" 2>&1
    [ $? -eq 1 ] || fail "rerun: exit $? (expected 1): $(cat "$tmp/log")"
    [ "$(status_of "$tmp/out" endless 2)" = timed_out ] || fail "rerun: $(status_of "$tmp/out" endless 2): $(message_of "$tmp/out" endless 2)"
    left=$(cd "$tmp/out/students/endless" && ls -A | grep -E '^(unpacked|lab_02\.tmp)$')
    [ -z "$left" ] || fail "the rerun left $left behind"
    [ -z "$(ls -A "$tmp/t")" ] || fail "temporary folders left in TMPDIR: $(ls -A "$tmp/t")"
    ;;
  grade_links)  # a folder submission whose exercise is a link, or lies in a linked folder: refused, nothing read
    lab2 right right
    mkdir -p "$tmp/subs/filelink/labs/02_ortho_fit" "$tmp/subs/dirlink/labs"
    ln -s "$tmp/subs/right/labs/02_ortho_fit/exercise.cpp" "$tmp/subs/filelink/labs/02_ortho_fit/exercise.cpp"
    ln -s "$tmp/subs/right/labs/02_ortho_fit" "$tmp/subs/dirlink/labs/02_ortho_fit"
    expect_exit 1 "" "$bin" grade "$tmp/subs/filelink" "$tmp/subs/dirlink" --lab 2 --out "$tmp/out"
    [ "$(status_of "$tmp/out" filelink 2)" = failed ] && message_has "$tmp/out" filelink 2 "a link; submit the file itself" \
      || fail "file link: $(message_of "$tmp/out" filelink 2)"
    [ "$(status_of "$tmp/out" dirlink 2)" = failed ] && message_has "$tmp/out" dirlink 2 "leads out of the submission" \
      || fail "folder link: $(message_of "$tmp/out" dirlink 2)"
    [ ! -e "$tmp/out/students/filelink/lab_02.log" ] || fail "a linked file was graded"
    ;;
  grade_exit_codes)  # 0 all passed, 1 some did not, 3 the grader broke (its own shader missing)
    lab2 right right
    expect_exit 0 "" "$bin" grade "$tmp/subs/right" --lab 2 --out "$tmp/all"
    stock
    expect_exit 1 "" "$bin" grade "$tmp/subs/right" "$tmp/subs/stock" --lab 2 --out "$tmp/some"
    mkdir "$tmp/data" && cp -r "$src/shaders" "$src/labs" "$src/assets" "$tmp/data/" && rm "$tmp/data/shaders/lit.frag"
    SHADOWLAB_DATA_DIR="$tmp/data" expect_exit 3 "" "$bin" grade "$tmp/subs/right" --lab 2 --out "$tmp/broken"
    [ "$(status_of "$tmp/broken" right 2)" = grader_error ] || fail "missing grader shader: $(status_of "$tmp/broken" right 2)"
    message_has "$tmp/broken" right 2 "lit.frag" || fail "the grader error does not name the file: $(message_of "$tmp/broken" right 2)"
    ;;
  grade_killed_resume)  # a run killed from outside keeps every lab it finished; the merge names the rest; a rerun continues
    stock
    "$bin" grade "$tmp/subs/stock" --lab 0,1,3,4,5,6 --out "$tmp/out" >"$tmp/log" 2>&1 &
    pid=$!
    for _ in $(seq 600); do
      [ -s "$tmp/out/students/stock/lab_01.json" ] && break
      sleep 0.1
    done
    [ -s "$tmp/out/students/stock/lab_01.json" ] || fail "no lab recorded: $(cat "$tmp/log")"
    kill -9 "$pid"; wait "$pid" 2>/dev/null
    sleep 1
    pgrep -f -- "--json $tmp/out" >/dev/null && fail "a check process outlived the killed grade"
    recorded=$(ls "$tmp/out/students/stock/" | grep -c '^lab_0[0-9].json$')
    [ "$recorded" -ge 2 ] && [ "$recorded" -lt 6 ] || fail "$recorded labs recorded"
    expect_exit 3 "" "$bin" grade --merge "$tmp/subs/stock" --lab 0,1,3,4,5,6 --out "$tmp/out"
    python3 - "$tmp/out/results.json" "$recorded" <<'PY' || fail "merge after the kill"
import json, sys
labs = json.load(open(sys.argv[1]))["students"][0]["labs"]
assert len(labs) == 6, labs
missing = [l for l in labs if l["status"] == "grader_error"]
assert len(missing) == 6 - int(sys.argv[2]) and all("no result" in l["message"] for l in missing), missing
PY
    expect_exit 1 "" "$bin" grade "$tmp/subs/stock" --lab 0,1,3,4,5,6 --out "$tmp/out"
    [ "$(grep -c "recorded before" "$tmp/stdout")" -eq "$recorded" ] || fail "the rerun graded again what was recorded: $(cat "$tmp/stdout")"
    # Through GNU parallel: the driver killed, its parallel, the per-submission tasks and their checks go too.
    mkdir -p "$tmp/subs/other" && cp -r "$src/labs" "$tmp/subs/other/"
    "$bin" grade "$tmp/subs/stock" "$tmp/subs/other" --jobs 2 --again --out "$tmp/par" >"$tmp/log" 2>&1 &
    pid=$!
    for _ in $(seq 600); do
      [ -n "$(ls "$tmp"/par/students/*/lab_00.json 2>/dev/null)" ] && break
      sleep 0.1
    done
    pgrep -f -- "--submission $tmp/subs/" >/dev/null || fail "no check running under parallel: $(cat "$tmp/log")"
    kill -9 "$pid"; wait "$pid" 2>/dev/null
    sleep 3
    pgrep -f -- "$tmp/par" >/dev/null && fail "processes of the killed parallel run remain: $(pgrep -af -- "$tmp/par")"
    true
    ;;
  grade_limits)  # an endless loop stopped by the CPU-time limit, a slow one by the wall clock; memory for lab 2
    mkdir -p "$tmp/subs/loop/labs/00_basic_shadow_map"
    python3 - "$src" "$tmp/subs/loop/labs/00_basic_shadow_map/exercise.glsl" <<'PY'
import sys
sys.path.insert(0, sys.argv[1] + "/tests")
from make_submissions import broken
text = open(sys.argv[1] + "/labs/00_basic_shadow_map/solution.glsl").read()
open(sys.argv[2], "w").write(broken(text, "endless_loop", False, "shadow_visibility")[0])
PY
    start=$(date +%s)
    expect_exit 1 "" "$bin" grade "$tmp/subs/loop" --lab 0 --cpu-time 4 --timeout 200 --out "$tmp/cpu"
    [ "$(status_of "$tmp/cpu" loop 0)" = timed_out ] && message_has "$tmp/cpu" loop 0 "4 s of CPU time" \
      || fail "CPU limit: $(status_of "$tmp/cpu" loop 0): $(message_of "$tmp/cpu" loop 0)"
    expect_exit 1 "" "$bin" grade "$tmp/subs/loop" --lab 0 --cpu-time 200 --timeout 4 --out "$tmp/wall"
    [ "$(status_of "$tmp/wall" loop 0)" = timed_out ] && message_has "$tmp/wall" loop 0 "4 s (wall clock)" \
      || fail "wall limit: $(status_of "$tmp/wall" loop 0): $(message_of "$tmp/wall" loop 0)"
    [ $(($(date +%s) - start)) -lt 120 ] || fail "the limits took $(($(date +%s) - start)) s to stop two 4 s labs"
    # Lab 2's program may take 1 GB: a student's exercise that allocates 4 GB is stopped there.
    lab2 hog right
    python3 - "$src" "$tmp/subs/hog/labs/02_ortho_fit/exercise.cpp" <<'PY'
import sys
sys.path.insert(0, sys.argv[1] + "/tests")
from make_submissions import function_start
lines = open(sys.argv[2]).read().split("\n")
start, _ = function_start(lines, "ortho_fit_exercise")
lines.insert(start, "  { char* p = new char[4ull << 30]; for (unsigned long long i = 0; i < (4ull << 30); i += 4096) p[i] = 1; }")
open(sys.argv[2], "w").write("\n".join(lines))
PY
    expect_exit 1 "" "$bin" grade "$tmp/subs/hog" --lab 2 --out "$tmp/memory"
    [ "$(status_of "$tmp/memory" hog 2)" = crashed ] && message_has "$tmp/memory" hog 2 "SIGABRT" \
      || fail "memory: $(status_of "$tmp/memory" hog 2): $(message_of "$tmp/memory" hog 2)"
    ;;
  grade_class_small)  # the class in small: 12 generated submissions, every status, GNU parallel, all reports
    # (SHADOWLAB_CLASS_SIZE=300 for the whole class; SHADOWLAB_CLASS_JOBS for other than 2 jobs)
    count=${SHADOWLAB_CLASS_SIZE:-12} jobs=${SHADOWLAB_CLASS_JOBS:-2}
    python3 "$src/tests/make_submissions.py" --bin "$bin" --out "$tmp/class" --count "$count" --seed 15 >"$tmp/gen" || fail "generator: $(cat "$tmp/gen")"
    start=$(date +%s)
    "$bin" grade "$tmp"/class/submissions/* --out "$tmp/grades" --jobs "$jobs" >"$tmp/log" 2>&1
    code=$?
    echo "$count submissions graded in $(($(date +%s) - start)) s with $jobs jobs, exit $code"
    [ "$code" -eq 1 ] || fail "exit $code (some labs fail by design: expected 1): $(tail -5 "$tmp/log")"
    python3 "$src/tests/check_grades.py" "$tmp/grades" "$tmp/class/expected.json" || fail "reports differ from the expected statuses"
    ;;
  *) fail "unknown case $case_name" ;;
esac
echo "ok: $case_name"
