#!/usr/bin/env python3
"""Policies side by side on folders of faces, through `autoblock eval` (one thread, in-process
seconds), each policy scored with the mesh preset: mean blocks / minimum blocks, mean return, the
median and largest seconds per face, completion, time-limit hits and who decided the cuts.

    python3 src/bench/compare_policies.py --autoblock build/bin/autoblock FOLDER [FOLDER ...]
        [--policy auto --policy optimal --policy sac-mesh]

Prints Markdown.
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--autoblock", default="build/bin/autoblock")
    parser.add_argument("--policy", action="append")
    parser.add_argument("--time-limit", default="30")
    args = parser.parse_args()
    policies = args.policy or ["auto", "optimal", "sac-mesh"]
    work = tempfile.mkdtemp(prefix="compare-policies-")
    print("| faces | policy | n | blocks / minimum | mean return (mesh) | median ms | max ms | complete | "
          "time limit hit | cuts by |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---|")
    for folder in args.folders:
        for policy in policies:
            out = os.path.join(work, "e.json")
            subprocess.run([args.autoblock, "eval", folder, "--policy", policy, "--reward", "mesh", "--threads", "1",
                            "--time-limit", args.time_limit, "--json", out], check=True, stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
            shapes = json.load(open(out))["shapes"]
            ratio = statistics.mean(s["n_blocks"] / s["min_blocks"] for s in shapes)
            ret = statistics.mean(s["return"] for s in shapes)
            ms = [1000 * s["seconds"] for s in shapes]
            deciders = {}
            for s in shapes:
                for who, count in s.get("decided_by", {}).items():
                    deciders[who] = deciders.get(who, 0) + count
            print("| {} | {} | {} | {:.3f} | {:.3f} | {:.1f} | {:.0f} | {}/{} | {} | {} |".format(
                os.path.basename(folder.rstrip("/")), policy, len(shapes), ratio, ret, statistics.median(ms), max(ms),
                sum(1 for s in shapes if s["complete"]), len(shapes), sum(1 for s in shapes if s.get("time_capped")),
                ", ".join("{} {}".format(k, v) for k, v in sorted(deciders.items()))), flush=True)


if __name__ == "__main__":
    main()
