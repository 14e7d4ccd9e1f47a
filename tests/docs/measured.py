#!/usr/bin/env python3
"""The recorded runs the instructor notes quote: made by one command, replayed by a test.

    measured.py record BINARY [ROOT] [LAB...]
                                        run every lab's (or the given labs') check (solution and stock exercise) and the
                                        variants below; write docs/measured/lab_NN.json
    measured.py selftest BINARY [ROOT]  prove replay fails on a quoted figure the code no longer gives
    measured.py replay BINARY [ROOT] [LAB...]
                                        run them again and compare with the committed JSON: every
                                        deterministic figure a text quotes (a marker
                                        `<!-- @ lab_NN.json:/json/pointer*scale -->`, see lab_texts.py)
                                        must still print the same; timings are not compared

Each docs/measured/lab_NN.json holds {"recorded": {command, date, version, commit, gl}, "runs": {name:
{"command": [...], "result": ...}}}. A run is a `shadowlab check` (its JSON report for the lab) or a
`shadowlab render` (its render.json). Check values are deterministic on llvmpipe (the renderer and the
ray-cast oracle are); times are not: a key ending in `_ms`, `seconds` or `ms` anywhere, and a render's
`stats`, are timings. A timing is quoted from the JSON as recorded (the JSON says when and where) and
never compared with a new run.
"""
import datetime
import json
import os
import pathlib
import platform
import re
import subprocess
import sys
import tempfile

SEED = 1

# Lab 3's GL exercise: the corpus's wrong answers whose probe reads the lab's texts quote.
LAB3_GL_ANSWERS = ("rgba8_moments", "half_float_moments", "nearest_filter", "no_depth_buffer", "clear_black", "repeat_wrap")

# Runs beyond each lab's solution and stock exercise: (lab, name, subcommand, extra arguments).
VARIANTS = [
    # Lab 1: a constant bias alone, swept with the stock exercise's formula at the check's light.
    *[(1, f"exercise_constant_{c}", "check", ["--impl", "exercise", "--set", f"shadow.bias={c}"])
      for c in ("0.0005", "0.002", "0.005", "0.01", "0.02", "0.04")],
    # Lab 1: the solution's formula with front (or back) faces culled in the shadow pass. Lab 1 takes the
    # culling from the #define SHADOW_PASS_CULL line of the graded file, which overrides --set shadow.cull,
    # so these are submissions: the solution with that one line changed (see SUBMISSIONS).
    *[(1, f"solution_cull_{cull}_slope_{k}", "submission", [f"cull_{cull}", "--set", f"shadow.slope_bias={k}"])
      for cull, k in (("front", "1"), ("front", "2"), ("back", "2"))],
    # Lab 1: the lecture's bias max(0.05 (1 - n.l), 0.005) as written (COURSE.md, "Artifacts and fixes"),
    # graded as a submission: why a course-faithful answer fails here (README.md quotes it).
    (1, "lecture_formula", "submission", ["lecture_formula"]),
    # Lab 3: the minimum variance swept (the solution; the check's oracle case), and half floats.
    *[(3, f"solution_min_variance_{v}", "check", ["--impl", "solution", "--set", f"vsm.min_variance={v}"])
      for v in ("1e-7", "1e-5", "1e-4", "1e-3")],
    (3, "solution_rg16f", "check", ["--impl", "solution", "--set", "vsm.format=RG16F"]),
    # Lab 3: the GL exercise's wrong answers the text quotes (LAB3_GL_ANSWERS, below).
    *[(3, f"gl_{answer}", "submission", [f"vsm_gl_{answer}"]) for answer in LAB3_GL_ANSWERS],
    # Lab 13: each exponent swept (the solution), and the positive warp's bound alone (two-moment EVSM).
    *[(13, f"solution_exponent_{c}", "check", ["--impl", "solution", "--set", f"vsm.evsm_exponent={c}"])
      for c in ("5", "10", "20")],
    *[(13, f"solution_negative_exponent_{c}", "check", ["--impl", "solution", "--set", f"vsm.evsm_negative_exponent={c}"])
      for c in ("1", "5", "20")],
    (13, "positive_bound_only", "submission", ["evsm2"]),
    # Lab 14: the bound the wrong way round (the weight at the receiver counted in front) and Cramer's rule
    # in float32, the corpus's answers as they are.
    (14, "upper_bound", "submission", ["msm_upper"]),
    (14, "cramer_in_float", "submission", ["msm_cramer"]),
    # Lab 12: the cascade count and the split blend varied (the solution): where cascades win.
    *[(12, f"solution_count_{n}", "check", ["--impl", "solution", "--set", f"csm.count={n}"]) for n in ("1", "2", "8")],
    *[(12, f"solution_lambda_{l}", "check", ["--impl", "solution", "--set", f"csm.lambda={l}"]) for l in ("0", "0.5", "1")],
    # Lab 15: two of the corpus's answers as they are: a near and far typed in (every frame right on the
    # lab's scene, only the probes' other boxes show it) and lookAt with up = +Y (only straight down).
    (15, "fixed_near_far", "submission", ["flash_fixed"]),
    (15, "lookat_up_y", "submission", ["flash_lookat"]),
    # Lab 17: the corpus's answers that each fail one criterion alone (the range check, the kernel's scale),
    # as they are: the instructor notes quote their values against the limits.
    *[(17, answer, "submission", [f"ssao_{answer}"])
      for answer in ("no_range_check", "range_check_inverted", "unscaled_radius", "samples_on_shell")],
]

# A "submission" run's first argument names one of these: {exercise slot: (the project file it is made
# from, the line replaced, its replacement)}, graded with `check --submission` (a folder laid out like the
# project; it holds the edited slots only).
SUBMISSIONS = {
    f"cull_{cull}": {"labs/01_bias_tuning/exercise.glsl": ("labs/01_bias_tuning/solution.glsl",
                                                          "#define SHADOW_PASS_CULL NONE",
                                                          f"#define SHADOW_PASS_CULL {cull.upper()}")}
    for cull in ("front", "back")
}
# Lab 13's two-moment EVSM: the corpus's answer that takes the positive warp's bound alone, as it is.
SUBMISSIONS["evsm2"] = {"labs/13_evsm/exercise.glsl": (
    "tests/answers/13_evsm/wrong/positive_bound_only__exercise.glsl", "  float mu = moments.x;", "  float mu = moments.x;")}
SUBMISSIONS["msm_upper"] = {"labs/14_msm/exercise.glsl": (
    "tests/answers/14_msm/wrong/counts_receiver_point__exercise.glsl", "  vec3 c = vec3(1.0, z, z * z);",
    "  vec3 c = vec3(1.0, z, z * z);")}
SUBMISSIONS["msm_cramer"] = {"labs/14_msm/exercise.glsl": (
    "tests/answers/14_msm/wrong/cramer_in_float__exercise.glsl", "  vec3 rhs = vec3(1.0, z, z * z);",
    "  vec3 rhs = vec3(1.0, z, z * z);")}
SUBMISSIONS["flash_fixed"] = {"labs/15_two_lights/exercise.cpp": (
    "tests/answers/15_two_lights/wrong/fixed_near_far__exercise.cpp", "  LightView v;", "  LightView v;")}
SUBMISSIONS["flash_lookat"] = {"labs/15_two_lights/exercise.cpp": (
    "tests/answers/15_two_lights/wrong/lookat_up_y__exercise.cpp", "  LightView v;", "  LightView v;")}
# Lab 17's wrong answers, taken as they are (their first code line kept).
for _answer in ("no_range_check", "range_check_inverted", "unscaled_radius", "samples_on_shell"):
    SUBMISSIONS[f"ssao_{_answer}"] = {"labs/17_ssao/exercise.glsl": (
        f"tests/answers/17_ssao/wrong/{_answer}__exercise.glsl",
        "float ssao_open(vec3 p, vec3 n, vec3 noise, float radius, float bias, bool range_check) {",
        "float ssao_open(vec3 p, vec3 n, vec3 noise, float radius, float bias, bool range_check) {")}
# Lab 3's GL exercise: the corpus's answers whose mistakes the text describes in the probe's reads, as they
# are (their line `target.size = size;` kept), with the solution's shaders in the two GLSL slots.
for _answer in LAB3_GL_ANSWERS:
    SUBMISSIONS[f"vsm_gl_{_answer}"] = {
        "labs/03_vsm_setup/gl_moments_target.cpp": (f"tests/answers/03_vsm_setup/wrong/{_answer}__gl_moments_target.cpp",
                                                    "  target.size = size;", "  target.size = size;"),
        "labs/03_vsm_setup/exercise_moments.glsl": ("shaders/vsm/moments.glsl", "const float SLOPE_VARIANCE_FACTOR",
                                                    "const float SLOPE_VARIANCE_FACTOR"),
        "labs/03_vsm_setup/exercise_chebyshev.glsl": ("shaders/vsm/chebyshev.glsl", "// Chebyshev's one-sided",
                                                      "// Chebyshev's one-sided")}
# The corpus's copy of the lecture's formula, taken as it is (its culling line kept).
SUBMISSIONS["lecture_formula"] = {"labs/01_bias_tuning/exercise.glsl": (
    "tests/answers/01_bias_tuning/wrong/learnopengl_literal__exercise.glsl", "#define SHADOW_PASS_CULL NONE",
    "#define SHADOW_PASS_CULL NONE")}


def make_submission(root, name, folder):
    """The submission folder for SUBMISSIONS[name], and how it was made (kept in the record)."""
    made = {}
    for slot, (source, line, replacement) in SUBMISSIONS[name].items():
        text = (root / source).read_text()
        if line not in text:
            raise RuntimeError(f"{source}: no line {line!r} to replace for the submission {name}")
        target = folder / slot
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text.replace(line, replacement, 1))
        made[slot] = f"{source} with {line!r} replaced by {replacement!r}"
    return made


def lab_folders(root):
    return {int(p.name[:2]): p.name for p in sorted((root / "labs").glob("[0-9][0-9]_*")) if (p / "lab.cpp").exists()}


def is_timing(key):
    return key in ("seconds", "stats") or "ms" in key.split("_")


def deterministic(value):
    """The value with every timing removed."""
    if isinstance(value, dict):
        return {k: deterministic(v) for k, v in value.items() if not is_timing(k)}
    if isinstance(value, list):
        return [deterministic(v) for v in value]
    return value


def run_check(binary, lab, args, out):
    report = pathlib.Path(out) / "report.json"
    command = ["check", "--lab", str(lab), "--seed", str(SEED), "--json", str(report), *args]
    done = subprocess.run([str(binary), *command], capture_output=True, text=True)
    if done.returncode not in (0, 1) or not report.exists():
        raise RuntimeError(f"shadowlab {' '.join(command)}: exit {done.returncode}\n{done.stdout}{done.stderr}")
    return command, json.loads(report.read_text())["labs"][0]


def run_render(binary, lab, args, out):
    command = ["render", "--lab", str(lab), "--out", str(out), *args]
    done = subprocess.run([str(binary), *command], capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"shadowlab {' '.join(command)}: exit {done.returncode}\n{done.stdout}{done.stderr}")
    return command, json.loads((pathlib.Path(out) / "render.json").read_text())


def runs_for(lab):
    yield "solution", "check", ["--impl", "solution"]
    yield "exercise", "check", ["--impl", "exercise"]
    for number, name, kind, args in VARIANTS:
        if number == lab:
            yield name, kind, args


def record_lab(binary, lab, root):
    runs = {}
    for name, kind, args in runs_for(lab):
        made = None
        with tempfile.TemporaryDirectory() as tmp:
            if kind == "submission":
                made = make_submission(root, args[0], pathlib.Path(tmp) / "submission")
                args = ["--submission", str(pathlib.Path(tmp) / "submission"), *args[1:]]
            command, result = (run_render if kind == "render" else run_check)(binary, lab, args, tmp)
        # The outputs' (and a submission's) temporary folder is no part of the record.
        command = [c for c in command if not c.startswith(tempfile.gettempdir())]
        if kind != "render":
            result.pop("images", None)
        runs[name] = {"command": ["shadowlab", *command], "result": result}
        if made:
            runs[name]["submission"] = made
        print(f"lab {lab} {name}: {result.get('status', 'rendered')}", flush=True)
    return runs


def blur_cost_fit(result):
    """Lab 5's blur time per pass against its taps (2 radius + 1): a least-squares line over the check's
    radii (a timing, like the times it is fitted to)."""
    points = [(2 * r["radius"] + 1, (r["gpu_ms_blur_x"] + r["gpu_ms_blur_y"]) / 2)
              for r in result["metrics"]["blur"]["radii"] if r["case"].startswith("radius")]
    n = len(points)
    mx = sum(x for x, _ in points) / n
    my = sum(y for _, y in points) / n
    slope = sum((x - mx) * (y - my) for x, y in points) / sum((x - mx) ** 2 for x, _ in points)
    return {"per_tap": slope, "fixed": my - slope * mx, "taps": [x for x, _ in points]}


# A receiver this far from the spot light, for lab 7's worked example of a constant window-depth bias.
SPOT_EXAMPLE_DISTANCE = 8.0


def spot_constant_shift(result, constant):
    """Lab 7: where a constant bias in window depth moves the comparison, at the low place's near and far,
    for a receiver SPOT_EXAMPLE_DISTANCE away: the exact depth z' with d(z') = d(z) - constant, where
    d(z) = f/(f-n) (1 - n/z), and the small-step estimate constant z^2 (f-n)/(f n)."""
    light = result["metrics"]["low"]["light"]
    n, f, z = light["near"], light["far"], SPOT_EXAMPLE_DISTANCE
    d = f / (f - n) * (1 - n / z) - constant
    exact = n / (1 - d * (f - n) / f)
    return {"distance": z, "near": n, "far": f, "constant": constant, "exact_depth": exact,
            "exact_shift": z - exact, "small_step_shift": constant * z * z * (f - n) / (f * n)}


def derive(lab, runs):
    """Figures computed from a lab's runs (kept beside them, replayed with them)."""
    if lab == 5:
        return {"blur_cost_ms": blur_cost_fit(runs["solution"]["result"])}
    if lab == 7:
        exercise = runs["exercise"]["result"]
        return {"constant_shift": spot_constant_shift(exercise, exercise["parameters"]["shadow.bias"])}
    return {}


def recorded_block(binary, root):
    version = subprocess.run([str(binary), "--version"], capture_output=True, text=True).stdout.strip()
    commit = subprocess.run(["git", "-C", str(root), "describe", "--always", "--dirty"], capture_output=True, text=True).stdout.strip()
    gl = ""
    with tempfile.TemporaryDirectory() as tmp:
        try:
            gl = run_render(binary, 0, ["--width", "64", "--height", "64"], tmp)[1]["gl"]["renderer"]
        except (RuntimeError, KeyError):
            pass
    return {"command": "python3 tests/docs/measured.py record build/app/shadowlab",
            "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
            "version": version.splitlines()[0] if version else "", "commit": commit, "gl": gl,
            "machine": f"{platform.machine()}, {os.cpu_count()} cores", "seed": SEED,
            "timings": "keys ending in _ms, 'seconds', 'ms' and a render's 'stats' are timings from this run; "
                       "everything else is deterministic and replayed by CTest docs.measured_replay"}


def record(binary, root, only=None):
    folder = root / "docs" / "measured"
    folder.mkdir(parents=True, exist_ok=True)
    block = recorded_block(binary, root)
    for lab in lab_folders(root):
        if only and lab not in only:
            continue
        data = {"recorded": block, "runs": record_lab(binary, lab, root)}
        derived = derive(lab, data["runs"])
        if derived:
            data["derived"] = derived
        (folder / f"lab_{lab:02d}.json").write_text(json.dumps(data, indent=1, sort_keys=True) + "\n")
    return 0


def quoted(root):
    """Every measured marker in the texts: (where, printed, file, pointer, scale)."""
    sys.path.insert(0, str(pathlib.Path(__file__).parent))
    import lab_texts
    lab_texts.ROOT = root
    return list(lab_texts.measured_markers())


def replay(binary, root, only=None):
    import lab_texts
    folder = root / "docs" / "measured"
    markers = quoted(root)
    # The lab records; a marker may also quote another recorded run (../bench.json: the benchmark's,
    # all timings), which is not replayed here.
    files = sorted({m[2] for m in markers if re.fullmatch(r"lab_\d+\.json", m[2])
                    and (not only or int(m[2][4:6]) in only)})
    problems, compared = [], 0
    for file in files:
        lab = int(re.match(r"lab_(\d+)\.json", file).group(1))
        old = json.loads((folder / file).read_text())
        new = {"runs": record_lab(binary, lab, root)}
        new["derived"] = derive(lab, new["runs"])
        for where, printed, _, pointer, scale in (m for m in markers if m[2] == file):
            parts = pointer.strip("/").split("/")
            if any(is_timing(p) for p in parts):
                continue
            try:
                value = lab_texts.number(lab_texts.resolve(new, pointer), pointer) * scale
            except (KeyError, IndexError, ValueError, TypeError, LookupError) as e:
                problems.append(f"{where}: {file}:{pointer} is not in the new run ({e!r})")
                continue
            compared += 1
            if not lab_texts.agrees(printed, value):
                problems.append(f"{where}: the text (and {file}) say {printed}, the current code gives {value:g} "
                                f"(record again: {old['recorded']['command']})")
        if deterministic(old["runs"]) != deterministic(new["runs"]):
            print(f"note: {file}: some unquoted deterministic value changed since it was recorded")
    for p in problems:
        print(p)
    print(f"{compared} quoted figures replayed from {len(files)} recorded files, {len(problems)} disagreements")
    return 1 if problems else 0


def selftest(binary, root):
    """replay must fail when the code no longer gives a quoted figure: a copy of the texts and records
    where one figure of lab 0 (text and record alike, so docs.lab_texts still passes) was changed."""
    import shutil
    sys.path.insert(0, str(pathlib.Path(__file__).parent))
    import lab_texts_selftest
    lab_texts_selftest.ROOT = root
    quote = "795<!-- @ lab_00.json:/runs/exercise/result/metrics/probe/wrong_inside -->"
    with tempfile.TemporaryDirectory() as tmp:
        copy = pathlib.Path(tmp)
        lab_texts_selftest.copy_texts(tmp)
        notes = copy / "labs" / "00_basic_shadow_map" / "INSTRUCTOR.md"
        record = copy / "docs" / "measured" / "lab_00.json"
        text, data = notes.read_text(), json.loads(record.read_text())
        if quote not in text:
            print("measured selftest: the quoted figure is gone from lab 0's INSTRUCTOR.md: update the self-test")
            return 1
        notes.write_text(text.replace(quote, quote.replace("795", "796", 1)))
        data["runs"]["exercise"]["result"]["metrics"]["probe"]["wrong_inside"] = 796.0
        record.write_text(json.dumps(data, indent=1, sort_keys=True) + "\n")
        texts = subprocess.run([sys.executable, str(pathlib.Path(__file__).with_name("lab_texts.py")), tmp],
                               capture_output=True, text=True)
        if texts.returncode != 0:
            print("measured selftest: the changed copy should still agree with itself:\n" + texts.stdout)
            return 1
        out = subprocess.run([sys.executable, __file__, "replay", str(binary), tmp, "0"], capture_output=True, text=True)
        if out.returncode != 1 or "say 796, the current code gives 795" not in out.stdout:
            print(f"measured selftest: replay did not catch a quoted figure the code no longer gives "
                  f"(exit {out.returncode}):\n{out.stdout}{out.stderr}")
            return 1
    print("replay caught a quoted figure the current code no longer gives")
    return 0


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("record", "replay", "selftest"):
        print(__doc__, file=sys.stderr)
        return 2
    binary = pathlib.Path(sys.argv[2]).resolve()
    root = pathlib.Path(sys.argv[3]).resolve() if len(sys.argv) > 3 else pathlib.Path(__file__).resolve().parents[2]
    labs = {int(n) for n in sys.argv[4:]}
    if sys.argv[1] == "record":
        return record(binary, root, labs)
    if sys.argv[1] == "selftest":
        return selftest(binary, root)
    return replay(binary, root, labs)


if __name__ == "__main__":
    sys.exit(main())
