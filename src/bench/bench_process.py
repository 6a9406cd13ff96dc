#!/usr/bin/env python3
"""Whole-process wall time: `autoblock mesh FACE` against a gmsh 4.8 all-quad run of the same face,
paired on every face (the machine is noisy: each face's two tools run back to back, alternating
which goes first, and the figure is the median of the per-face ratios).

gmsh runs as in autoblock_bench_mesh: Frontal-Delaunay for quads (Mesh.Algorithm 8, with
Mesh.CrossFieldClosestPoint = 0, it crashes otherwise in 4.8), Blossom full-quad recombination,
element size h = AutoBlock's default (1/20 of the face's longer side, read from AutoBlock's
report). Both write a .msh file. Also times `autoblock --help`.

    python3 src/bench/bench_process.py --autoblock build/bin/autoblock FOLDER [FOLDER ...]
        [--policy auto] [--policy greedy] [--repeats 3] [--limit N]

Prints Markdown.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

GMSH_SETTINGS = ("Mesh.Algorithm = 8;\nMesh.CrossFieldClosestPoint = 0;\nMesh.RecombineAll = 1;\n"
                 "Mesh.RecombinationAlgorithm = 3;\nMesh.MeshSizeFromPoints = 0;\n"
                 "Mesh.MeshSizeMin = {h:.17g};\nMesh.MeshSizeMax = {h:.17g};\n")


def timed(command):
    start = time.perf_counter()
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        raise RuntimeError("{} failed ({}): {}".format(command[0], done.returncode, done.stderr.decode()[:300]))
    return seconds


def faces_of(folder, limit):
    names = sorted(n for n in os.listdir(folder) if n.endswith((".brep", ".step", ".stp")))
    return [os.path.join(folder, n) for n in names[:limit or None]]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--autoblock", default="build/bin/autoblock")
    parser.add_argument("--gmsh", default="gmsh")
    parser.add_argument("--policy", action="append", help="policies to time (default: the default policy)")
    parser.add_argument("--repeats", type=int, default=3, help="runs per face and tool; each takes its fastest")
    parser.add_argument("--limit", type=int, default=0, help="at most this many faces per folder")
    args = parser.parse_args()
    policies = args.policy or [""]
    work = tempfile.mkdtemp(prefix="bench-process-")

    help_times = [timed([args.autoblock, "--help"]) for _ in range(10)]
    true_times = [timed(["true"]) for _ in range(10)]
    print("`autoblock --help`: median {:.3f} s over 10 runs (`true`: {:.3f} s)\n".format(
        statistics.median(help_times), statistics.median(true_times)))

    print("| faces | policy | n | AutoBlock median s | gmsh median s | median ratio AutoBlock / gmsh | "
          "faces with ratio <= 1 | max AutoBlock s | cuts by (auto) |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---|")
    for folder in args.folders:
        faces = faces_of(folder, args.limit)
        for policy in policies:
            ours, theirs, ratios, deciders = [], [], [], {}
            for k, face in enumerate(faces):
                report = os.path.join(work, "r.json")
                base = [args.autoblock, "mesh", face, "--out", os.path.join(work, "a.msh")]
                if policy:
                    base += ["--policy", policy]
                # An untimed run for the report (h, and who decided the cuts).
                subprocess.run(base + ["--json", report], check=True, stdout=subprocess.DEVNULL)
                with open(report) as f:
                    r = json.load(f)
                for who, count in r["decomposition"].get("decided_by", {}).items():
                    deciders[who] = deciders.get(who, 0) + count
                geo = os.path.join(work, "face.geo")
                with open(geo, "w") as f:
                    f.write('SetFactory("OpenCASCADE");\nMerge "{}";\n'.format(os.path.abspath(face)))
                    f.write(GMSH_SETTINGS.format(h=r["target_size"]))
                gmsh = [args.gmsh, geo, "-2", "-format", "msh41", "-o", os.path.join(work, "g.msh")]
                a, g = [], []
                for rep in range(args.repeats):
                    if (k + rep) % 2:
                        a.append(timed(base))
                        g.append(timed(gmsh))
                    else:
                        g.append(timed(gmsh))
                        a.append(timed(base))
                ours.append(min(a))
                theirs.append(min(g))
                ratios.append(min(a) / min(g))
            print("| {} | {} | {} | {:.3f} | {:.3f} | {:.2f} | {}/{} | {:.3f} | {} |".format(
                folder, policy or "default", len(faces), statistics.median(ours), statistics.median(theirs),
                statistics.median(ratios), sum(1 for x in ratios if x <= 1.0), len(ratios), max(ours),
                ", ".join("{} {}".format(k, v) for k, v in sorted(deciders.items()))))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
