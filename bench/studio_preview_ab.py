"""Two procex-studio binaries on the recipes of issue 16's Performance paragraph
(samples/city.pxg with the 18 footprints of samples/footprints/sample_block.geojson
bound, and the fig. 25 analogue samples/gallery_figure25.pxg), in one sitting:
each round runs every recipe with both binaries, their order alternating between
rounds, through bench/studio_edit_bench.py's run() (--bench-edits, --report-frames).
BENCHMARKS.md, Studio, "The preview on a thread of its own (issue 16)".

Per run, of the frames that drew something: canvas frames (the 3D preview's image
not changed) and preview frames (a new image shown), each with its own time (the UI
build and the draw up to a glFinish, the wait for an event before the frame left
out): median (90th percentile, max); their CPU time (UI thread + Mesa's rasteriser
threads), and that of the canvas frames during which no image of the preview was
being drawn (the rasteriser's threads are shared by both contexts, so the others
count the image's filling too); edit to screen (the edit until its image is on
screen); CPU per edit by thread (UI, preview thread, rasteriser, evaluation) over
the whole run; the load average at each run's start and end.

    python3 bench/studio_preview_ab.py BEFORE AFTER [ROUNDS] [EDITS]   (from the repository root)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from studio_edit_bench import run  # noqa: E402

recipes = ["samples/city.pxg", "samples/gallery_figure25.pxg"]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    binaries = {"before": sys.argv[1], "after": sys.argv[2]}
    rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    edits = int(sys.argv[4]) if len(sys.argv) > 4 else 30
    print(f"{rounds} rounds of {edits} edits; load average {os.getloadavg()[0]:.1f} at the start\n")
    print("| round | recipe | binary | canvas frames | canvas frame own time | canvas frame CPU (no preview drawn meanwhile) | "
          "preview frames | preview frame own time | preview frame CPU | edit to screen | evaluation | CPU per edit: UI, preview thread, rasteriser, evaluation | load |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for rnd in range(rounds):
        for recipe in recipes:
            for name in (["before", "after"] if rnd % 2 == 0 else ["after", "before"]):
                r = run(recipe, studio=binaries[name], edits=edits)
                c = r["cpu_per_edit"]
                print(f"| {rnd + 1} | `{recipe}` | {name} | {r['canvas_frames']} | {r['canvas_own']:.1f} ms ({r['canvas_own_p90']:.1f}, max {r['canvas_own_max']:.1f}) | "
                      f"{r['canvas_cpu']:.1f} ms ({r['canvas_lone_cpu']:.1f} ms, {r['canvas_lone_frames']} frames) | "
                      f"{r['preview_frames']} | {r['preview_own']:.1f} ms ({r['preview_own_p90']:.1f}) | {r['preview_cpu']:.1f} ms | "
                      f"{r['edit']:.1f} ms ({r['edit_p90']:.1f}) | {r['evaluation']:.1f} ms | "
                      f"{c['ui']:.1f}, {c['preview thread']:.1f}, {c['rasteriser']:.1f}, {c['evaluation']:.1f} ms | "
                      f"{r['load'][0]:.1f}-{r['load'][1]:.1f} |", flush=True)


if __name__ == "__main__":
    main()
