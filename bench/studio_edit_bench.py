"""The studio's frame time and re-evaluation latency on the sample recipes
(BENCHMARKS.md, "Studio"): each recipe opened in procex-studio under Xvfb
with --bench-edits, which sets the recipe's first ranged float parameter (or,
when the recipe has none, that of the first group's nodes, edited inside the
group) to a new value (nothing comes from the cache) and times each edit until
the frame showing its result is swapped and glFinish'ed. samples/city.pxg runs
with the 18 footprints of samples/footprints/sample_block.geojson bound
(--footprints: every feature evaluated and shown at its place). Rounds run the recipes
in turn; per recipe, the medians over rounds of each run's median (and 90th
percentile), and the edit latency as a ratio to the house's in the same round.
Frame time counts only frames that drew something (an unchanged frame is
neither drawn nor shown), from the frame that showed the first image on (the
start-up left out). Those split into canvas frames (the edited value,
the status bar: the 3D preview not redrawn) and preview frames (the new
buildings drawn), each with its wall time and its CPU time: the UI thread's
plus the software rasteriser's threads' (Mesa's llvmpipe), which on a loaded
machine is what the frame cost, the rest being waits for a core. The load
average at the start and end of the rounds is printed.

    python3 bench/studio_edit_bench.py [ROUNDS] [EDITS]   (from the repository root)

PROCEX_STUDIO names the binary (default build/app/studio/procex-studio).
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile

studio = os.environ.get("PROCEX_STUDIO", "build/app/studio/procex-studio")
reference = "samples/house.pxg"
block = "samples/footprints/sample_block.geojson"
recipes = [reference, "samples/barn.pxg", "samples/gallery_figure25.pxg",
           "tests/studio/data/street100.pxg", "samples/city.pxg"]
footprints = {"samples/city.pxg": block}


def p90(xs):
    return sorted(xs)[min(len(xs) - 1, int(0.9 * len(xs)))]


def run(recipe, studio=studio, edits=40):
    """One run of `studio` on `recipe`: the medians (90th percentiles) of the frame report."""
    with tempfile.TemporaryDirectory() as tmp:
        report = os.path.join(tmp, "frames.json")
        env = dict(os.environ, PROCEX_STUDIO_HOME=os.path.join(tmp, "home"), XDG_CONFIG_HOME=os.path.join(tmp, "config"))
        bind = ["--footprints", footprints[recipe]] if recipe in footprints else []
        subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x800x24", studio, recipe, "--bench-edits", str(edits),
                        "--report-frames", report, "--timeout", "300"] + bind, check=True, env=env, capture_output=True)
        with open(report) as f:
            r = json.load(f)
    if not r["edit_to_screen_ms"]:
        sys.exit(f"{recipe}: no parameter to edit")
    if recipe in footprints and r["preview_features"] != 18:
        sys.exit(f"{recipe}: {r['preview_features']} of the 18 footprints evaluated")
    # Preview frames: those that showed a new image of the preview. A studio that draws the preview on a
    # thread of its own says which (preview_shown); before that, they were those that issued its drawing.
    shown = r["preview_shown"] if "preview_shown" in r else [ms > 0 for ms in r["preview_cpu_ms"]]
    # The frames from the one that showed the first image on: those before it are the start-up's (fonts,
    # shaders compiled, the first evaluation), and the edits begin once the first image is shown.
    start = shown.index(True) if True in shown else 0
    # Frames in which nothing changed are neither drawn nor swapped: a new frame is one that drew something.
    drawn = [ms for ms, share in zip(r["frame_ms"][start:], r["redrawn_share"][start:]) if share > 0]
    # Frames during which the preview's thread drew an image: the rasteriser's threads are shared by
    # the window's and the preview's contexts, so their CPU time in such a frame counts the image's too.
    overlapped = r.get("preview_drawing", [False] * len(shown))
    # A frame's own time: the UI build and the draw up to a glFinish, without the wait for an event
    # that a frame begins with (frame_ms counts it).
    frames = list(zip(r["frame_ms"], r["redrawn_share"], shown, r["frame_cpu_ms"], r["rasteriser_cpu_ms"], r["ui_build_ms"], r["draw_ms"], overlapped))[start:]
    canvas = [f for f in frames if f[1] > 0 and not f[2]]
    preview = [f for f in frames if f[1] > 0 and f[2]]
    med = lambda fs, k: statistics.median(k(f) for f in fs) if fs else float("nan")
    pct = lambda fs, k: p90([k(f) for f in fs]) if fs else float("nan")
    own = lambda f: f[5] + f[6]
    cpu = lambda f: f[3] + f[4]
    lone = [f for f in canvas if not f[7]]
    done = len(r["edit_to_screen_ms"])
    per_edit = lambda prefix: sum(t["cpu_ms"] for name, t in r["threads"].items() if name.startswith(prefix)) / done
    return {"parameter": r["parameter"], "bound": r["preview_features"] or "none", "edit": statistics.median(r["edit_to_screen_ms"]), "edit_p90": p90(r["edit_to_screen_ms"]),
            "evaluation": statistics.median(r["evaluation_ms"]), "frame": statistics.median(drawn), "frame_p90": p90(drawn),
            "canvas": med(canvas, lambda f: f[0]), "canvas_cpu": med(canvas, cpu),
            "preview": med(preview, lambda f: f[0]), "preview_cpu": med(preview, cpu), "load": r["load_average"],
            "canvas_frames": len(canvas), "canvas_own": med(canvas, own), "canvas_own_p90": pct(canvas, own), "canvas_own_max": max(map(own, canvas), default=float("nan")),
            "canvas_lone_frames": len(lone), "canvas_lone_cpu": med(lone, cpu),
            "preview_frames": len(preview), "preview_own": med(preview, own), "preview_own_p90": pct(preview, own),
            "cpu_per_edit": {"ui": per_edit("procex-studio"), "preview thread": per_edit("procex-preview"), "rasteriser": per_edit("llvmpipe-"),
                             "evaluation": per_edit("procex-eval")}}


def main():
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    edits = int(sys.argv[2]) if len(sys.argv) > 2 else 40
    load_start = os.getloadavg()[0]
    results = {r: [] for r in recipes}
    ratios = {r: [] for r in recipes}
    for _ in range(rounds):
        this_round = {r: run(r, edits=edits) for r in recipes}
        for r in recipes:
            results[r].append(this_round[r])
            ratios[r].append(this_round[r]["edit"] / this_round[reference]["edit"])

    print(f"{rounds} rounds of {edits} edits; medians over rounds (90th percentiles in brackets); load average {load_start:.1f} at the start, {os.getloadavg()[0]:.1f} at the end\n")
    print("| recipe | nodes | footprints bound | parameter edited | edit to screen | evaluation of the edit | new frame | canvas frame: wall, CPU | preview frame: wall, CPU | edit to screen / house's |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in recipes:
        with open(r) as f:
            nodes = len(json.load(f)["nodes"])
        m = lambda k: statistics.median(x[k] for x in results[r])
        print(f"| `{r}` | {nodes} | {results[r][0]['bound']} | `{results[r][0]['parameter']}` | {m('edit'):.1f} ms ({m('edit_p90'):.1f}) | {m('evaluation'):.1f} ms | "
              f"{m('frame'):.1f} ms ({m('frame_p90'):.1f}) | {m('canvas'):.1f}, {m('canvas_cpu'):.1f} ms | {m('preview'):.1f}, {m('preview_cpu'):.1f} ms | "
              f"{statistics.median(ratios[r]):.2f} ({min(ratios[r]):.2f}-{max(ratios[r]):.2f}) |")


if __name__ == "__main__":
    main()
