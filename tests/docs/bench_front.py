#!/usr/bin/env python3
"""The README's benchmark tables, made from the recorded run (docs/bench.json) and held to it.

    bench_front.py [ROOT] [--write]

Three blocks of README.md are generated, each between its markers:
  <!-- bench:front --> ... <!-- /bench:front -->    the Pareto front per scene, fastest first;
  <!-- bench:light_size --> ... <!-- /bench:light_size -->  the same frames graded against suns with a size:
                                                    the front per scene and sun, and what the sharpest
                                                    one-map shadow errs there against its error at size 0;
  <!-- bench:beyond --> ... <!-- /bench:beyond -->  per scene, where cascades (lab 12), EVSM (lab 13) and
                                                    MSM (lab 14) beat the techniques before them, and where not.
Without --write: exit 0 when README.md says what docs/bench.json says, 1 (and the expected block) when
not, 2 when a block's markers are missing. With --write: the blocks are rewritten from docs/bench.json.
After `shadowlab bench --out docs`, run it with --write; the test (docs.bench_front) runs it without.
The light_size block is made from docs/bench_light_size.json when that file exists (a later run of the
same sweep); its size-0 errors must then equal docs/bench.json's point for point (exit 1 otherwise).
"""
import json
import pathlib
import re
import statistics
import sys

args = [a for a in sys.argv[1:] if not a.startswith("--")]
ROOT = pathlib.Path(args[0]) if args else pathlib.Path(__file__).resolve().parents[2]
WRITE = "--write" in sys.argv[1:]

SIZES = (512, 1024, 2048, 4096)
SINGLE = ("hard", "pcf 1")  # one map, one tap: what a cascade's texels are measured against


def ms(p):
    return f"{p['gpu_ms']:.1f}"


def err(x):
    return f"{x:.2g}"


def ratio(x):
    return f"{x:.2f}x"


def span(values):
    lo, hi = min(values), max(values)
    return ratio(lo) if f"{lo:.2f}" == f"{hi:.2f}" else f"{lo:.2f}-{hi:.2f}x"


def label(p):
    return p["technique"] if p["technique"] == "volumes" else f"{p['technique']} {p['map_size']}"


def sizes(ns):
    ns = sorted(ns)
    if len(ns) > 1 and all(SIZES.index(b) == SIZES.index(a) + 1 for a, b in zip(ns, ns[1:])):
        return f"{ns[0]}-{ns[-1]}"
    return ", ".join(str(n) for n in ns)


def front_block(bench):
    scenes = sorted({p["scene"] for p in bench["points"]})
    rows = ["| scene | front: technique and map size (ms per frame, error), fastest first |", "|---|---|"]
    for s in scenes:
        front = sorted((p for p in bench["points"] if p["scene"] == s and p["pareto"]), key=lambda p: p["gpu_ms"])
        rows.append(f"| {s} | " + " - ".join(f"{label(p)} ({ms(p)}, {err(p['error'])})" for p in front) + " |")
    return rows


def light_size_block(bench):
    rows = ["| scene | sun | front: technique and map size (ms per frame, error), fastest first | "
            "hard 2048: error against a point sun -> against this sun (over the penumbra) |",
            "|---|---|---|---|"]
    scenes = sorted({p["scene"] for p in bench["points"]})
    suns = sorted({e["sun_deg"] for p in bench["points"] for e in p.get("light_sizes", [])})
    for s in scenes:
        for d in suns:
            pts = [(p, e) for p in bench["points"] if p["scene"] == s for e in p.get("light_sizes", []) if e["sun_deg"] == d]
            front = sorted((pe for pe in pts if pe[1]["pareto"]), key=lambda pe: pe[1].get("gpu_ms", pe[0]["gpu_ms"]))
            hard = [pe for pe in pts if pe[0]["technique"] == "hard" and pe[0]["map_size"] == 2048]
            sharp = (f"{err(hard[0][0]['error'])} -> {err(hard[0][1]['error'])} ({err(hard[0][1]['mae_penumbra'])})"
                     if hard else "not measured")
            rows.append(f"| {s} | {d:g} deg | " + " - ".join(f"{label(p)} ({ms(e if 'gpu_ms' in e else p)}, {err(e['error'])})"
                                                           for p, e in front)
                        + f" | {sharp} |")
    return rows


def on_front(points, prefix):
    names = [label(p) for p in sorted(points, key=lambda p: p["gpu_ms"]) if p["pareto"] and p["technique"].startswith(prefix)]
    return "on the front: " + ", ".join(names) if names else "not on the front"


def compare(new, old):
    """Per map size, new's error over old's: (sizes where new errs less, their ratios, sizes where more, theirs)."""
    win, win_r, lose, lose_r = [], [], [], []
    for n in SIZES:
        if n in new and n in old:
            r = new[n] / old[n]
            (win if r < 1 else lose).append(n)
            (win_r if r < 1 else lose_r).append(r)
    return win, win_r, lose, lose_r


def verdict(win, win_r, lose, lose_r):
    parts = []
    if win:
        parts.append(f"**errs less** at {sizes(win)} ({span(win_r)} the error)")
    if lose:
        parts.append(f"errs more at {sizes(lose)} ({span(lose_r)})")
    return "; ".join(parts)


def beyond_block(bench):
    scenes = sorted({p["scene"] for p in bench["points"]})
    rows = ["| scene | cascades (csm 2, csm 4) against one map (hard, pcf 1) at the same texels | "
            "EVSM against VSM (same blur radius and map; the range is over all pairs) | "
            "MSM against VSM r0 (same map) |",
            "|---|---|---|---|"]
    for s in scenes:
        pts = [p for p in bench["points"] if p["scene"] == s]
        by = {}
        for p in pts:
            by.setdefault(p["technique"], {})[p["map_size"]] = p

        def best(techniques):
            out = {}
            for n in SIZES:
                errs = [by[t][n]["error"] for t in techniques if t in by and n in by[t]]
                if errs:
                    out[n] = min(errs)
            return out

        csm = verdict(*compare(best(["csm 2", "csm 4"]), best(SINGLE)))
        csm += "; " + on_front(pts, "csm")

        lower, total, e_r, t_r = 0, 0, [], []
        for t in by:
            if t.startswith("evsm "):
                v = "vsm " + t.split()[1]
                for n, p in by[t].items():
                    if v in by and n in by[v]:
                        total += 1
                        lower += p["error"] < by[v][n]["error"]
                        e_r.append(p["error"] / by[v][n]["error"])
                        t_r.append(p["gpu_ms"] / by[v][n]["gpu_ms"])
        evsm = (f"errs less in {lower} of {total} pairs ({span(e_r)} the error) at "
                f"{ratio(statistics.median(t_r))} the time (median); " + on_front(pts, "evsm"))

        msm_w, msm_wr, msm_l, msm_lr = compare({n: p["error"] for n, p in by.get("msm", {}).items()},
                                               {n: p["error"] for n, p in by.get("vsm r0", {}).items()})
        m_t = [by["msm"][n]["gpu_ms"] / by["vsm r0"][n]["gpu_ms"] for n in by.get("msm", {}) if n in by.get("vsm r0", {})]
        msm = verdict(msm_w, msm_wr, msm_l, msm_lr) + f", at {ratio(statistics.median(m_t))} the time (median); " + on_front(pts, "msm")
        rows.append(f"| {s} | {csm} | {evsm} | {msm} |")
    return rows


def main():
    bench = json.loads((ROOT / "docs" / "bench.json").read_text(encoding="utf-8"))
    readme_path = ROOT / "README.md"
    readme = readme_path.read_text(encoding="utf-8")
    blocks = {"front": front_block(bench), "beyond": beyond_block(bench)}
    # The fronts per light size come from their own run (docs/bench_light_size.json) when there is one:
    # the same sweep, graded also against suns with a size. Its size-0 errors must be bench.json's, point
    # for point (errors do not depend on the machine's load; the soft grading changes nothing at size 0).
    sized_path = ROOT / "docs" / "bench_light_size.json"
    sized = json.loads(sized_path.read_text(encoding="utf-8")) if sized_path.exists() else bench
    status = 0
    if sized is not bench:
        key = lambda p: (p["scene"], p["technique"], p.get("map_size"))
        errors = {key(p): p["error"] for p in sized["points"]}
        shared = [p for p in bench["points"] if key(p) in errors]
        differ = [key(p) for p in shared if errors[key(p)] != p["error"]]
        if differ or len(shared) != len(bench["points"]):
            print(f"docs/bench_light_size.json: {len(differ)} of {len(shared)} shared points err differently at size 0 "
                  f"from docs/bench.json, {len(bench['points']) - len(shared)} missing: {differ[:5]}")
            status = 1
    if any("light_sizes" in p for p in sized["points"]):  # runs recorded before light sizes have none
        blocks["light_size"] = light_size_block(sized)
    for name, rows in blocks.items():
        pattern = re.compile(r"(<!-- bench:" + name + r" -->\n)(.*?)(<!-- /bench:" + name + r" -->)", re.DOTALL)
        m = pattern.search(readme)
        if not m:
            print(f"README.md: the block <!-- bench:{name} --> ... <!-- /bench:{name} --> is missing")
            return 2
        want = "\n".join(rows) + "\n"
        if m.group(2) != want:
            if WRITE:
                readme = readme[:m.start(2)] + want + readme[m.end(2):]
            else:
                print(f"README.md: the block bench:{name} does not say what docs/bench.json says; expected:\n{want}"
                      f"(run tests/docs/bench_front.py --write after a new `shadowlab bench --out docs`)")
                status = 1
    if WRITE:
        readme_path.write_text(readme, encoding="utf-8")
    else:
        print(f"README.md's benchmark blocks agree with docs/bench.json ({len(bench['points'])} points)" if status == 0 else "")
    return status


if __name__ == "__main__":
    sys.exit(main())
