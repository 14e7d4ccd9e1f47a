# Shared by tests/cli.sh (the command line) and tests/window.sh (the window under Xvfb): sourced with the
# binary and the case name as $1 and $2. Each case gets its own temporary folder and never touches the
# user's own settings file.
set -uo pipefail
bin="$1"; case_name="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
src="$(cd "$(dirname "$0")/.." && pwd)"  # the source tree: shaders/ and labs/
# No test ever reads or writes the user's own settings file.
export SHADOWLAB_SETTINGS="$tmp/settings.json"
fail() { echo "FAIL: $*"; exit 1; }

expect_error() {  # expect_error "message part" command...: non-zero exit, one clear line on stderr
  local want="$1"; shift
  "$@" >"$tmp/out" 2>"$tmp/err" && fail "exit 0 from: $*"
  grep -qF -- "$want" "$tmp/err" || fail "stderr lacks '$want': $(cat "$tmp/err")"
  grep -q "Segmentation\|Aborted\|terminate called" "$tmp/err" && fail "crashed: $(cat "$tmp/err")"
  return 0
}
one_line() { [ "$(wc -l <"$tmp/err")" -eq 1 ] || fail "expected one line on stderr: $(cat "$tmp/err")"; }
# python3 with tests/png_tools.py importable, for the cases that read PNGs (`from png_tools import load`).
# Pillow is Debian's python3-pil (scripts/setup): when the python3 first on PATH lacks it (a pyenv, a
# venv), the system's is used.
png_python() {
  local py
  for py in python3 /usr/bin/python3; do
    if "$py" -c "import PIL" 2>/dev/null; then
      PYTHONPATH="$src/tests${PYTHONPATH:+:$PYTHONPATH}" "$py" "$@"
      return
    fi
  done
  fail "no python3 with Pillow (bash scripts/setup installs python3-pil)"
}
window() {  # window ARGS...: the window under Xvfb on a 1440x900 screen; stderr kept in $tmp/err
  command -v xvfb-run >/dev/null || fail "xvfb-run missing (scripts/setup installs xvfb)"
  xvfb-run -a -s "-screen 0 1440x900x24" "$bin" "$@" >"$tmp/out" 2>"$tmp/err" || fail "window run failed: $(tail -3 "$tmp/err")"
  grep -q "Segmentation\|Aborted\|terminate called" "$tmp/err" && fail "crashed: $(cat "$tmp/err")"
  return 0
}

