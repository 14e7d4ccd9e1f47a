#!/usr/bin/env bash
# End-to-end tests of the window, under Xvfb (scripted keys and clicks, screenshots, settings), one case per
# CTest entry: tests/window.sh BIN CASE. The command line's cases are in tests/cli.sh.
source "$(dirname "$0")/cli_lib.sh"

case "$case_name" in
  window_xvfb)
    command -v xvfb-run >/dev/null || fail "xvfb-run missing (scripts/setup installs xvfb)"
    xvfb-run -a -s "-screen 0 1440x900x24" "$bin" --frames 5 --screenshot "$tmp/window.png" || fail "window run failed"
    [ -s "$tmp/window.png" ] || fail "no screenshot"
    png_python - "$tmp/window.png" <<'PY' || fail "panel not visible in the screenshot"
import sys
from png_tools import load
# Look for the panel: ImGui's dark title bar and text near the top-left corner differ from the scene's
# background colour.
w, h, rows = load(sys.argv[1])
bg = (41, 46, 56)  # the renderer's clear colour, sRGB-encoded
panel = sum(1 for y in range(20, 300) for x in range(20, 400)
            if abs(rows[y][4 * x] - bg[0]) + abs(rows[y][4 * x + 1] - bg[1]) + abs(rows[y][4 * x + 2] - bg[2]) > 30)
print("panel pixels differing from background:", panel)
assert panel > 5000
PY
    ;;
  window_settings)  # the window keeps values per lab, and a bad file is kept aside with a warning
    command -v xvfb-run >/dev/null || fail "xvfb-run missing (scripts/setup installs xvfb)"
    echo '{"version": 1, "labs": {"1": {"params": {"shadow.bias": 0.0' >"$SHADOWLAB_SETTINGS"  # cut short
    xvfb-run -a "$bin" --lab 1 --frames 2 >/dev/null 2>"$tmp/err" || fail "window run failed: $(cat "$tmp/err")"
    grep -q "warning: .*settings.json: is not valid JSON; kept as .*settings.json.bad-" "$tmp/err" || fail "no warning: $(cat "$tmp/err")"
    [ "$(cat "$tmp"/settings.json.bad-*)" = '{"version": 1, "labs": {"1": {"params": {"shadow.bias": 0.0' ] || fail "backup differs"
    python3 -c "import json,sys; j=json.load(open(sys.argv[1])); assert j['version'] == 1 and 'shadow.bias' in j['labs']['1']['params'], j" \
      "$SHADOWLAB_SETTINGS" || fail "defaults not saved on exit"
    python3 - "$SHADOWLAB_SETTINGS" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
j["labs"]["1"]["params"]["shadow.bias"] = 0.02
j["labs"]["1"]["presets"] = {"mine": {"shadow.bias": 0.03}}
json.dump(j, open(sys.argv[1], "w"))
PY
    xvfb-run -a "$bin" --lab 1 --frames 2 >/dev/null 2>"$tmp/err" || fail "second window run failed: $(cat "$tmp/err")"
    [ ! -s "$tmp/err" ] || fail "unexpected warning: $(cat "$tmp/err")"
    python3 -c "import json,sys; p=json.load(open(sys.argv[1]))['labs']['1']; assert p['params']['shadow.bias'] == 0.02 and 'mine' in p['presets'], p" \
      "$SHADOWLAB_SETTINGS" || fail "the lab's value or preset was lost"
    # The camera is kept with the scene (as a window keeps one moved there: --camera is for one run, see
    # window_one_off); a run that fails to start (a bad --camera) writes nothing.
    python3 -c "import json,sys; j=json.load(open(sys.argv[1])); j['camera'].update(target=[0, 1, 2], distance=1, fov_y_deg=40); json.dump(j, open(sys.argv[1], 'w'))" \
      "$SHADOWLAB_SETTINGS" || fail "no camera kept by the runs before"
    python3 -c "import json,sys; c=json.load(open(sys.argv[1]))['camera']; assert c['fov_y_deg'] == 40 and abs(c['distance'] - 1) < 1e-5 and c['target'] == [0, 1, 2] and c['scene'], c" \
      "$SHADOWLAB_SETTINGS" || fail "the camera was not kept: $(cat "$SHADOWLAB_SETTINGS")"
    cp "$SHADOWLAB_SETTINGS" "$tmp/kept.json"
    "$bin" --lab 1 --frames 2 --camera "eye=0,1,3 target=0,1,3" >/dev/null 2>"$tmp/err"; [ $? -eq 2 ] || fail "a bad --camera must exit 2"
    cmp -s "$SHADOWLAB_SETTINGS" "$tmp/kept.json" || fail "a run that failed to start changed the settings"
    # Started again without --camera, the window looks from the kept camera (and keeps it on exit; the
    # framed camera it would start from otherwise has a 45-degree field of view).
    xvfb-run -a "$bin" --lab 1 --frames 2 >/dev/null 2>"$tmp/err" ||
      fail "third window run failed: $(cat "$tmp/err")"
    python3 -c "import json,sys; c=json.load(open(sys.argv[1]))['camera']; assert c['fov_y_deg'] == 40 and c['target'] == [0, 1, 2], c" \
      "$SHADOWLAB_SETTINGS" || fail "the kept camera was replaced: $(cat "$SHADOWLAB_SETTINGS")"
    ;;
  window_keys_split)  # keys switch labs, S toggles the split view: the screenshots differ where they should
    window --script "frames:3,screenshot:$tmp/lab0.png,key:1,frames:3,screenshot:$tmp/lab1.png,key:s,frames:3,screenshot:$tmp/split.png,key:s,frames:3,screenshot:$tmp/unsplit.png,key:n,frames:3,screenshot:$tmp/lab2.png"
    for f in lab0 lab1 split unsplit lab2; do [ -s "$tmp/$f.png" ] || fail "no $f.png"; done
    png_python - "$tmp" <<'PY' || fail "screenshots do not differ as expected"
import sys
from png_tools import load, differing
img = {n: load(f"{sys.argv[1]}/{n}.png") for n in ("lab0", "lab1", "split", "unsplit", "lab2")}
w, h, _ = img["lab1"]
r = {n: v[2] for n, v in img.items()}
panel = (20, 60, 430, 400)                   # the panel's title, task and check sections
left = (460, 60, w // 2 - 40, h - 60)        # the view left of the divider, right of the panel
right = (w // 2 + 40, 60, w - 20, h - 60)    # the view right of the divider, above the magnifier corner
stats = {
    "panel lab0/lab1": differing(r["lab0"], r["lab1"], *panel),
    "panel lab1/lab2 (N)": differing(r["lab1"], r["lab2"], *panel),
    "left split/lab1": differing(r["split"], r["lab1"], *left),
    "right split/lab1": differing(r["split"], r["lab1"], *right),
    "view unsplit/lab1": differing(r["unsplit"], r["lab1"], 460, 60, w - 20, h - 60),
}
print(stats)
assert stats["panel lab0/lab1"] > 0.02, "key 1 did not change the panel"
assert stats["panel lab1/lab2 (N)"] > 0.02, "key N did not change the panel"
assert stats["right split/lab1"] > 0.01, "the split's right side (solution) looks like the exercise"
assert stats["left split/lab1"] < stats["right split/lab1"] / 3, "the split changed the left side"
assert stats["view unsplit/lab1"] < 0.01, "S again did not return to the single view"
# The divider: a bright vertical line in the middle of the split screenshot, none without the split.
col = lambda rows, x: sum(1 for y in range(100, h - 100, 4) if min(rows[y][4 * x:4 * x + 3]) > 200)
line_split = max(col(r["split"], x) for x in range(w // 2 - 2, w // 2 + 3))
line_single = max(col(r["lab1"], x) for x in range(w // 2 - 2, w // 2 + 3))
print("divider rows:", line_split, line_single)
assert line_split > 0.9 * len(range(100, h - 100, 4)) and line_single < line_split / 2, "no divider"
PY
    ;;
  window_frame_cost)  # the window takes render's options; its interactive frame waits for nothing (issue 17)
    code 2 "$bin" --size 12x9 --frames 1
    code 2 "$bin" --size 640 --frames 1
    code 2 "$bin" --camera "eye=1,2 target=0,0,0" --frames 1
    code 2 "$bin" --camera "eye=1,1,1 target=1,1,1" --frames 1
    code 2 "$bin" --camera "fov=abc" --frames 1
    code 2 "$bin" --set shadow.bais=1 --frames 1
    code 2 "$bin" render --out "$tmp/o" --camera "zoom=2"
    "$bin" render --lab 6 --out "$tmp/cam" --width 320 --height 180 --camera "eye=-2,4,-1 target=0,0,0 fov=45" \
      || fail "render --camera failed"
    # Lab 6 at LearnOpenGL's view, the line shown for 4 frames, then hidden (H) for 12.
    window --lab 6 --size 640x360 --camera "eye=-2,4,-1 target=0,0,0 fov=45" --set view.debug_quad=0 \
      --frame-report "$tmp/cost.json" --script "frames:4,key:h,frames:12,screenshot:$tmp/cost.png"
    png_python - "$tmp" <<'PY' || fail "the interactive frame waits for the GPU, or --size/--camera were not applied"
import json, sys
from png_tools import size
t = sys.argv[1]
r = json.load(open(f"{t}/cost.json"))
print(r)
w, h = size(f"{t}/cost.png")
assert (w, h) == (640, 360), (w, h)
hidden, shown = r["pass_line_hidden"], r["pass_line_shown"]
assert hidden["frames"] >= 10 and shown["frames"] >= 3, r
assert hidden["gl_finishes"] == 0 and hidden["blocking_query_reads"] == 0, "waits with the pass-time line hidden"
if r["timers_work"]:
    assert shown["gl_finishes"] == 0 and shown["blocking_query_reads"] == 0, "waits although the timers work"
else:  # a software rasteriser: exact times only while the line is shown, and they are counted
    assert shown["gl_finishes"] >= 2 * shown["frames"], r
PY
    ;;
  window_hide_panel)  # H hides the panel (no ImGui window is built), a corner line says how to get it back, H shows it
    window --script "frames:3,screenshot:$tmp/shown.png,key:h,frames:3,screenshot:$tmp/hidden.png,key:h,frames:3,screenshot:$tmp/again.png"
    png_python - "$tmp" <<'PY' || fail "H did not hide and restore the panel"
import sys
from png_tools import load, differing
w, h, _ = load(f"{sys.argv[1]}/shown.png")
r = {n: load(f"{sys.argv[1]}/{n}.png")[2] for n in ("shown", "hidden", "again")}
stats = {"panel hidden/shown": differing(r["hidden"], r["shown"], 20, 60, 430, 400),
         "panel again/shown": differing(r["again"], r["shown"], 20, 60, 430, 400),
         "hint hidden/again": differing(r["hidden"], r["again"], 12, h - 34, 250, h - 14, step=1)}
print(stats)
assert stats["panel hidden/shown"] > 0.2, "H did not hide the panel"
assert stats["panel again/shown"] < 0.01, "H again did not bring the panel back"
assert stats["hint hidden/again"] > 0.03, "no 'press H' line in the corner while the panel is hidden"
PY
    ;;
  window_check_async)  # Check runs on a worker thread: the window keeps drawing, with a progress bar, then the result
    window --lab 5 --script "frames:3,screenshot:$tmp/before.png,check,frames:2,screenshot:$tmp/running.png,frames:2,screenshot:$tmp/running2.png,wait:12,frames:3,screenshot:$tmp/done.png"
    png_python - "$tmp" <<'PY' || fail "the Check did not run alongside the frames"
import os, sys
from png_tools import load
d = sys.argv[1]
r = {n: load(f"{d}/{n}.png")[2] for n in ("before", "running", "running2", "done")}
# ImGui's progress bar fill (PlotHistogram, dark style: 230, 179, 0) in the panel; FAIL lines are red.
bar = lambda rows: sum(1 for y in range(20, 700, 2) for x in range(20, 430, 2)
                       if rows[y][4 * x] > 200 and 150 < rows[y][4 * x + 1] < 200 and rows[y][4 * x + 2] < 40)
red = lambda rows: sum(1 for y in range(20, 840, 2) for x in range(20, 430, 2)
                       if rows[y][4 * x] > 200 and rows[y][4 * x + 1] < 150 and rows[y][4 * x + 2] < 140)
t = {n: os.path.getmtime(f"{d}/{n}.png") for n in r}
stats = {"bar before": bar(r["before"]), "bar running": bar(r["running"]), "bar running2": bar(r["running2"]),
         "bar done": bar(r["done"]), "red before": red(r["before"]), "red done": red(r["done"]),
         "seconds running->running2": round(t["running2"] - t["running"], 2)}
print(stats)
assert stats["bar before"] == 0 and stats["bar done"] == 0, "a progress bar outside the check"
assert stats["bar running"] > 20 and stats["bar running2"] > 20, "no progress bar while the check runs"
# Two frames while lab 5's check (about 4 s) runs take far less than the check: the loop is not blocked.
assert stats["seconds running->running2"] < 2.0, "frames stalled during the check"
assert stats["red done"] > stats["red before"] + 20, "the result (the stock exercise's FAILs) is not shown"
PY
    ;;
  window_resize_minimise)  # resizing, minimising, fullscreen and back: no crash, pictures of the right size
    window --lab 5 --script "frames:2,resize:800x500,frames:3,screenshot:$tmp/small.png,iconify,wait:0.5,restore,wait:0.3,frames:2,key:m,key:f11,frames:3,screenshot:$tmp/full.png,key:f11,frames:3,screenshot:$tmp/back.png"
    png_python - "$tmp" <<'PY' || fail "wrong picture sizes"
import sys
from png_tools import load
sizes = {n: load(f"{sys.argv[1]}/{n}.png")[:2] for n in ("small", "full", "back")}
print(sizes)
assert sizes["small"] == (800, 500), sizes
assert sizes["full"] == (1440, 900), sizes
assert sizes["back"] == (800, 500), sizes
PY
    ;;
  window_drop)  # a bad file dropped on the window shows an error in the panel; a good one replaces the scene
    echo "not a model" >"$tmp/bad.gltf"
    window --script "frames:2,screenshot:$tmp/before.png,drop:$tmp/bad.gltf,frames:2,screenshot:$tmp/bad.png,drop:$src/assets/models/Duck/Duck.glb,frames:3,screenshot:$tmp/duck.png"
    png_python - "$tmp" <<'PY' || fail "drop not shown as expected"
import sys
from png_tools import load, differing
r = {n: load(f"{sys.argv[1]}/{n}.png")[2] for n in ("before", "bad", "duck")}
w, h = 1440, 860
red = lambda rows: sum(1 for y in range(20, 400) for x in range(20, 430)
                       if rows[y][4 * x] > 200 and rows[y][4 * x + 1] < 150 and rows[y][4 * x + 2] < 140)
stats = {"red before": red(r["before"]), "red bad": red(r["bad"]), "red duck": red(r["duck"]),
         "view bad/before": differing(r["bad"], r["before"], 460, 60, w - 20, h - 60),
         "view duck/before": differing(r["duck"], r["before"], 460, 60, w - 20, h - 60)}
print(stats)
assert stats["red bad"] > stats["red before"] + 200, "no error text in the panel"
assert stats["red duck"] < stats["red bad"], "the error stayed after a good file"
assert stats["view bad/before"] < 0.01, "a bad file changed the scene"
assert stats["view duck/before"] > 0.05, "the dropped model is not shown"
PY
    ;;
  window_bad_script)
    expect_error "--script: bad step 'key:nokey'" "$bin" --script "frames:1,key:nokey"
    for step in "click:62" "click:62;" "click:x;302" "click:-1;302"; do expect_error "--script: bad step '$step'" "$bin" --script "frames:1,$step"; done
    ;;
  window_annotations)  # issue 35: the window draws the same labels over its debug quads (lab 12's cascades)
    window --lab 12 --size 1280x720 --script "frames:3,screenshot:$tmp/shown.png"
    window --lab 12 --size 1280x720 --set view.debug_quad=false --script "frames:3,screenshot:$tmp/hidden.png"
    png_python - "$tmp" <<'PY' || fail "the window draws no labels over its debug quads"
import sys
from png_tools import load
w, h, shown = load(f"{sys.argv[1]}/shown.png")
# Near-white label text in the strip right above the quads (90 px squares at the bottom right).
white = lambda rows: sum(1 for y in range(h - 140, h - 100) for x in range(w - 378, w - 4)
                         if min(rows[y][4 * x:4 * x + 3]) > 215)
hidden = load(f"{sys.argv[1]}/hidden.png")[2]
stats = {"label text pixels": white(shown), "without the quads": white(hidden)}
print(stats)
assert stats["label text pixels"] > 60 and stats["without the quads"] < 10, "no label text over the quads"
PY
    ;;
  window_bench)  # --bench opens the plot window; a bad file stops before the window, settings untouched
    cp "$src/docs/bench.json" "$tmp/b.json"
    window --frames 3 --screenshot "$tmp/plain.png"
    window --bench "$tmp/b.json" --frames 3 --screenshot "$tmp/plot.png"
    png_python - "$tmp" <<'PY' || fail "no plot window in the screenshot"
import sys
from png_tools import load, differing
w, h, plain = load(f"{sys.argv[1]}/plain.png")
_, _, plot = load(f"{sys.argv[1]}/plot.png")
d = differing(plain, plot, w - 640, 60, w - 40, 500)
print("plot window region differs:", d)
assert d > 0.5
PY
    rm -f "$SHADOWLAB_SETTINGS"
    echo 'not json' >"$tmp/bad.json"
    xvfb-run -a -s "-screen 0 1440x900x24" "$bin" --bench "$tmp/bad.json" --frames 3 >"$tmp/out" 2>"$tmp/err" \
      && fail "exit 0 with a bad --bench file"
    grep -qF "bad.json: not valid JSON" "$tmp/err" || fail "the error does not name the file: $(cat "$tmp/err")"
    [ ! -e "$SHADOWLAB_SETTINGS" ] || fail "a failed start wrote the settings file"
    ;;
  window_drop_hostile)  # issue 18: a dropped model with a huge or hostile error text: no abort, bounded panel text
    [ -x "${SHADOWLAB_HOSTILE_CASES:-}" ] || fail "SHADOWLAB_HOSTILE_CASES is not the hostile_cases tool"
    "$SHADOWLAB_HOSTILE_CASES" "$tmp/cases" >/dev/null || fail "could not write the cases"
    window --script "frames:2,drop:$tmp/cases/long_uri.gltf,frames:2,drop:$tmp/cases/data_uri_60mb.gltf,frames:2,drop:$tmp/cases/data_uri_30mb.gltf,frames:2,drop:$tmp/cases/escape_uri.gltf,frames:2,drop:$tmp/cases/deep_extras.gltf,frames:2,screenshot:$tmp/shot.png"
    [ "$(grep -c "cannot open the dropped file" "$tmp/err")" -eq 5 ] || fail "not every error on the terminal: $(cat "$tmp/err")"
    [ "$(wc -c <"$tmp/err")" -lt 5000 ] || fail "$(wc -c <"$tmp/err") bytes of errors for 5 files"
    grep -qF '(20004 bytes)' "$tmp/err" || fail "the long URI is not cut: $(head -c 600 "$tmp/err")"
    grep -qF '\x1B[2J' "$tmp/err" || fail "the escape sequence is not shown escaped"
    LC_ALL=C grep -q $'[\x01-\x08\x0b-\x1f\x7f]' "$tmp/err" && fail "control characters on the terminal"
    png_python - "$tmp" <<'PY' || fail "no error shown in the panel"
import sys
from png_tools import load
w, h, rows = load(f"{sys.argv[1]}/shot.png")
red = sum(1 for y in range(20, 500) for x in range(20, 430)
          if rows[y][4 * x] > 200 and rows[y][4 * x + 1] < 150 and rows[y][4 * x + 2] < 140)
print("red pixels in the panel:", red)
assert red > 200
PY
    ;;
  window_one_off)  # issue 35: --set, --preset, --impl, --camera are for one run: the settings file is as it was after it
    window --lab 1 --frames 3 --screenshot "$tmp/plain1.png"  # the first run writes the lab's values and the camera
    [ -s "$SHADOWLAB_SETTINGS" ] || fail "no settings written by a plain run"
    cp "$SHADOWLAB_SETTINGS" "$tmp/kept.json"
    window --lab 1 --frames 3 --screenshot "$tmp/given.png" --preset peter-panning --set view.debug_quad_size=0.8 \
      --impl solution --camera "eye=0,1,3 target=0,1,2 fov=40"
    cmp -s "$SHADOWLAB_SETTINGS" "$tmp/kept.json" ||
      fail "a run with --set/--preset/--impl/--camera changed the settings: $(diff "$tmp/kept.json" "$SHADOWLAB_SETTINGS" | head -20)"
    window --lab 1 --frames 3 --screenshot "$tmp/plain2.png"
    cmp -s "$SHADOWLAB_SETTINGS" "$tmp/kept.json" || fail "the run after the one-off run changed the settings"
    png_python - "$tmp" <<'PY' || fail "the one-off values were not shown, or they persisted"
import sys
from png_tools import load, differing
w, h, _ = load(f"{sys.argv[1]}/plain1.png")
r = {n: load(f"{sys.argv[1]}/{n}.png")[2] for n in ("plain1", "given", "plain2")}
view = (460, 60, w - 20, h - 60)
stats = {"given/plain1": differing(r["given"], r["plain1"], *view), "plain2/plain1": differing(r["plain2"], r["plain1"], *view)}
print(stats)
assert stats["given/plain1"] > 0.2, "the command line's values were not shown"
assert stats["plain2/plain1"] < 0.01, "the command line's values came back at the next start"
PY
    # A camera moved in the window (R: the scene framed, 45 degrees) is kept, --camera or not.
    python3 - "$SHADOWLAB_SETTINGS" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); j["camera"]["fov_y_deg"] = 30; json.dump(j, open(sys.argv[1], "w"))
PY
    window --lab 1 --camera "eye=0,1,3 target=0,1,2 fov=40" --script "frames:2,key:r,frames:2"
    python3 -c "import json,sys; c=json.load(open(sys.argv[1]))['camera']; assert c['fov_y_deg'] == 45, c" "$SHADOWLAB_SETTINGS" ||
      fail "the camera reset by R was not kept: $(cat "$SHADOWLAB_SETTINGS")"
    ;;
  window_details)  # issue 35: F12 saves in the pictures folder and says where over the view; the text size is kept
    mkdir -p "$tmp/home"
    # F12 with no SHADOWLAB_SCREENSHOTS: the pictures folder (here ~/Pictures: no xdg-user-dirs file in this home).
    HOME="$tmp/home" XDG_CONFIG_HOME= XDG_PICTURES_DIR= window --lab 1 \
      --script "frames:3,screenshot:$tmp/before.png,key:f12,frames:2,screenshot:$tmp/toast.png"
    shots=("$tmp"/home/Pictures/shadowlab/shadowlab-lab01-*.png)
    [ "${#shots[@]}" -eq 1 ] && [ -s "${shots[0]}" ] || fail "F12 saved no picture in ~/Pictures/shadowlab: $(ls -R "$tmp/home")"
    grep -qF "screenshot saved to ${shots[0]}" "$tmp/out" || fail "F12 did not say where: $(cat "$tmp/out")"
    SHADOWLAB_SCREENSHOTS="$tmp/shots" window --lab 1 --script "frames:2,key:f12,frames:2,key:f12,frames:2"
    [ "$(ls "$tmp/shots" | grep -c '^shadowlab-lab01-.*\.png$')" -eq 2 ] || fail "two F12s, not two pictures in \$SHADOWLAB_SCREENSHOTS: $(ls "$tmp/shots")"
    # The text size kept in the settings is the panel's at the next start, and stays kept.
    python3 - "$SHADOWLAB_SETTINGS" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); j.setdefault("ui", {})["text_size"] = 2; json.dump(j, open(sys.argv[1], "w"))
PY
    window --lab 1 --frames 3 --screenshot "$tmp/large.png"
    python3 -c "import json,sys; assert json.load(open(sys.argv[1]))['ui']['text_size'] == 2" "$SHADOWLAB_SETTINGS" || fail "text size lost"
    png_python - "$tmp" <<'PY' || fail "no feedback over the view after F12, or the kept text size was not used"
import sys
from png_tools import load, differing
w, h, _ = load(f"{sys.argv[1]}/before.png")
r = {n: load(f"{sys.argv[1]}/{n}.png")[2] for n in ("before", "toast", "large")}
stats = {"toast: bottom centre": differing(r["toast"], r["before"], w // 2 - 200, h - 40, w // 2 + 200, h - 12, step=1),
         "text size 2: panel": differing(r["large"], r["before"], 20, 60, 430, 400)}
print(stats)
assert stats["toast: bottom centre"] > 0.05, "F12 showed nothing at the bottom of the view"
assert stats["text size 2: panel"] > 0.2, "the kept text size was not used"
PY
    ;;
  window_demo)  # issue 35: demo mode at 1280x720: F-keys choose presets, Page Down / Up step the story, a large caption says which
    # Lab 1's presets: acne, peter-panning, tuned (F3; the lab's defaults, so only the caption changes the picture), cull front, no culling.
    window --lab 1 --size 1280x720 --script "frames:3,screenshot:$tmp/plain.png,key:f3,frames:3,screenshot:$tmp/tuned.png,key:pageup,frames:3,screenshot:$tmp/back.png,key:pagedown,frames:3,screenshot:$tmp/again.png,key:h,frames:3,screenshot:$tmp/hidden.png,key:h,key:f1,frames:3,screenshot:$tmp/acne.png,key:f2,frames:3,key:f3,frames:3,screenshot:$tmp/f2f3.png"
    # The same preset with the solution: it needs no working exercise, so its caption says nothing of one.
    window --lab 1 --size 1280x720 --impl solution --script "frames:2,key:f1,frames:3,screenshot:$tmp/acne_solution.png"
    # Lab 9's stock exercise emits no volumes: its z-pass preset (F2) shows nothing there; "Solution beside it" does.
    window --lab 9 --size 1280x720 --script "frames:2,key:f2,frames:3,screenshot:$tmp/zpass.png,solution-beside,frames:3,screenshot:$tmp/beside.png"
    window --lab 9 --size 1280x720 --impl solution --script "frames:2,key:f2,frames:3,screenshot:$tmp/zpass_solution.png"
    png_python - "$tmp" <<'PY' || fail "the presets' keys, the story or the caption did not work"
import sys
from png_tools import load, differing
w, h, _ = load(f"{sys.argv[1]}/plain.png")
r = {n: load(f"{sys.argv[1]}/{n}.png")[2] for n in ("plain", "tuned", "back", "again", "f2f3", "hidden", "acne", "acne_solution", "zpass", "zpass_solution", "beside")}
# The caption's line for a preset that needs a working exercise is in the panel's hint colour (242, 204, 115).
yellow = lambda rows: sum(1 for y in range(0, 200) for x in range(460, 950)
                          if rows[y][4 * x] > 200 and 170 < rows[y][4 * x + 1] < 230 and 80 < rows[y][4 * x + 2] < 150)
top = (460, 0, 950, 200)              # the caption: top of the view, right of the panel, left of the pass-time line
below = (460, 300, w - 10, h - 60)    # the view under it
stats = {"caption tuned/plain": differing(r["tuned"], r["plain"], *top),
         "view tuned/plain": differing(r["tuned"], r["plain"], *below),
         "caption back/tuned (Page Up)": differing(r["back"], r["tuned"], *top),
         "view back/tuned (Page Up)": differing(r["back"], r["tuned"], *below),
         # Page Down from peter-panning: "tuned" over peter-panning's camera (a preset without a view keeps
         # the one shown), the same picture as pressing F2 then F3; its view differs from peter-panning's.
         "all again/F2 then F3 (Page Down)": differing(r["again"], r["f2f3"], 0, 0, w, h),
         "view again/back (Page Down)": differing(r["again"], r["back"], *below),
         "caption hidden panel/plain": differing(r["hidden"], r["plain"], w // 4, 0, 3 * w // 4, 120)}
# How tall the caption is: the rows where F3 changed the picture (a lecture hall's back row needs large text).
rows = [y for y in range(0, h // 2) if any(sum(abs(r["tuned"][y][4 * x + c] - r["plain"][y][4 * x + c]) for c in range(3)) > 24
                                            for x in range(460, 950, 2))]
stats["caption rows"] = (rows[0], rows[-1]) if rows else None
stats["needs-exercise line: acne exercise, solution, tuned"] = (yellow(r["acne"]), yellow(r["acne_solution"]), yellow(r["tuned"]))
print(stats)
assert stats["caption tuned/plain"] > 0.05, "F3 showed no caption"
assert stats["view tuned/plain"] < 0.01, "F3 (the lab's defaults) changed the view, or the caption is not at the top"
assert rows and rows[-1] - rows[0] >= 60, "the caption is too small to read from afar"
assert stats["caption back/tuned (Page Up)"] > 0.05 and stats["view back/tuned (Page Up)"] > 0.01, "Page Up did not step back to peter-panning"
assert stats["all again/F2 then F3 (Page Down)"] < 0.005 and stats["view again/back (Page Down)"] > 0.01, \
    "Page Down did not step forward to tuned again"
assert stats["caption hidden panel/plain"] > 0.05, "the caption went with the panel (H)"
# "Solution beside it": the right half is the solution's (as in zpass_solution), the left stays the exercise's.
mid = w // 2  # the divider (compare.divider 0.5 of the width); right of it, where the scene's shadows fall
stats["beside: right vs solution, right vs exercise, left vs exercise"] = (
    differing(r["beside"], r["zpass_solution"], mid + 20, 330, 1000, 600),
    differing(r["beside"], r["zpass"], mid + 20, 330, 1000, 600),
    differing(r["beside"], r["zpass"], 470, 300, mid - 20, h - 60))
print(stats["beside: right vs solution, right vs exercise, left vs exercise"])
rs, re_, le = stats["beside: right vs solution, right vs exercise, left vs exercise"]
assert re_ > 0.02 and rs < re_ / 3 and le < re_ / 3, "Solution beside it did not put the solution's picture on the right"
ex, sol, tuned = stats["needs-exercise line: acne exercise, solution, tuned"]
assert ex > 300 and sol < ex / 20 and tuned < ex / 20, "the caption does not say which presets need a working exercise"
PY
    ;;
  window_click)  # issue 35: a click on a panel button, through ImGui's mouse callbacks, does what the button says
    # Lab 1 at 1280x720: the button "F4 cull front" has its centre at (62, 302) in the panel (measured in a
    # screenshot of this layout). Clicking it must give the picture F4 gives (the preset's values, camera and
    # caption). A click that misses it leaves the view as it was (at (62, 340), below the button: 0.08 % of the view changed, against 90 % for the hit).
    window --lab 1 --size 1280x720 --script "frames:3,screenshot:$tmp/plain.png,click:62;302,frames:3,screenshot:$tmp/clicked.png"
    window --lab 1 --size 1280x720 --script "frames:3,key:f4,frames:3,screenshot:$tmp/f4.png"
    png_python - "$tmp" <<'PY' || fail "clicking the preset's button did not choose the preset"
import sys
from png_tools import load, differing
w, h, _ = load(f"{sys.argv[1]}/plain.png")
r = {n: load(f"{sys.argv[1]}/{n}.png")[2] for n in ("plain", "clicked", "f4")}
# Right of the panel, above and below the row where the button's tooltip (its description) spills into the view.
above, below = (460, 0, w, 300), (460, 340, w, h)
stats = {"clicked/plain": (differing(r["clicked"], r["plain"], *above) + differing(r["clicked"], r["plain"], *below)) / 2,
         "clicked/F4": (differing(r["clicked"], r["f4"], *above) + differing(r["clicked"], r["f4"], *below)) / 2}
print(stats)
assert stats["clicked/plain"] > 0.3, "the click changed (almost) nothing in the view: did it miss the button?"
assert stats["clicked/F4"] < 0.005, "the click gave another picture than the preset's key F4"
PY
    ;;
  window_live_cpp)  # issue 34: a saved C++ exercise is rebuilt in the background and used from the next frame
    # A data folder like the source tree (SHADOWLAB_DATA_DIR), with lab 2 copied so its exercise can be edited.
    mkdir -p "$tmp/data/labs"
    for f in "$src"/*; do [ "$(basename "$f")" = labs ] || ln -s "$f" "$tmp/data/"; done
    for f in "$src"/labs/*; do ln -s "$f" "$tmp/data/labs/"; done
    rm "$tmp/data/labs/02_ortho_fit" && cp -r "$src/labs/02_ortho_fit" "$tmp/data/labs/"
    export SHADOWLAB_DATA_DIR="$tmp/data"
    exercise="$tmp/data/labs/02_ortho_fit/exercise.cpp"
    # The student saves twice while the window runs: a right answer once the first picture is taken, then
    # a file that does not compile once the second is. Each save is picked up by the window's poll.
    ( for _ in $(seq 600); do [ -s "$tmp/stock.png" ] && break; sleep 0.1; done
      cp "$src/tests/answers/02_ortho_fit/right/own_basis__exercise.cpp" "$exercise"
      for _ in $(seq 1800); do [ -s "$tmp/live.png" ] && break; sleep 0.1; done
      printf 'int broken = ;\n' >>"$exercise" ) &
    editor=$!
    # The builds take a few seconds each here (compiled in the sandbox, under load up to half a minute).
    window --lab 2 --script "frames:3,screenshot:$tmp/stock.png,wait:45,frames:3,screenshot:$tmp/live.png,wait:45,frames:3,screenshot:$tmp/broken.png"
    wait "$editor"
    grep -q "shadowlab: your edited C++ exercise is live" "$tmp/out" || fail "the edited exercise was not used: $(cat "$tmp/out" "$tmp/err")"
    grep -q "labs/02_ortho_fit/exercise.cpp:[0-9]*:[0-9]*: error" "$tmp/err" || fail "the build error does not name the student's line: $(cat "$tmp/err")"
    grep -q "your last good build keeps running" "$tmp/err" || fail "the error does not say the last good build runs: $(cat "$tmp/err")"
    png_python - "$tmp" <<'PY' || fail "the view did not follow the saved exercise"
import sys
from png_tools import load
d = sys.argv[1]
r = {n: load(f"{d}/{n}.png")[2] for n in ("stock", "live", "broken")}
w = len(r["stock"][0]) // 4
# The 3D view right of the panel (x from 460), under the pass-time line (whose figures change every frame):
# the fixed box of the stock exercise against the fitted one.
def differing(a, b):
    return sum(1 for y in range(60, len(a), 2) for x in range(460, w, 2)
               if sum(abs(a[y][4 * x + c] - b[y][4 * x + c]) for c in range(3)) > 30)
stats = {"stock->live": differing(r["stock"], r["live"]), "live->broken": differing(r["live"], r["broken"])}
print(stats)
assert stats["stock->live"] > 500, "the saved right answer did not change the view"
assert stats["live->broken"] < 50, "a file that does not build replaced the last good one"
PY
    ;;
  window_live_gl)  # issue 34: lab 0's GL exercise, saved, is built into the window and draws its shadow map
    # A data folder like the source tree, with lab 0 copied: its GLSL part is a right answer, so that what
    # changes the picture is the OpenGL part alone (gl_shadow_target.cpp).
    mkdir -p "$tmp/data/labs"
    for f in "$src"/*; do [ "$(basename "$f")" = labs ] || ln -s "$f" "$tmp/data/"; done
    for f in "$src"/labs/*; do ln -s "$f" "$tmp/data/labs/"; done
    lab0="$tmp/data/labs/00_basic_shadow_map"
    rm "$lab0" && cp -r "$src/labs/00_basic_shadow_map" "$lab0"
    answers="$src/tests/answers/00_basic_shadow_map"
    cp "$answers/right/texel_fetch__exercise.glsl" "$lab0/exercise.glsl"
    export SHADOWLAB_DATA_DIR="$tmp/data"
    # The program's own functions (the solution's) with the same GLSL answer: what a right GL answer must draw.
    window --lab 0 --impl solution --script "frames:3,screenshot:$tmp/solution.png"
    # The student saves three times while the window runs: a right answer once the stock file's picture is
    # taken, then one that never clears the map, then a file that does not compile. A build takes under a
    # second here (0.4 s measured under a load of 8); each picture waits 10 s for it.
    exercise="$lab0/gl_shadow_target.cpp"
    ( for shot in stock right no_clear; do
        for _ in $(seq 1200); do [ -s "$tmp/$shot.png" ] && break; sleep 0.1; done
        case $shot in
          stock) cp "$answers/right/clamp_to_border_one__gl_shadow_target.cpp" "$exercise" ;;
          right) cp "$answers/wrong/no_clear__gl_shadow_target.cpp" "$exercise" ;;
          no_clear) printf 'int broken = ;\n' >>"$exercise" ;;
        esac
      done ) &
    editor=$!
    steps="frames:3,wait:10,frames:3,screenshot:$tmp/stock.png"
    for shot in right no_clear broken; do steps="$steps,wait:10,frames:3,screenshot:$tmp/$shot.png"; done
    window --lab 0 --impl exercise --script "$steps"
    wait "$editor"
    grep -q "shadowlab: your edited C++ exercise is live" "$tmp/out" || fail "the GL exercise was not used: $(cat "$tmp/out" "$tmp/err")"
    grep -q "labs/00_basic_shadow_map/gl_shadow_target.cpp:[0-9]*:[0-9]*: error" "$tmp/err" ||
      fail "the build error does not name the student's line: $(cat "$tmp/err")"
    png_python - "$tmp" <<'PY' || fail "the view did not follow the saved GL exercise"
import sys
from png_tools import load
d = sys.argv[1]
r = {n: load(f"{d}/{n}.png")[2] for n in ("solution", "stock", "right", "no_clear", "broken")}
w = len(r["stock"][0]) // 4
# The 3D view right of the panel (x from 460), under the pass-time line, debug quads included.
def differing(a, b):
    return sum(1 for y in range(60, len(a), 2) for x in range(460, w, 2)
               if sum(abs(a[y][4 * x + c] - b[y][4 * x + c]) for c in range(3)) > 30)
pairs = (("stock->right", "stock", "right"), ("right~solution", "right", "solution"),
         ("right->no_clear", "right", "no_clear"), ("no_clear->broken", "no_clear", "broken"))
stats = {k: differing(r[a], r[b]) for k, a, b in pairs}
print(stats)
assert stats["stock->right"] > 500, "the saved right answer did not change the view"
assert stats["right~solution"] < 50, "a right answer does not draw what the program's own functions draw"
assert stats["right->no_clear"] > 500, "a pass that never clears its map looks like a right one"
assert stats["no_clear->broken"] < 50, "a file that does not build replaced the last good one"
PY
    ;;
  window_check_dropped)  # issue 36: Check on a dropped model grades it as `check --scene` does (in the lab's frame, against the solution there)
    # Lab 7's solution on the Duck: in absolute units its spot places miss the model (high.shadow_error 0.022
    # against the lab's 0.005: FAIL lines); graded as a foreign scene it passes (cli.check_foreign_scene).
    window --lab 7 --impl solution --script "frames:2,drop:$src/assets/models/Duck/Duck.glb,frames:2,screenshot:$tmp/duck.png,check,wait:60,frames:3,screenshot:$tmp/checked.png"
    png_python - "$tmp" <<'PY' || fail "the Check on the dropped Duck did not grade it as a foreign scene"
import sys
from png_tools import load
r = {n: load(f"{sys.argv[1]}/{n}.png")[2] for n in ("duck", "checked")}
# FAIL lines are red in the panel; a passing result has none. ImGui's green PASS (and the progress bar) are not red.
red = lambda rows: sum(1 for y in range(20, 840, 2) for x in range(20, 430, 2)
                       if rows[y][4 * x] > 200 and rows[y][4 * x + 1] < 150 and rows[y][4 * x + 2] < 140)
green = lambda rows: sum(1 for y in range(20, 840, 2) for x in range(20, 430, 2)
                         if rows[y][4 * x + 1] > 170 and rows[y][4 * x] < 150 and rows[y][4 * x + 2] < 150)
stats = {"red duck": red(r["duck"]), "red checked": red(r["checked"]), "green duck": green(r["duck"]),
         "green checked": green(r["checked"])}
print(stats)
assert stats["green checked"] > stats["green duck"] + 20, "no passing result shown"
assert stats["red checked"] <= stats["red duck"] + 5, "the Check shows FAIL lines on the dropped model"
PY
    ;;
  *) fail "unknown case $case_name" ;;
esac
echo "ok: $case_name"
