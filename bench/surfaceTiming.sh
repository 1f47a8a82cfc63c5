#!/usr/bin/env bash
# fluidSurface's speed on 226,560 fluid particles (README "Surfaces"): the dam break's tank with its column
# widened to 0.6 x 0.59 x 0.64 m (r = 5 mm), sampled, optionally run to RUN_TO seconds so the surface is
# that of a collapsing column, then fluidSurface on the latest time, RUNS times per thread count. Prints
# fluidSurface's own lines (triangles, grid, surface time, time with reading and writing) of every run.
#
# usage: bench/surfaceTiming.sh [BUILD_DIR] [RUN_TO] [RUNS] [THREADS]
#   BUILD_DIR  build tree holding bin/sampleParticles, bin/poroSph, bin/fluidSurface (default: <repo>/build)
#   RUN_TO     simulated time to run first; 0 times the sampled block (default: 0; 0.2 takes about
#              10 minutes on 2 cores)
#   RUNS       fluidSurface runs per thread count                          (default: 5)
#   THREADS    space-separated thread counts                               (default: "1 2")
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(dirname "$here")"
build="${1:-$repo/build}"
run_to="${2:-0}"
runs="${3:-5}"
threads_list="${4:-1 2}"

die() { echo "surfaceTiming: $*" >&2; exit 1; }

for exe in sampleParticles poroSph fluidSurface; do
  [[ -x "$build/bin/$exe" ]] || die "$build/bin/$exe not found; build it: cmake --build $build"
done
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || die "RUNS must be a positive integer, got '$runs'"

work="$(mktemp -d "${TMPDIR:-/tmp}/surfaceTiming.XXXXXX")"
trap 'rm -rf "$work"' EXIT
cp -r "$repo/tutorials/fluid/damBreak/system" "$repo/tutorials/fluid/damBreak/constant" "$work/"
sed -i 's/max: \[0.2, 0.4, 0.64\]/max: [0.6, 0.59, 0.64]/' "$work/system/particleDict"
grep -q 'max: \[0.6, 0.59, 0.64\]' "$work/system/particleDict" || die "the dam break's column is no longer where this script widens it"
"$build/bin/sampleParticles" -case "$work" > "$work/log.sampleParticles" || die "sampleParticles failed: $work/log.sampleParticles"
grep '^Wrote' "$work/log.sampleParticles"

if [[ "$run_to" != 0 ]]; then
  sed -i "s/^endTime:.*/endTime: $run_to/; s/^writeInterval:.*/writeInterval: $run_to/" "$work/system/controlDict"
  "$build/bin/poroSph" -case "$work" > "$work/log.poroSph" || die "poroSph failed"
fi

for t in $threads_list; do
  echo "threads $t:"
  for ((i = 0; i < runs; ++i)); do
    "$build/bin/fluidSurface" -case "$work" -latestTime -threads "$t" | grep -E 'triangles|with reading'
  done
done
