#!/usr/bin/env python3
"""Hostile input experiment: mutated copies of valid face files through `autoblock decompose` (or mesh).

Usage:
  python3 src/bench/mutate_inputs.py --autoblock build/bin/autoblock --count 1000 --seed 1 \
      --timeout 20 [--jobs 2] [--keep DIR] [--inputs 'models/data/*/*.brep'] [--no-out]

Each run takes one shipped face (models/data/*/*.brep by default), applies one seeded mutation and
runs `autoblock decompose FILE --policy greedy --out OUT.brep` with a timeout. Mutations:
  number    a numeric token replaced (another number, a huge/tiny one, a malformed one: "1.5e", "-", "1..2")
  coord     a coordinate replaced by a huge value, NaN or infinity
  bytes     1-8 random bytes replaced
  truncate  the file cut at a random byte
  lines     a random line deleted or duplicated (counts no longer match)
  shift     (only asked for, --kinds) a number of the geometry sections moved a little or a lot (times
            1.0001 or 1.1 plus a bit, or negated): plausible numbers, the geometry no longer agreeing with
            the topology (a plane's origin moved within it, a circle off its cylinder)
With --mesh, each run is `autoblock mesh FILE --out OUT.msh` instead (swept solids and faces: the
whole meshing pipeline), e.g. over fused solids (src/bench/fused_solids.py):
  python3 src/bench/mutate_inputs.py --autoblock build/bin/autoblock --mesh --inputs '/tmp/fused/*.brep' \
      --kinds shift,coord,number,lines --count 240 --seed 55 --timeout 120 --slow 20
The outcome of each run is one of:
  ok        exit 0
  input     exit 2 with exactly one line "error: ..." on stderr
  internal  exit 1 ("error: internal: ...")
  signal    killed by a signal (a crash)
  hang      still running at the timeout (then killed)
  other     any other exit status, or exit 2 with more than one line (or no "error:" line)
and a table (mutation x outcome) is printed with the slowest run and the runs longer than --slow
seconds (5; the reader's own time budget, AUTOBLOCK_READ_TIMEOUT, turns a stuck read into exit 2
after 30 s: such runs show up here). With --keep, every input whose outcome is internal, signal,
hang or other, or whose run was slow, is copied there with its stderr, for regression tests.
Exit status: 0 when every run ended as ok or input within --slow seconds, else 1.
"""
import argparse
import collections
import concurrent.futures
import glob
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

NUMBER = re.compile(rb"(?<![A-Za-z_])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
KINDS = ["number", "coord", "bytes", "truncate", "lines"]
OUTCOMES = ["ok", "input", "internal", "signal", "hang", "other"]


def replace_number(data, rng, values):
    matches = list(NUMBER.finditer(data))
    if not matches:
        return data
    for _ in range(rng.randint(1, 3)):
        m = rng.choice(matches)
        data = data[:m.start()] + rng.choice(values) + data[m.end():]
        matches = list(NUMBER.finditer(data))
        if not matches:
            break
    return data


def mutate(data, kind, rng):
    if kind == "shift":
        head = data.find(b"Curves")
        tail = data.find(b"TShapes")
        if head < 0:
            return data
        body = data[head:tail] if tail > head else data[head:]
        matches = [m for m in NUMBER.finditer(body) if b"." in m.group() or m.group() not in (b"0", b"1", b"-1")]
        matches = matches or list(NUMBER.finditer(body))
        if not matches:
            return data
        m = rng.choice(matches)
        try:
            value = float(m.group())
        except ValueError:
            return data
        moved = rng.choice([value * 1.0001 + 1e-4, value * 1.1 + 0.5, -value, value + 0.5])
        body = body[:m.start()] + repr(moved).encode() + body[m.end():]
        return data[:head] + body + (data[tail:] if tail > head else b"")
    if kind == "number":
        values = [b"0", b"-1", b"1", b"2", b"3", b"7", b"100", b"65536", b"2147483647", b"-2147483648",
                  b"99999999999", b"1e-300", b"0.5", b"1.5e", b"-", b"1..2", b"+", b"e5", b"3x", b"0x10"]
        values.append(str(rng.randint(-50, 500)).encode())
        values.append(repr(rng.uniform(-1e3, 1e3)).encode())
        return replace_number(data, rng, values)
    if kind == "coord":
        # Coordinates are the numbers with a decimal point or exponent in the geometry sections.
        head = data.find(b"Curves")
        body = data[head:] if head >= 0 else data
        values = [b"1e300", b"-1e308", b"1.7976931348623157e308", b"nan", b"-nan", b"inf", b"-inf", b"1e-320",
                  b"123456789012345678", b"4.9e-324"]
        mutated = replace_number(body, rng, values)
        return (data[:head] + mutated) if head >= 0 else mutated
    if kind == "bytes":
        out = bytearray(data)
        for _ in range(rng.randint(1, 8)):
            i = rng.randrange(len(out))
            out[i] = rng.choice([rng.randrange(256), rng.choice(b"0123456789.-+e \n")])
        return bytes(out)
    if kind == "truncate":
        return data[:rng.randrange(1, len(data))]
    if kind == "lines":
        lines = data.split(b"\n")
        i = rng.randrange(len(lines))
        if rng.random() < 0.5:
            del lines[i]
        else:
            lines.insert(i, lines[i])
        return b"\n".join(lines)
    raise ValueError(kind)


def make_cases(sources, count, seed, work, kinds=None):
    """Writes the mutated files into work; returns [(i, kind, source, path)]. Same seed, same files."""
    kinds = kinds or KINDS
    originals = {p: open(p, "rb").read() for p in sources}
    rng = random.Random(seed)
    cases = []
    for i in range(count):
        source = rng.choice(sources)
        kind = kinds[i % len(kinds)]
        data = mutate(originals[source], kind, rng)
        path = os.path.join(work, f"m{i:05d}_{kind}.brep")
        with open(path, "wb") as f:
            f.write(data)
        cases.append((i, kind, source, path))
    return cases


def classify(returncode, stderr, timed_out):
    if timed_out:
        return "hang"
    if returncode < 0:
        return "signal"
    lines = [l for l in stderr.splitlines() if l.strip()]
    if returncode == 0:
        return "ok"
    if returncode == 2 and len(lines) == 1 and lines[0].startswith("error: ") and not lines[0].startswith("error: internal"):
        return "input"
    if returncode == 1 and len(lines) == 1 and lines[0].startswith("error: internal"):
        return "internal"
    return "other"


def run_one(binary, path, out, timeout, write_out, mesh=False):
    command = [binary, "mesh", path] if mesh else [binary, "decompose", path, "--policy", "greedy"]
    if write_out:
        command += ["--out", out + (".msh" if mesh else "")]
    start = time.monotonic()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, start_new_session=True)
    timed_out = False
    try:
        _, err = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        os.killpg(process.pid, signal.SIGKILL)
        _, err = process.communicate()
    seconds = time.monotonic() - start
    stderr = err.decode("utf-8", "replace")
    return classify(process.returncode, stderr, timed_out), process.returncode, stderr, seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    parser.add_argument("--autoblock", required=True, help="path of the autoblock binary")
    parser.add_argument("--count", type=int, default=1000, help="number of mutated files")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=20.0, help="seconds per run before it counts as a hang")
    parser.add_argument("--jobs", type=int, default=1, help="runs at once")
    parser.add_argument("--inputs", default=os.path.join(os.path.dirname(__file__), "..", "..", "models", "data", "*", "*.brep"),
                        help="glob of the valid files to mutate")
    parser.add_argument("--keep", help="folder for the inputs whose outcome is internal, signal, hang or other")
    parser.add_argument("--slow", type=float, default=5.0, help="runs longer than this many seconds are listed (and kept)")
    parser.add_argument("--no-out", action="store_true", help="do not pass --out (skip cutting and writing the blocks)")
    parser.add_argument("--mesh", action="store_true", help="run `autoblock mesh` (the mesh, .msh) instead of decompose")
    parser.add_argument("--kinds", help="comma-separated mutations to take in turn (default: " + ",".join(KINDS) +
                        "; also: shift)")
    args = parser.parse_args()

    sources = sorted(glob.glob(args.inputs))
    if not sources:
        sys.exit(f"error: no files match {args.inputs}")
    work = tempfile.mkdtemp(prefix="autoblock-mutate-")
    kinds = args.kinds.split(",") if args.kinds else KINDS
    unknown = [k for k in kinds if k not in KINDS + ["shift"]]
    if unknown:
        sys.exit(f"error: unknown mutation {unknown[0]} (choose from {', '.join(KINDS + ['shift'])})")
    cases = make_cases(sources, args.count, args.seed, work, kinds)

    table = collections.defaultdict(collections.Counter)
    slowest = (0.0, None)
    multi_line = 0
    bad = []
    slow = []
    started = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = {pool.submit(run_one, args.autoblock, path, os.path.join(work, f"out{i}.brep"), args.timeout,
                               not args.no_out, args.mesh): (i, kind, source, path) for i, kind, source, path in cases}
        for future in concurrent.futures.as_completed(futures):
            i, kind, source, path = futures[future]
            outcome, code, stderr, seconds = future.result()
            table[kind][outcome] += 1
            if len([l for l in stderr.splitlines() if l.strip()]) > 1:
                multi_line += 1
            if seconds > slowest[0]:
                slowest = (seconds, path)
            if seconds > args.slow:
                slow.append((seconds, outcome, path))
            if outcome not in ("ok", "input") or seconds > args.slow:
                if outcome not in ("ok", "input"):
                    bad.append((outcome, code, path, stderr.strip().splitlines()[-1:] if stderr.strip() else ""))
                if args.keep:
                    os.makedirs(args.keep, exist_ok=True)
                    name = f"{outcome}_{os.path.basename(path)}"
                    shutil.copy(path, os.path.join(args.keep, name))
                    with open(os.path.join(args.keep, name + ".stderr"), "w") as f:
                        f.write(f"source: {source}\nexit: {code}\n{stderr}")
    elapsed = time.monotonic() - started

    print(f"mutate_inputs: {args.count} files, seed {args.seed}, timeout {args.timeout:g} s, binary {args.autoblock}")
    header = f"{'mutation':<10}" + "".join(f"{o:>10}" for o in OUTCOMES) + f"{'total':>10}"
    print(header)
    totals = collections.Counter()
    for kind in kinds:
        row = table[kind]
        totals.update(row)
        print(f"{kind:<10}" + "".join(f"{row[o]:>10}" for o in OUTCOMES) + f"{sum(row.values()):>10}")
    print(f"{'all':<10}" + "".join(f"{totals[o]:>10}" for o in OUTCOMES) + f"{sum(totals.values()):>10}")
    print(f"runs with more than one line on stderr: {multi_line}")
    print(f"slowest run: {slowest[0]:.2f} s ({slowest[1]}); wall time {elapsed:.0f} s")
    print(f"runs longer than {args.slow:g} s: {len(slow)}")
    for seconds, outcome, path in sorted(slow, reverse=True)[:20]:
        print(f"  slow      {seconds:.1f} s, {outcome}: {path}")
    for outcome, code, path, last in sorted(bad)[:40]:
        print(f"  {outcome:<9} exit {code}: {path}: {last[0] if last else ''}")
    if not bad and not slow:
        shutil.rmtree(work, ignore_errors=True)
    else:
        print(f"mutated files kept in {work}")
    return 0 if not bad and not slow else 1


if __name__ == "__main__":
    sys.exit(main())
