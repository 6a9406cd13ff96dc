#!/usr/bin/env python3
"""Training runs side by side, as the paper's two panels: the training return (moving average over
10 episodes) and the deterministic test return, from the CSV logs `autoblock train` writes, with
reference lines (e.g. the test set's optimal, greedy and random returns).

    /usr/bin/python3 src/bench/plot_training_runs.py --out curves.png \\
        --run "paper agent=runs/a.csv" --run "linear actor=runs/b.csv" \\
        --ref "optimal=34.518" --ref "greedy=24.916" [--title TEXT]

Also prints each run's test returns as Markdown (episode, test return, wall seconds).
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def labelled(text, what):
    label, sep, value = text.partition("=")
    if not sep or not label or not value:
        sys.exit(f"error: {what} '{text}': expected LABEL=VALUE")
    return label, value


def read_run(path):
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        sys.exit(f"error: cannot read {path}: {e.strerror}")
    if not rows or "return" not in rows[0] or "test_return" not in rows[0]:
        sys.exit(f"error: {path}: not a training log (no return / test_return columns)")
    episodes = [int(r["episode"]) for r in rows]
    returns = [float(r["return"]) for r in rows]
    tests = [(int(r["episode"]), float(r["test_return"]), float(r["wall_seconds"])) for r in rows if r["test_return"]]
    return episodes, returns, tests


def moving_average(values, window=10):
    out, total = [], 0.0
    for k, v in enumerate(values):
        total += v
        if k >= window:
            total -= values[k - window]
        out.append(total / min(k + 1, window))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--run", action="append", required=True, help="LABEL=CSV")
    parser.add_argument("--ref", action="append", default=[], help="LABEL=VALUE, a dashed line on the test panel")
    parser.add_argument("--out", required=True)
    parser.add_argument("--title", default="")
    args = parser.parse_args()
    runs = [(label, read_run(path)) for label, path in (labelled(r, "--run") for r in args.run)]
    refs = []
    for r in args.ref:
        label, value = labelled(r, "--ref")
        try:
            refs.append((label, float(value)))
        except ValueError:
            sys.exit(f"error: --ref '{r}': the value is not a number")

    fig, (train, test) = plt.subplots(1, 2, figsize=(13, 4.6))
    for k, (label, (episodes, returns, tests)) in enumerate(runs):
        colour = f"C{k}"
        train.plot(episodes, moving_average(returns), color=colour, label=label, linewidth=1.2)
        test.plot([e for e, _, _ in tests], [t for _, t, _ in tests], color=colour, label=label, marker=".")
    for k, (label, value) in enumerate(refs):
        test.axhline(value, color=f"C{len(runs) + k}", linestyle="--", linewidth=1, label=f"{label} ({value:.2f})")
    train.set_title("Training episodes: return, moving average over 10")
    test.set_title("Test set: mean deterministic return")
    for ax in (train, test):
        ax.set_xlabel("episode")
        ax.set_ylabel("return")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)

    for label, (_, _, tests) in runs:
        print(f"\n{label}\n\n| episode | test return | wall s |\n|---:|---:|---:|")
        for e, t, w in tests:
            print(f"| {e} | {t:.3f} | {w:.0f} |")


if __name__ == "__main__":
    main()
