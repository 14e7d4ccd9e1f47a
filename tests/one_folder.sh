#!/usr/bin/env bash
# "A lab is a folder", proven: a copy of the source tree gets a copy of lab 0 as labs/98_throwaway (its
# title changed inside its own lab.cpp, nothing else edited anywhere), is configured and built, and the
# built shadowlab lists lab 98, grades it (its solution passes, its stock exercise fails) and opens it in
# the window, by --lab 98 and by the keys 9, 8 (tests/cli.sh case one_folder_lab).
# Usage: tests/one_folder.sh [WORK_DIR]   (default: a temporary folder, removed afterwards)
# The copy is built by tests/tree_copy.sh: ccache serves every object but the new lab's and the generated
# lab list.
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
# shellcheck source=tests/tree_copy.sh
source "$src/tests/tree_copy.sh"
work_folder "$@"
copy="$work/src"
copy_tree "$src" "$copy"
cp -r "$copy/labs/00_basic_shadow_map" "$copy/labs/98_throwaway"
sed -i 's/lab.title = "Basic shadow map";/lab.title = "Throwaway copy";/' "$copy/labs/98_throwaway/lab.cpp"
grep -q '"Throwaway copy"' "$copy/labs/98_throwaway/lab.cpp" || { echo "one_folder: lab 0's title line moved" >&2; exit 1; }

build_copy "$src" "$copy" "$work/build.log" \
  || { tail -30 "$work/build.log" >&2; echo "one_folder: the copy with labs/98_throwaway does not build" >&2; exit 1; }
SHADOWLAB_DATA_DIR="$copy" bash "$copy/tests/cli.sh" "$copy/build/app/shadowlab" one_folder_lab
