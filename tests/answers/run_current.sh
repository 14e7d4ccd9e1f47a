#!/usr/bin/env bash
# Grades every answer of the corpus (tests/answers/<NN_slug>/{wrong,right}/<answer>__<exercise file>)
# with today's checks and prints one row per answer: lab, expected, answer, today's verdict, and the
# criteria that failed. It measures the checks; it does not change them.
#
#   tests/answers/run_current.sh [--lab N[,M...]] [--answer NAME] [--set key=value]... [--no-lab2]
#                                [--markdown FILE] [--keep DIR] [--strict]
#   tests/answers/run_current.sh --lint    (only checks the corpus's layout and header lines; no build needed)
#
# GLSL labs: each answer is graded in a temporary data folder (a copy of shaders/ and labs/) where the
# answer's files replace the exercise files and the exercise files it does not give are the solution's
# (so an answer can be wrong in one part only), through SHADOWLAB_DATA_DIR=<tmp> shadowlab check.
# Lab 2 (C++ compiled into the binary): the answer is copied over labs/02_ortho_fit/exercise.cpp, the
# shadowlab target rebuilt, graded, and exercise.cpp restored (and rebuilt) after lab 2's last answer,
# or on exit, whatever happens.
# Checks run one at a time (the machine is shared).
# --set: passed to every check (held-out conditions: another light elevation, map size...).
# --keep: keep each check's JSON as DIR/<lab>_<expected>_<answer>.json (all metrics, not only the graded).
# --strict: exit 1 when a wrong answer passes or a right one fails (today it does: that is the point).
set -uo pipefail

root="$(cd "$(dirname "$0")/../.." && pwd)"
answers="$root/tests/answers"
build="${SHADOWLAB_BUILD_DIR:-$root/build}"
bin="$build/app/shadowlab"
only_labs="" only_answer="" skip_lab2=0 sets=() markdown="" keep="" strict=0 lint=0
while (($#)); do
  case "$1" in
    --lab) only_labs=",$2,"; shift 2 ;;
    --answer) only_answer="$2"; shift 2 ;;
    --set) sets+=(--set "$2"); shift 2 ;;
    --no-lab2) skip_lab2=1; shift ;;
    --markdown) markdown="$2"; shift 2 ;;
    --keep) keep="$2"; shift 2 ;;
    --strict) strict=1; shift ;;
    --lint) lint=1; shift ;;
    -h|--help) sed -n '2,19p' "$0"; exit 0 ;;
    *) echo "run_current.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
if ((lint)); then
  # Every file: <answer>__<one of the lab's exercise files>, first line "// wrong: ..." or "// right: ..." as
  # its folder says, second line "// expect: <category>"; at least 4 wrong and 1 right answer per lab,
  # 60 wrong and 20 right in all.
  python3 - "$answers" "$root" <<'PY'
import os, re, sys
answers, root = sys.argv[1], sys.argv[2]
problems, totals = [], {"wrong": 0, "right": 0}
labs = sorted(d for d in os.listdir(os.path.join(root, "labs")) if re.match(r"\d\d_", d))
for lab in labs:
    exercise = {f for f in os.listdir(os.path.join(root, "labs", lab)) if f.startswith("exercise")}
    for kind in ("wrong", "right"):
        folder = os.path.join(answers, lab, kind)
        names = sorted(os.listdir(folder)) if os.path.isdir(folder) else []
        prefixes = set()
        for name in names:
            path = f"{lab}/{kind}/{name}"
            answer, sep, file = name.partition("__")
            if not sep or file not in exercise or not re.fullmatch(r"[a-z0-9_]+", answer):
                problems.append(f"{path}: not <answer>__<exercise file of {lab}> ({', '.join(sorted(exercise))})"); continue
            lines = open(os.path.join(folder, name), errors="replace").read().splitlines()
            if len(lines) < 2 or not lines[0].startswith(f"// {kind}: ") or len(lines[0]) < len(f"// {kind}: ") + 10:
                problems.append(f"{path}:1: the first line must be '// {kind}: <what it models>'")
            if len(lines) < 2 or not re.fullmatch(r"// expect: [a-z][a-z-]+", lines[1]):
                problems.append(f"{path}:2: the second line must be '// expect: <category>'")
            prefixes.add(answer)
        totals[kind] += len(prefixes)
        least = 4 if kind == "wrong" else 1
        if len(prefixes) < least:
            problems.append(f"{lab}/{kind}: {len(prefixes)} answers, at least {least} wanted")
for kind, least in (("wrong", 60), ("right", 20)):
    if totals[kind] < least:
        problems.append(f"{totals[kind]} {kind} answers in all, at least {least} wanted")
print("\n".join(problems) if problems else f"corpus ok: {totals['wrong']} wrong and {totals['right']} right answers over {len(labs)} labs")
sys.exit(1 if problems else 0)
PY
  exit $?
fi
[[ -x "$bin" ]] || { echo "run_current.sh: $bin not found: build first (bash scripts/build)" >&2; exit 2; }

# Exercise file -> the solution file given in its place when an answer does not give it. The same
# pairs as each lab's exercise_files / solution_files (labs/NN_slug/lab.cpp).
declare -A solution_of=(
  [labs/00_basic_shadow_map/exercise.glsl]=labs/00_basic_shadow_map/solution.glsl
  [labs/01_bias_tuning/exercise.glsl]=labs/01_bias_tuning/solution.glsl
  [labs/03_vsm_setup/exercise_moments.glsl]=shaders/vsm/moments.glsl
  [labs/03_vsm_setup/exercise_chebyshev.glsl]=shaders/vsm/chebyshev.glsl
  [labs/04_light_bleeding/exercise.glsl]=shaders/vsm/visibility.glsl
  [labs/05_moment_blur/exercise.glsl]=shaders/vsm/gaussian_blur.glsl
  [labs/06_pcf/exercise.glsl]=shaders/shadow/pcf.glsl
  [labs/07_spot_light/exercise.glsl]=shaders/shadow/spot.glsl
  [labs/08_point_light/exercise.glsl]=shaders/shadow/cube.glsl
  [labs/09_shadow_volumes/exercise.glsl]=shaders/volume/volume.glsl
)

tmp="$(mktemp -d)"
lab2_src="$root/labs/02_ortho_fit/exercise.cpp"
lab2_saved="$tmp/exercise.cpp.orig"
lab2_touched=0
rebuild_shadowlab() {
  local launcher=()
  if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
  CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1 cmake --build "$build" --target shadowlab -j 2 >"$tmp/build.log" 2>&1
}
restore_lab2() {  # puts the student's exercise.cpp back and rebuilds the binary with it
  ((lab2_touched)) || return 0
  cp "$lab2_saved" "$lab2_src"
  lab2_touched=0
  rebuild_shadowlab || echo "run_current.sh: rebuilding with the restored exercise.cpp failed: see $tmp/build.log" >&2
}
cleanup() {
  restore_lab2
  rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# One verdict line from a check's JSON and exit code: "PASS", "FAIL<TAB>criteria" or "ERROR<TAB>message".
verdict() {  # verdict <json> <rc> <log>
  python3 - "$1" "$2" "$3" <<'PY'
import json, math, sys
path, rc, log = sys.argv[1], int(sys.argv[2]), sys.argv[3]
try:
    lab = json.load(open(path))["labs"][0]
except Exception:
    msg = open(log, errors="replace").read().strip().splitlines()
    print("ERROR\t" + (msg[0] if msg else f"no JSON, exit {rc}")[:160]); sys.exit()
status = lab.get("status")  # passed / failed / compile_error / grader_error (older binaries: none)
if lab.get("error") or status in ("compile_error", "grader_error"):
    msg = (lab.get("error") or status).strip().splitlines()
    print("ERROR\t" + (status + ": " if status and status != "failed" else "") + (msg[0] if msg else "")[:160]); sys.exit()
failed = []
if isinstance(lab.get("criteria"), list):  # one entry per graded criterion, with its own verdict
    for c in lab["criteria"]:
        if not c.get("passed", False):
            v = c.get("value")
            failed.append(f"{c.get('metric', '?')}=" + (f"{v:.4g}" if isinstance(v, (int, float)) else "?"))
else:
    for name, t in lab.get("thresholds", {}).items():
        v = lab.get("metrics", {}).get(name)
        if v is None or (isinstance(v, float) and math.isnan(v)):
            failed.append(f"{name}=?"); continue
        if ("max" in t and v > t["max"]) or ("min" in t and v < t["min"]):
            failed.append(f"{name}={v:.4g}")
if lab.get("passed") and rc == 0:
    print("PASS\t")
else:
    print("FAIL\t" + (", ".join(failed) if failed else f"exit {rc}"))
PY
}

rows="$tmp/rows.tsv"
: >"$rows"
grade() {  # grade <lab number> <kind> <answer> <file>...
  local n="$1" kind="$2" answer="$3"; shift 3
  local json="$tmp/check.json" log="$tmp/check.log" rc line
  rm -f "$json"
  if [[ "$n" == 2 ]]; then
    if ((!lab2_touched)); then cp "$lab2_src" "$lab2_saved"; lab2_touched=1; fi
    cp "$1" "$lab2_src"
    if ! rebuild_shadowlab; then
      line="ERROR	build failed: $(grep -m1 -E 'error' "$tmp/build.log" | cut -c1-140)"
      printf '%s\t%s\t%s\t%s\n' "$n" "$kind" "$answer" "$line" >>"$rows"; return
    fi
    "$bin" check --lab 2 --impl exercise --json "$json" "${sets[@]}" >"$log" 2>&1; rc=$?
  else
    local data="$tmp/data"
    rm -rf "$data"; mkdir -p "$data"
    cp -r "$root/shaders" "$root/labs" "$data/"
    local slug_dir exercise given f
    slug_dir="$(ls -d "$root"/labs/$(printf '%02d' "$n")_* | head -1)"
    for exercise in "${!solution_of[@]}"; do
      [[ "$exercise" == "labs/$(basename "$slug_dir")/"* ]] || continue
      given=""
      for f in "$@"; do [[ "$(basename "$f")" == "${answer}__$(basename "$exercise")" ]] && given="$f"; done
      if [[ -n "$given" ]]; then cp "$given" "$data/$exercise"; else cp "$root/${solution_of[$exercise]}" "$data/$exercise"; fi
    done
    SHADOWLAB_DATA_DIR="$data" "$bin" check --lab "$n" --impl exercise --json "$json" "${sets[@]}" >"$log" 2>&1; rc=$?
  fi
  if [[ -n "$keep" && -f "$json" ]]; then mkdir -p "$keep" && cp "$json" "$keep/${n}_${kind}_${answer}.json"; fi
  line="$(verdict "$json" "$rc" "$log")"
  printf '%s\t%s\t%s\t%s\n' "$n" "$kind" "$answer" "$line" >>"$rows"
  printf '%-3s %-6s %-44s %s\n' "$n" "$kind" "$answer" "${line//	/  }"
}

for lab_dir in "$answers"/[0-9][0-9]_*/; do
  slug="$(basename "$lab_dir")"; n=$((10#${slug%%_*}))
  [[ -z "$only_labs" || "$only_labs" == *",$n,"* ]] || continue
  ((n == 2 && skip_lab2)) && continue
  for kind in wrong right; do
    [[ -d "$lab_dir/$kind" ]] || continue
    # Answers: the distinct <answer> prefixes; each may give several exercise files.
    for answer in $(ls "$lab_dir/$kind" | sed -n 's/__.*//p' | sort -u); do
      [[ -z "$only_answer" || "$answer" == "$only_answer" ]] || continue
      grade "$n" "$kind" "$answer" "$lab_dir/$kind/${answer}__"*
    done
  done
  ((n == 2)) && restore_lab2
done

# Summary: per lab, right accepted and wrong rejected, and the answers today's checks grade wrongly.
python3 - "$rows" "$markdown" "$strict" <<'PY'
import signal, sys
signal.signal(signal.SIGPIPE, signal.SIG_DFL)
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1]) if l.strip()]
markdown, strict = sys.argv[2], sys.argv[3] == "1"
labs = sorted({int(r[0]) for r in rows})
out = ["| lab | right accepted | wrong rejected |", "|---|---|---|"]
tot = [0, 0, 0, 0]
for n in labs:
    rr = [r for r in rows if int(r[0]) == n and r[1] == "right"]
    ww = [r for r in rows if int(r[0]) == n and r[1] == "wrong"]
    ra = sum(r[3] == "PASS" for r in rr); wr = sum(r[3] != "PASS" for r in ww)
    tot = [tot[0] + ra, tot[1] + len(rr), tot[2] + wr, tot[3] + len(ww)]
    out.append(f"| {n} | {ra} / {len(rr)} | {wr} / {len(ww)} |")
out.append(f"| all | {tot[0]} / {tot[1]} | {tot[2]} / {tot[3]} |")
bad = [r for r in rows if (r[1] == "wrong") == (r[3] == "PASS")]
out += ["", "Graded wrongly today (wrong answers that PASS, right answers that do not):", ""]
out += [f"- lab {r[0]} {r[1]} `{r[2]}`: {r[3]} {r[4] if len(r) > 4 else ''}".rstrip() for r in bad] or ["- none"]
text = "\n".join(out)
print("\n" + text)
if markdown:
    open(markdown, "w").write(text + "\n")
sys.exit(1 if strict and bad else 0)
PY
