#!/usr/bin/env python3
# Usage: python3 src/bench/verify_cli_runs.py build/bin/autoblock OUTPUT_FOLDER
# 750 CLI runs: greedy, random, random-split on 200 fresh 2-10 rectangle faces and 50 with holes.
# Checks per run: exit 0, complete, 4-corner axis-aligned blocks, no two overlapping, areas summing
# to the face's, block count >= min_blocks, and OCCT's check of the written blocks (decompose --out
# validates the conformal compound and fails otherwise).
import json, os, subprocess, sys, itertools
B = sys.argv[1]; out = sys.argv[2]
os.makedirs(out, exist_ok=True)
subprocess.run([B, "generate", "--count", "200", "--seed", "9001", "--out", out + "/plain"], check=True, stdout=subprocess.DEVNULL)
subprocess.run([B, "generate", "--count", "50", "--seed", "9002", "--holes", "--out", out + "/holes"], check=True, stdout=subprocess.DEVNULL)
runs = bad = 0
for folder in ("plain", "holes"):
    index = json.load(open(f"{out}/{folder}/index.json"))
    for shape in index["shapes"]:
        f = f"{out}/{folder}/{shape['file']}"
        for policy in ("greedy", "random", "random-split"):
            runs += 1
            rep = f"{out}/r.json"
            p = subprocess.run([B, "decompose", f, "--policy", policy, "--json", rep, "--out", f"{out}/b.brep", "--seed", "5"], capture_output=True, text=True)
            ok = p.returncode == 0
            if ok:
                r = json.load(open(rep))
                boxes = []
                for blk in r["blocks"]:
                    xs = sorted({c[0] for c in blk}); ys = sorted({c[1] for c in blk})
                    ok &= len(blk) == 4 and len(xs) == 2 and len(ys) == 2
                    boxes.append((xs[0], ys[0], xs[-1], ys[-1]))
                area = sum((b[2]-b[0])*(b[3]-b[1]) for b in boxes)
                ok &= abs(area - shape["area"]) <= 1e-9 * max(1.0, shape["area"])
                for a, b in itertools.combinations(boxes, 2):
                    if min(a[2], b[2]) - max(a[0], b[0]) > 1e-12 and min(a[3], b[3]) - max(a[1], b[1]) > 1e-12:
                        ok = False
                ok &= r["complete"] and not r["truncated"] and r["n_blocks"] >= r["min_blocks"]
            if not ok:
                bad += 1
                print("FAILED", f, policy, p.returncode, p.stderr.strip()[:200])
print(f"{runs} runs, {bad} failed")
