# Sourced by tests/one_folder.sh and tests/one_technique.sh: a copy of the source tree, built as cheaply
# as the tree itself was.
#
# work_folder [WORK_DIR]: sets `work` to WORK_DIR (created), or to a temporary folder removed at exit.
work_folder() {
  if [ $# -ge 1 ]; then
    work="$1"
    mkdir -p "$work"
  else
    work="$(mktemp -d)"
    trap 'rm -rf "$work"' EXIT
  fi
}
#
# copy_tree SRC COPY: the working tree as it is (tracked files and new ones git does not ignore) into COPY.
copy_tree() {
  local src="$1" copy="$2"
  rm -rf "$copy"
  mkdir -p "$copy"
  if git -C "$src" rev-parse --show-toplevel >/dev/null 2>&1; then
    (cd "$src" && git ls-files -co --exclude-standard -z | tar --null --ignore-failed-read -T - -cf -) | tar -xf - -C "$copy"
  else  # not a git checkout: everything but the build folder
    tar -C "$src" --exclude=./build -cf - . | tar -xf - -C "$copy"
  fi
}

# build_copy SRC COPY LOG: configures COPY/build and builds shadowlab into it, the output into LOG (false
# when it does not build). The copy is compiled with SRC's SHADOWLAB_DATA_DIR, so that ccache serves every
# object the copy did not change; at run time SHADOWLAB_DATA_DIR points at the copy. The build folder sits
# inside the copy, as scripts/build has it: the same relative paths, the same generator as the tree's own
# build (else Ninja where installed; Make runs each compiler in another folder, so its relative paths,
# and ccache's keys, differ from a Ninja build's: the copy then compiled everything again, 245 s here),
# the same ccache keys.
build_copy() {
  local src="$1" copy="$2" log="$3"
  local launcher=() generator=() made_with
  if command -v ccache >/dev/null; then
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    export CCACHE_BASEDIR="$copy" CCACHE_NOHASHDIR=1
  fi
  local cache="${SHADOWLAB_BUILD_DIR:-$src/build}/CMakeCache.txt" unity=()
  made_with=$(sed -n 's/^CMAKE_GENERATOR:INTERNAL=//p' "$cache" 2>/dev/null || true)
  if [ -n "$made_with" ]; then generator=(-G "$made_with"); elif command -v ninja >/dev/null; then generator=(-G Ninja); fi
  # Unity batches or single files as the tree's build has them (SHADOWLAB_UNITY=OFF builds single files):
  # other objects than the tree's miss ccache.
  made_with=$(sed -n 's/^CMAKE_UNITY_BUILD:BOOL=//p' "$cache" 2>/dev/null || true)
  if [ -n "$made_with" ]; then unity=(-DCMAKE_UNITY_BUILD="$made_with"); fi
  cmake -S "$copy" -B "$copy/build" "${generator[@]}" "${unity[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DSHADOWLAB_BUILD_TESTS=OFF -DSHADOWLAB_DATA_DIR="$src" "${launcher[@]}" >/dev/null
  cmake --build "$copy/build" --target shadowlab -j "$(nproc)" >"$log" 2>&1
}
