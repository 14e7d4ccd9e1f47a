#!/usr/bin/env bash
# "A lab is a folder", proven: a copy of the source tree gets a copy of lab 0 as labs/98_throwaway (its
# title changed inside its own lab.cpp, nothing else edited anywhere), is configured and built, and the
# built shadowlab lists lab 98, grades it (its solution passes, its stock exercise fails) and opens it in
# the window, by --lab 98 and by the keys 9, 8 (tests/cli.sh case one_folder_lab).
# Usage: tests/one_folder.sh [WORK_DIR]   (default: a temporary folder, removed afterwards)
# The copy is compiled with the original tree's SHADOWLAB_DATA_DIR, so that ccache serves every object
# but the new lab's and the generated lab list; at run time SHADOWLAB_DATA_DIR points at the copy.
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
if [ $# -ge 1 ]; then
  work="$1"
  mkdir -p "$work"
else
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
fi
copy="$work/src"
rm -rf "$copy"
mkdir -p "$copy"
# The working tree as it is: tracked files and new ones git does not ignore.
if git -C "$src" rev-parse --show-toplevel >/dev/null 2>&1; then
  (cd "$src" && git ls-files -co --exclude-standard -z | tar --null --ignore-failed-read -T - -cf -) | tar -xf - -C "$copy"
else  # not a git checkout: everything but the build folder
  tar -C "$src" --exclude=./build -cf - . | tar -xf - -C "$copy"
fi
cp -r "$copy/labs/00_basic_shadow_map" "$copy/labs/98_throwaway"
sed -i 's/lab.title = "Basic shadow map";/lab.title = "Throwaway copy";/' "$copy/labs/98_throwaway/lab.cpp"
grep -q '"Throwaway copy"' "$copy/labs/98_throwaway/lab.cpp" || { echo "one_folder: lab 0's title line moved" >&2; exit 1; }

launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$copy" CCACHE_NOHASHDIR=1
fi
# The build folder inside the copy, as scripts/build has it: the same relative paths, the same generator
# as the tree's own build (else Ninja where installed; Make runs each compiler in another folder, so its relative paths, and ccache's
# keys, differ from a Ninja build's: the copy then compiled everything again, 245 s here), the same ccache keys.
generator=()
made_with=$(sed -n 's/^CMAKE_GENERATOR:INTERNAL=//p' "${SHADOWLAB_BUILD_DIR:-$src/build}/CMakeCache.txt" 2>/dev/null || true)
if [ -n "$made_with" ]; then generator=(-G "$made_with"); elif command -v ninja >/dev/null; then generator=(-G Ninja); fi
cmake -S "$copy" -B "$copy/build" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWLAB_BUILD_TESTS=OFF \
  -DSHADOWLAB_DATA_DIR="$src" "${launcher[@]}" >/dev/null
cmake --build "$copy/build" --target shadowlab -j "$(nproc)" >"$work/build.log" 2>&1 \
  || { tail -30 "$work/build.log" >&2; echo "one_folder: the copy with labs/98_throwaway does not build" >&2; exit 1; }
SHADOWLAB_DATA_DIR="$copy" bash "$copy/tests/cli.sh" "$copy/build/app/shadowlab" one_folder_lab
