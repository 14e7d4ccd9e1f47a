#!/usr/bin/env bash
# "A shadow test is registered like a pass", proven as tests/one_folder.sh proves "a lab is a folder": a
# copy of the source tree gets a throwaway shadow test, its own two files and nothing else
# (renderer/shadow_tests/throwaway.cpp: its name, file, parameter and bind; shaders/shadow/throwaway.glsl:
# the hard test with shadowed points at throwaway.level instead of 0), is configured and built, and the
# built shadowlab renders lab 1 with it (render --shadow-test throwaway --set throwaway.level=0.25) and
# with the hard test. Asserted:
#   (a) the copy differs from the tree in exactly those two new files (no registration edited anywhere);
#   (b) the throwaway's visibility (visibility.npy) is the hard test's wherever the hard test lit the
#       point, and 0.25 (its parameter, so its bind ran) instead of 0 at the points it shadowed; every
#       other pixel equal; an unknown test's error names the throwaway. At 320 x 180 here: 3470 pixels
#       shadowed, 8464 lit; at least 1000 of each are asked for, so that the two tests are told apart
#       (an unset uniform reads 0: without the bind no pixel is at 0.25 and the test fails).
# Usage: tests/one_technique.sh [WORK_DIR]   (default: a temporary folder, removed afterwards)
# The copy is built by tests/tree_copy.sh: ccache serves every object but the new test's and the
# generated list; at run time SHADOWLAB_DATA_DIR points at the copy (where the new shader is).
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
# shellcheck source=tests/tree_copy.sh
source "$src/tests/tree_copy.sh"
work_folder "$@"
copy="$work/src"
fail() { echo "one_technique: $*" >&2; exit 1; }
copy_tree "$src" "$copy"
fingerprint() { (cd "$copy" && find . -path ./build -prune -o -type f -print0 | sort -z | xargs -0 sha1sum); }
fingerprint >"$work/before.txt"

cat >"$copy/renderer/shadow_tests/throwaway.cpp" <<'CPP'
// A throwaway shadow test (tests/one_technique.sh): the hard test, shadowed points at throwaway.level.
#include <vector>

#include "core/params.h"
#include "renderer/shader.h"
#include "renderer/shadow_test.h"

namespace shadowlab {

namespace {
const FloatParam throwaway_level{{"throwaway.level", "Throwaway shadow level", ParamKind::Float, 0.5, 0.0, 1.0,
                                  "Visibility of a shadowed point."}};
}  // namespace

ShadowTest SHADOWLAB_SHADOW_TEST_MAKER() {
  return {"throwaway", "shaders/shadow/throwaway.glsl", specs_of(throwaway_level),
          [](GLuint program) -> ShadowTestBind {
            return [level = Uniform(program, "u_throwaway_level")](const ShadowTestFrame& f) {
              level.set(f.params.get(throwaway_level));
            };
          },
          {}};
}

}  // namespace shadowlab
CPP
cat >"$copy/shaders/shadow/throwaway.glsl" <<'GLSL'
// A throwaway shadow test (tests/one_technique.sh): the hard test, shadowed points at u_throwaway_level.
#include "lab/bias.glsl"

uniform float u_throwaway_level;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  return s.z - shadow_bias(n_dot_l) > closest ? u_throwaway_level : 1.0;
}
GLSL

# (a) The copy differs from the tree in the two new files only.
fingerprint >"$work/after.txt"
changed=$(comm -13 <(sed 's/^[0-9a-f]*  //' "$work/before.txt" | sort) <(sed 's/^[0-9a-f]*  //' "$work/after.txt" | sort) | tr '\n' ' ')
[ "$changed" = "./renderer/shadow_tests/throwaway.cpp ./shaders/shadow/throwaway.glsl " ] \
  || fail "the copy's new files are '$changed', not the throwaway's two"
[ "$(grep -vxFf "$work/before.txt" "$work/after.txt" | wc -l)" = 2 ] || fail "a file of the tree changed besides the two new ones"

build_copy "$src" "$copy" "$work/build.log" \
  || { tail -30 "$work/build.log" >&2; fail "the copy with the throwaway shadow test does not build"; }

# (b) Rendered with it and with the hard test, the same lab, light and camera.
bin="$copy/build/app/shadowlab"
export SHADOWLAB_DATA_DIR="$copy"
render() {
  "$bin" render --lab 1 --width 320 --height 180 --buffers --out "$work/$1" --shadow-test "${@:2}" >"$work/$1.log" 2>&1 \
    || { cat "$work/$1.log" >&2; fail "render --shadow-test $2 failed"; }
}
render hard hard
render throwaway throwaway --set throwaway.level=0.25
set +e
"$bin" render --lab 1 --out "$work/none" --shadow-test no_such_test >"$work/none.log" 2>&1
status=$?
set -e
[ "$status" = 2 ] || fail "an unknown shadow test exited $status, not 2 (usage)"
grep -q "throwaway" "$work/none.log" || fail "an unknown shadow test's error does not list the throwaway: $(cat "$work/none.log")"

python3 - "$work/hard/visibility.npy" "$work/throwaway/visibility.npy" <<'PY'
import ast, struct, sys

def load(path):  # a float32 .npy as render --buffers writes it (little-endian, C order)
    data = open(path, "rb").read()
    assert data[:6] == b"\x93NUMPY", path
    header_len = struct.unpack("<H", data[8:10])[0]
    header = ast.literal_eval(data[10:10 + header_len].decode("latin1"))
    assert header["descr"] == "<f4", header
    body = data[10 + header_len:]
    return struct.unpack("<%df" % (len(body) // 4), body)

hard, throwaway = load(sys.argv[1]), load(sys.argv[2])
assert len(hard) == len(throwaway) > 0
shadowed = sum(1 for h, t in zip(hard, throwaway) if h == 0.0 and t == 0.25)
other = [(i, h, t) for i, (h, t) in enumerate(zip(hard, throwaway)) if h != t and not (h == 0.0 and t == 0.25)]
lit = sum(1 for h in hard if h == 1.0)
print(f"one_technique: {len(hard)} pixels, {lit} lit by both, {shadowed} shadowed by hard at 0.25 with the throwaway")
if other:
    sys.exit(f"one_technique: {len(other)} pixels differ otherwise, first {other[:3]}")
if shadowed < 1000 or lit < 1000:
    sys.exit("one_technique: too few shadowed or lit pixels to tell the tests apart")
PY
echo "one_technique: a shadow test added as its own two files builds, renders and binds its parameter"
