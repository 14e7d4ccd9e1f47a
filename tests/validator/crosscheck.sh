#!/usr/bin/env bash
# The loader's verdicts against the Khronos glTF validator's, on every file of the invalid suites
# (assets/invalid) and every hostile model of issue 18 (but the FIFOs, which the validator would wait on,
# and files over 40 MB):
#
#     bash tests/validator/crosscheck.sh GLTF_CHECK HOSTILE_CASES
#
# A file the validator finds an error in must be refused by the loader. A file it finds valid may still
# be refused, for a reason the validator does not judge: nothing to draw (no triangle meshes in the
# scene), a budget (LoadLimits::...), a feature the lab does not support. Every such file is listed
# with the loader's reason. The validator (npm gltf-validator) is installed by scripts/setup.
set -uo pipefail
check="$1"; hostile="$2"
here="$(cd "$(dirname "$0")" && pwd)"
src="$(cd "$here/../.." && pwd)"
[ -f "$here/node_modules/gltf-validator/package.json" ] || {
  echo "FAIL: the glTF validator is not installed (bash scripts/setup runs npm ci in tests/validator)"; exit 1; }
command -v node >/dev/null || { echo "FAIL: node is missing (scripts/setup installs nodejs)"; exit 1; }
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
"$hostile" "$tmp/cases" >"$tmp/manifest" || { echo "FAIL: hostile_cases"; exit 1; }
{
  find "$src/assets/invalid" -type f \( -name '*.gltf' -o -name '*.glb' \) | sort
  find "$tmp/cases" -type f \( -name '*.gltf' -o -name '*.glb' \) -size -40M | sort
} >"$tmp/files"
mapfile -t files <"$tmp/files"
# The validator itself dies of a stack overflow on deeply nested JSON (the hostile deep_* models): the
# files are validated in order, so the first one without a line is the one it died on; it is marked
# VALIDATOR_CRASHED (an error verdict) and the rest are validated again.
: >"$tmp/validator.tsv"
pending=("${files[@]}")
while [ ${#pending[@]} -gt 0 ]; do
  node "$here/crosscheck.mjs" "${pending[@]}" >>"$tmp/validator.tsv" 2>/dev/null
  declare -A seen=()
  while IFS=$'\t' read -r f _; do seen["$f"]=1; done <"$tmp/validator.tsv"
  next=(); crashed=""
  for f in "${pending[@]}"; do
    [ -n "${seen[$f]:-}" ] && continue
    if [ -z "$crashed" ]; then crashed="$f"; printf '%s\t1\tVALIDATOR_CRASHED\n' "$f" >>"$tmp/validator.tsv"
    else next+=("$f"); fi
  done
  unset seen
  pending=("${next[@]}")
done
"$check" "${files[@]}" >"$tmp/loader.tsv" || { echo "FAIL: gltf_check did not run"; exit 1; }
python3 - "$tmp/validator.tsv" "$tmp/loader.tsv" "$src/" "$tmp/cases/" <<'PY'
import sys
validator = {}
for line in open(sys.argv[1], encoding="utf-8", errors="replace"):
    f, n, codes = line.rstrip("\n").split("\t", 2)
    validator[f] = (int(n), codes)
loader = {}
for line in open(sys.argv[2], encoding="utf-8", errors="replace"):
    f, verdict, text = line.rstrip("\n").split("\t", 2)
    loader[f] = (verdict, text)
# What the validator does not judge, and so may make the loader refuse a file it finds valid.
# tinygltf 2.7 refuses an index accessor without a bufferView ("accessor[0] invalid bufferView"): valid
# glTF (all indices zero), useless geometry, not supported. "overflows": node transforms whose product
# leaves single precision, which the renderer uses.
not_judged = ("no triangle meshes to draw", "LoadLimits::", "is not supported", "are not supported",
              "accessor[0] invalid bufferView", "world transform overflows")
short = lambda f: f.replace(sys.argv[3], "").replace(sys.argv[4], "hostile/")
bad, both, neither, stricter = [], 0, 0, []
for f in sorted(validator):
    n, codes = validator[f]
    verdict, text = loader[f]
    reason = text[len(f) + 2:] if text.startswith(f) else text
    if n > 0 and verdict == "loaded":
        bad.append(f"{short(f)}: the validator reports {codes}, the loader loaded it")
    elif n > 0:
        both += 1
        print(f"both refuse  {short(f):62} {codes[:60]:60} | {reason[:90]}")
    elif verdict == "loaded":
        neither += 1
        print(f"both accept  {short(f)}")
    else:
        stricter.append(f)
        ok = any(r in reason for r in not_judged)
        print(f"loader only  {short(f):62} {'(valid)':60} | {reason[:90]}")
        if not ok:
            bad.append(f"{short(f)}: valid for the validator, refused for a reason it judges: {reason[:200]}")
print(f"validator cross-check: {len(validator)} files; both refuse {both}, both accept {neither}, "
      f"only the loader refuses {len(stricter)} (nothing to draw, a budget or an unsupported feature)")
for b in bad:
    print("FAIL:", b)
print(f"{len(validator) - len(bad)} passed, {len(bad)} failed")
sys.exit(1 if bad else 0)
PY
