#!/usr/bin/env bash
# The rooms stand in one order, and a room includes only the rooms below it (README, "Layout"):
#   core <- oracle <- renderer <- grading <- labs <- app
# Fails naming each `#include "ROOM/..."` of a product source (*.h, *.cpp) whose
# ROOM stands above the file's own room, e.g. core/ including oracle/, or grading/ including labs/.
# Usage: tests/rooms.sh [ROOT]   (default: this checkout)
set -euo pipefail
root="${1:-$(cd "$(dirname "$0")/.." && pwd)}"
rooms=(core oracle renderer grading labs app)
bad=0
for i in "${!rooms[@]}"; do
  above=("${rooms[@]:$((i + 1))}")
  [ ${#above[@]} -eq 0 ] && continue
  pattern="^[[:space:]]*#[[:space:]]*include[[:space:]]*\"($(IFS='|'; echo "${above[*]}"))/"
  hits=$(cd "$root" && find "${rooms[$i]}" -name '*.h' -o -name '*.cpp' | sort | xargs grep -HnE "$pattern" || true)
  if [ -n "$hits" ]; then
    echo "$hits" | sed "s|^|rooms: ${rooms[$i]}/ includes a room above it: |" >&2
    bad=1
  fi
done
# Inside the renderer the passes stand below the lit pass: a pass says which lit draws it wants
# (ShadowPass::Shape::lit_first, lit_view) and the renderer draws them; no pass calls the lit pass.
# Only the renderer and its debug views (and the lit pass itself) include renderer/lit_pass.h.
hits=$(cd "$root" && grep -lE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"renderer/lit_pass.h"' -r core oracle renderer grading labs app |
       grep -vxE 'renderer/(lit_pass|renderer|debug_views)\.(h|cpp)' | sort || true)
if [ -n "$hits" ]; then
  echo "$hits" | sed "s|^|rooms: includes renderer/lit_pass.h (a pass asks for lit draws, it never draws the lit pass): |" >&2
  bad=1
fi
[ "$bad" -eq 0 ] || exit 1
echo "rooms: no include runs up (${rooms[*]}), no pass includes the lit pass"
