# Solids split across the sweep, for `autoblock mesh`: each face of a folder written by `autoblock
# generate` extruded in two to four slabs at random heights (FreeCAD's Face.extrude) and fused without
# refining (Shape.fuse: the side faces stay split where the slabs meet), and the same solid refined
# (removeSplitter), as OUT/<kind>_<n>.brep and OUT/<kind>_<n>_refined.brep.
#
#   freecadcmd -c "import sys; sys.argv = ['fused_solids.py', 'GENERATED', 'OUT', 'SEED']; \
#                  exec(open('src/bench/fused_solids.py').read())"
#
# GENERATED holds one folder per kind (rectangles, polygon, arcs...), each autoblock generate's
# output; every solid is swept by 0.2-0.8 of its face's longer side. Then, with python3 (no FreeCAD):
#
#   python3 src/bench/fused_solids.py --report OUT AUTOBLOCK
#
# meshes every solid with `AUTOBLOCK mesh FILE --json` (defaults, one after the other, whole-process
# wall time) and prints BENCHMARKS.md's table: fused against refined, per kind and in all.
import glob
import json
import os
import statistics
import subprocess
import sys
import time


def make(generated, out, seed):
    import random

    import FreeCAD as App
    import Part

    V = App.Vector
    rng = random.Random(seed)
    os.makedirs(out, exist_ok=True)
    count = 0
    for folder in sorted(glob.glob(os.path.join(generated, "*"))):
        kind = os.path.basename(folder)
        for path in sorted(glob.glob(os.path.join(folder, "shape_*.brep"))):
            shape = Part.Shape()
            shape.read(path)
            face = shape.Faces[0]
            box = face.BoundBox
            height = max(box.XLength, box.YLength) * rng.uniform(0.2, 0.8)
            cuts = sorted(rng.uniform(0.1, 0.9) for _ in range(rng.randint(1, 3)))
            levels = [0.0] + [c * height for c in cuts] + [height]
            slabs = [face.translated(V(0, 0, levels[i])).extrude(V(0, 0, levels[i + 1] - levels[i]))
                     for i in range(len(levels) - 1)]
            solid = slabs[0]
            for slab in slabs[1:]:
                solid = solid.fuse(slab)
            name = "%s_%s" % (kind, os.path.basename(path)[len("shape_"):-len(".brep")])
            solid.exportBrep(os.path.join(out, name + ".brep"))
            solid.removeSplitter().exportBrep(os.path.join(out, name + "_refined.brep"))
            count += 1
    print("%d solids, fused and refined, in %s" % (count, out))


def report(out, autoblock):
    runs = {}
    for path in sorted(glob.glob(os.path.join(out, "*.brep"))):
        name = os.path.basename(path)[:-len(".brep")]
        target = os.path.join(out, name + ".json")
        start = time.perf_counter()
        done = subprocess.run([autoblock, "mesh", path, "--json", target], stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True)
        seconds = time.perf_counter() - start
        if done.returncode != 0:
            print("%s: exit %d: %s" % (name, done.returncode, done.stderr.strip()))
            continue
        with open(target) as f:
            runs[name] = (json.load(f), seconds)
    names = sorted(n for n in runs if not n.endswith("_refined") and n + "_refined" in runs)
    print("| faces | solids | fused: meshed, conformal | refined: meshed, conformal | mean min SJ fused | refined | "
          "same min SJ | mean hexahedra fused | refined | layers fused / refined | median ms fused | refined | "
          "median time fused / refined |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    kinds = sorted({n.rsplit("_", 1)[0] for n in names})
    for kind in kinds + [None]:
        rows = [n for n in names if kind is None or n.rsplit("_", 1)[0] == kind]
        if not rows:
            continue
        a = [runs[n][0] for n in rows]
        b = [runs[n + "_refined"][0] for n in rows]
        sj = lambda r: r["quality"]["min_scaled_jacobian"]
        print("| %s | %d | %d/%d | %d/%d | %.4f | %.4f | %d | %.0f | %.0f | %.2f | %.1f | %.1f | %.2f |" % (
            kind or "all", len(rows), sum(r["conformal"] for r in a), len(rows), sum(r["conformal"] for r in b),
            len(rows), statistics.mean(map(sj, a)), statistics.mean(map(sj, b)),
            sum(abs(sj(x) - sj(y)) < 1e-9 for x, y in zip(a, b)), statistics.mean(r["hexahedra"] for r in a),
            statistics.mean(r["hexahedra"] for r in b),
            statistics.mean(r["layers"] for r in a) / statistics.mean(r["layers"] for r in b),
            1000 * statistics.median(runs[n][1] for n in rows), 1000 * statistics.median(runs[n + "_refined"][1] for n in rows),
            statistics.median(runs[n][1] / runs[n + "_refined"][1] for n in rows)))


if len(sys.argv) >= 4 and sys.argv[1] == "--report":
    report(sys.argv[2], sys.argv[3])
elif len(sys.argv) >= 3:
    make(sys.argv[1], sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 2055)
else:
    print(__doc__ if __doc__ else "usage: see the comment at the top of fused_solids.py")
