#!/usr/bin/env bash
# Whole-case timing (ARCHITECTURE.md "bench/"): copies a tutorial case to a temporary directory, samples
# its particles, runs about STEPS time steps from time 0 and prints particle counts, steps, ms/step,
# million particle-steps per second (fluid and porous particles: the unknowns; walls are not counted) and
# poroSph's phase breakdown.
#
# usage: bench/caseTiming.sh [BUILD_DIR] [CASE] [STEPS] [THREADS]
#   BUILD_DIR  build tree holding bin/poroSph and bin/sampleParticles   (default: <repo>/build)
#   CASE       case directory with system/ and constant/                 (default: <repo>/tutorials/fluid/damBreak)
#   STEPS      steps to run: endTime is set to STEPS * deltaT           (default: 100)
#   THREADS    space-separated thread counts, one run each               (default: "2"; e.g. "1 2")
# environment: FIXED_STEP=1 sets adjustTimeStep false (exactly STEPS steps of deltaT).
#
# endTime = STEPS * deltaT with the case's own deltaT; with adjustTimeStep the solver may take another step
# size, so the step count printed is the one read from the log. Output is written only at endTime
# (writeControl runTime, writeInterval = endTime), so writes do not enter the time-loop timing, which is the
# last "ExecutionTime" of the log (the loop's wall clock after the last step, before the final write).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(dirname "$here")"
build="${1:-$repo/build}"
case_src="${2:-$repo/tutorials/fluid/damBreak}"
steps="${3:-100}"
threads_list="${4:-2}"

die() { echo "caseTiming: $*" >&2; exit 1; }

for exe in poroSph sampleParticles; do
  [[ -x "$build/bin/$exe" ]] || die "$build/bin/$exe not found; build it: cmake --build $build --target $exe"
done
[[ -f "$case_src/system/controlDict" ]] || die "$case_src is not a case (no system/controlDict)"
[[ "$steps" =~ ^[1-9][0-9]*$ ]] || die "STEPS must be a positive integer, got '$steps'"
for t in $threads_list; do
  [[ "$t" =~ ^[1-9][0-9]*$ ]] || die "THREADS must be positive integers, got '$t'"
done

work="$(mktemp -d "${TMPDIR:-/tmp}/caseTiming.XXXXXX")"
trap 'rm -rf "$work"' EXIT
case_dir="$work/case"
mkdir -p "$case_dir"
# Only the inputs (system/, constant/): sampleParticles writes a fresh 0/, old results stay behind.
cp -r "$case_src/system" "$case_dir/"
if [[ -d "$case_src/constant" ]]; then cp -r "$case_src/constant" "$case_dir/"; fi

control="$case_dir/system/controlDict"
# The value of a top-level key of the YAML controlDict (comments stripped).
get_key() { sed -n "s/^$1:[[:space:]]*\([^#[:space:]]*\).*/\1/p" "$control" | tail -n 1; }
# Sets a top-level key, replacing its line or appending it.
set_key() {
  if grep -q "^$1:" "$control"; then
    sed -i "s|^$1:.*|$1: $2|" "$control"
  else
    printf '%s: %s\n' "$1" "$2" >>"$control"
  fi
}

delta_t="$(get_key deltaT)"
[[ -n "$delta_t" ]] || die "$case_src/system/controlDict has no deltaT"
end_time="$(awk -v n="$steps" -v dt="$delta_t" 'BEGIN { printf "%.12g", n * dt }')"
set_key startFrom startTime
set_key startTime 0
set_key endTime "$end_time"
set_key writeControl runTime
set_key writeInterval "$end_time"
set_key purgeWrite 0
# FIXED_STEP=1 turns adjustTimeStep off, so exactly STEPS steps of the case's deltaT run.
if [[ "${FIXED_STEP:-0}" == 1 ]]; then set_key adjustTimeStep false; fi

"$build/bin/sampleParticles" -case "$case_dir" >"$work/log.sampleParticles" 2>&1 ||
  { cat "$work/log.sampleParticles" >&2; die "sampleParticles failed"; }
dynamic="$(awk '/^region .*: [0-9]+ (fluid|porous) particles/ {
                  for (i = 1; i <= NF; ++i) if ($(i + 1) == "fluid" || $(i + 1) == "porous") n += $i }
                END { print n + 0 }' "$work/log.sampleParticles")"
total="$(sed -n 's/^Wrote .* with \([0-9][0-9]*\) particles.*/\1/p' "$work/log.sampleParticles" | tail -n 1)"

echo "case:       $case_src"
echo "particles:  $dynamic fluid and porous, $total total (radius $(sed -n 's/^particleRadius:[[:space:]]*\([^#[:space:]]*\).*/\1/p' "$case_dir/system/particleDict") m)"
echo "requested:  $steps steps, endTime = $steps x $delta_t = $end_time s"

status=0
for t in $threads_list; do
  # Each run starts from the same 0/ (startFrom startTime); the final write goes to a new time directory.
  log="$work/log.poroSph.$t"
  if ! "$build/bin/poroSph" -case "$case_dir" -threads "$t" >"$log" 2>&1; then
    echo "--- poroSph -threads $t failed; end of its log:" >&2
    tail -n 20 "$log" >&2
    status=1
    continue
  fi
  awk -v dynamic="$dynamic" -v threads="$t" '
    /^Time = .*\(step [0-9]+\)/ { s = $0; sub(/.*\(step /, "", s); sub(/\).*/, "", s); steps = s + 0 }
    /^pressure: [0-9]+ sweeps/  { sweeps += $2; nPressure++ }
    /^implicit: [0-9]+ CG/      { cg += $2; nImplicit++ }
    /^ExecutionTime = /         { seconds = $3 + 0 }
    /^Phase breakdown over/     { inPhases = 1 }
    inPhases && /^End$/         { inPhases = 0 }
    inPhases && NF > 0          { phases = phases "  " $0 "\n" }
    END {
      if (steps == 0 || seconds <= 0) { print "threads " threads ": no steps found in the log"; exit 1 }
      printf "\n== threads %d\n", threads
      printf "steps:      %d in %.3f s (time loop)\n", steps, seconds
      printf "ms/step:    %.2f\n", 1000.0 * seconds / steps
      printf "throughput: %.3f million particle-steps/s (fluid and porous)\n", dynamic * steps / seconds / 1e6
      if (nPressure > 0) printf "pressure:   %.1f sweeps/step\n", sweeps / nPressure
      if (nImplicit > 0) printf "implicit:   %.1f CG iterations/step\n", cg / nImplicit
      printf "%s", phases
    }' "$log" || status=1
done
exit "$status"
