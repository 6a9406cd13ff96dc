#!/usr/bin/env bash
# The unseen face sets of the start-up / default-policy benchmarks (BENCHMARKS.md, "The default policy
# and start-up"): validation sets (seeds 701-706, used to choose auto's budgets) and report sets
# (seeds 801-807), default and thin-feature kinds, with and without holes.
#   src/bench/make_sets.sh [AUTOBLOCK] [FOLDER]
set -euo pipefail
ab=${1:-build/bin/autoblock}
out=${2:-bench-sets}
thin32=(--grid 32 --min-side 3 --max-side 18)
thin64=(--grid 64 --min-side 4 --max-side 24 --min-rects 11 --max-rects 40)
gen() { local name=$1; shift; "$ab" generate "$@" --out "$out/$name" >/dev/null; }
gen v-default-2-10 --count 100 --seed 701
gen v-default-11-40 --count 50 --seed 702 --min-rects 11 --max-rects 40
gen v-thin-2-10 --count 100 --seed 703 "${thin32[@]}"
gen v-thin-11-40 --count 50 --seed 704 "${thin64[@]}"
gen v-thin-11-40-holes --count 50 --seed 705 "${thin64[@]}" --holes
gen v-thin-2-10-holes --count 50 --seed 706 "${thin32[@]}" --holes
gen r-default-2-10 --count 100 --seed 801
gen r-default-11-40 --count 50 --seed 802 --min-rects 11 --max-rects 40
gen r-default-2-10-holes --count 50 --seed 803 --holes
gen r-thin-2-10 --count 100 --seed 804 "${thin32[@]}"
gen r-thin-11-40 --count 50 --seed 805 "${thin64[@]}"
gen r-thin-11-40-holes --count 50 --seed 806 "${thin64[@]}" --holes
gen r-thin-41-80 --count 20 --seed 807 --grid 96 --min-side 4 --max-side 30 --min-rects 41 --max-rects 80
# Larger faces with holes, whose exact search runs into auto's budget ("auto's and optimal's search
# budgets in work").
gen x-60-100-holes --count 30 --seed 901 --min-rects 60 --max-rects 100 --holes
gen x-thin-41-80-holes --count 30 --seed 902 --grid 96 --min-side 4 --max-side 30 --min-rects 41 --max-rects 80 --holes
echo "sets in $out"
