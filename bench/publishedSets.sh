#!/usr/bin/env bash
# The published sets' timing table (issue "four times the authors' speed", bench/README.md): each set is the
# tutorial in tutorials/published/, at the resolution and over the interval of its row, at the paper's fixed
# dt = 1 ms, run once per mode and thread count from the same sampled 0/. Prints one Markdown row per run:
# particles, ms/step, microseconds per particle-step, phase split, pressure sweeps and CG iterations per
# step, peak resident memory (GNU time) and bytes per particle. Before and after the table, the machine's own 1 -> 2
# thread speed-up on pure arithmetic (bench_kernels' ParallelGrain, when built), to read the efficiencies against.
#
# usage: bench/publishedSets.sh [BUILD_DIR] [SETS] [MODES] [THREADS]
#   BUILD_DIR  build tree holding bin/poroSph and bin/sampleParticles                   (default: <repo>/build)
#   SETS       of: seep-r2cm float-r2.5cm climb-r2cm seep-r1cm seep-r1.5cm climb-r1cm climb-r1.5cm
#              (default: the first three; seep-r1cm takes about 5 minutes a run on 2 cores; seep-r1.5cm and
#              climb-r1.5cm are the middle resolutions of the cost-per-particle-step comparison, with the r = 2 and
#              1 cm sets; Climb's rows of it run 0-0.3 s, so STEPS=300 for climb-r2cm)
#   MODES      of: paper reference                                                      (default: both)
#   THREADS    thread counts, RUNS runs each                                            (default: "1 2")
# environment: STEPS=N runs N steps of every set instead of its row's interval (a quick look); RUNS=N runs each
#              row N times, the thread counts taking turns, and prints the median run (by time-loop seconds)
#              with the fastest and slowest ms/step.
#
# The time per step is the time loop's ("ExecutionTime" of the log after the last step: set-up and the one
# final write excluded); memory is the whole process's peak.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(dirname "$here")"
build="${1:-$repo/build}"
sets="${2:-seep-r2cm float-r2.5cm climb-r2cm}"
modes="${3:-paper reference}"
threads_list="${4:-1 2}"
runs="${RUNS:-1}"

die() { echo "publishedSets: $*" >&2; exit 1; }

for exe in poroSph sampleParticles; do
  [[ -x "$build/bin/$exe" ]] || die "$build/bin/$exe not found; build it: cmake --build $build --target $exe"
done
[[ -x /usr/bin/time ]] || die "/usr/bin/time (GNU time, Debian package 'time') is needed for the peak memory"
for mode in $modes; do [[ "$mode" == paper || "$mode" == reference ]] || die "unknown mode '$mode' (paper, reference)"; done
for t in $threads_list; do [[ "$t" =~ ^[1-9][0-9]*$ ]] || die "THREADS must be positive integers, got '$t'"; done
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || die "RUNS must be a positive integer, got '$runs'"

# set -> "tutorial steps": the rows of the issue's table. A set with bench/published/<set>.particleDict
# uses that instead of the tutorial's.
declare -A row=(
  [seep-r2cm]="seep 500"     # 0-0.5 s
  [float-r2.5cm]="float 1000" # 0-1 s, the published set
  [climb-r2cm]="climb 1000"   # 0-1 s
  [seep-r1cm]="seep 300"      # 0-0.3 s, the published set: landing and first contact
  [seep-r1.5cm]="seep 300"    # 0-0.3 s, between the two above (cost per particle-step against resolution)
  [climb-r1cm]="climb 300"    # 0-0.3 s, the published set
  [climb-r1.5cm]="climb 300"  # 0-0.3 s, with climb-r2cm and climb-r1cm: cost per particle-step in a slow flow
)
for set in $sets; do [[ -n "${row[$set]:-}" ]] || die "unknown set '$set' (${!row[*]})"; done

work="$(mktemp -d "${TMPDIR:-/tmp}/publishedSets.XXXXXX")"
trap 'rm -rf "$work"' EXIT

# Sets a top-level key of a YAML dictionary, replacing its line.
set_key() { sed -i "s|^$2:.*|$2: $3|" "$1"; }

# The machine's own 1 -> 2 thread speed-up on loops of pure arithmetic (bench_kernels' ParallelGrain, 8,192 items,
# medians of 3), printed before and after the table with the two times: the cores here do not always run at one
# speed, and a row's efficiency is to be read against the ratio, its ms/step against the 1-thread time.
machine_speedup() {
  local bench="$build/bin/bench_kernels"
  if [[ ! -x "$bench" ]]; then
    echo "machine speed-up $1 the table: not measured ($bench not built: Google Benchmark missing?)"
    return
  fi
  { "$bench" --benchmark_filter='ParallelGrain/threads:./items:8192' --benchmark_repetitions=3 \
             --benchmark_report_aggregates_only=true --benchmark_format=csv 2>/dev/null || true; } |
    awk -F, -v when="$1" '$1 ~ /_median"$/ { t = ($1 ~ /threads:1\//) ? 1 : 2; us[t] = $3 }
      END { if (us[1] > 0 && us[2] > 0)
              printf "machine speed-up %s the table (ParallelGrain, 8,192 items, 1 -> 2 threads): %.2f (%.1f / %.1f µs)\n",
                     when, us[1] / us[2], us[1], us[2]
            else print "machine speed-up " when " the table: not measured" }'
}

machine_speedup before
echo
echo "| set | mode | threads | particles (fluid + porous / walls) | ms/step | µs per particle-step (all) | search / densities / implicit / pressure % | sweeps/step | CG/step | peak RSS MiB | bytes/particle |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for set in $sets; do
  read -r tutorial steps <<<"${row[$set]}"
  steps="${STEPS:-$steps}"
  base="$work/$set"
  mkdir -p "$base"
  cp -r "$repo/tutorials/published/$tutorial/system" "$repo/tutorials/published/$tutorial/constant" "$base/"
  if [[ -f "$here/published/$set.particleDict" ]]; then # a coarse set with boxes of whole spacings
    cp "$here/published/$set.particleDict" "$base/system/particleDict"
  fi
  control="$base/system/controlDict"
  end_time="$(awk -v n="$steps" 'BEGIN { printf "%.12g", n * 0.001 }')"
  set_key "$control" startFrom startTime
  set_key "$control" deltaT 0.001
  set_key "$control" adjustTimeStep false
  set_key "$control" endTime "$end_time"
  set_key "$control" writeInterval "$end_time"
  "$build/bin/sampleParticles" -case "$base" >"$base/log.sampleParticles" 2>&1 ||
    { tail -n 20 "$base/log.sampleParticles" >&2; die "sampleParticles failed on $set"; }
  count() { # particles of one phase in the sampling log
    awk -v phase="$1" '/^region .*: [0-9]+ (fluid|porous) particles/ {
                         for (i = 1; i <= NF; ++i) if ($(i + 1) == phase) n += $i }
                       END { print n + 0 }' "$base/log.sampleParticles"
  }
  fluid="$(count fluid)"
  porous="$(count porous)"
  total="$(sed -n 's/^Wrote .* with \([0-9][0-9]*\) particles.*/\1/p' "$base/log.sampleParticles" | tail -n 1)"
  for mode in $modes; do
    sed -i "s/^  preset: .*/  preset: $mode/" "$base/system/solverDict"
    unset seconds
    declare -A seconds=() # per thread count, a line "time-loop seconds run" for each run
    # The thread counts take turns (1 2 1 2 ...): the machine's speed drifts over minutes, and runs a minute apart
    # compare the thread counts more fairly than blocks of runs a row apart.
    for ((run = 1; run <= runs; ++run)); do
      for t in $threads_list; do
        rm -rf "$base/$end_time" "$base/case.pvd" "$base/postProcessing"
        log="$base/log.poroSph.$mode.$t.$run"
        /usr/bin/time -f "%M" -o "$base/rss.$t.$run" "$build/bin/poroSph" -case "$base" -threads "$t" >"$log" 2>&1 ||
          { tail -n 20 "$log" >&2; die "poroSph failed on $set ($mode, $t threads)"; }
        seconds[$t]+="$(awk '/^ExecutionTime = / { s = $3 } END { print s + 0 }' "$log") $run"$'\n'
      done
    done
    for t in $threads_list; do
      # The row is the median run's; with RUNS > 1 its ms/step is followed by the fastest and slowest runs'.
      sorted="$(printf '%s' "${seconds[$t]}" | sort -g)"
      read -r _ run <<<"$(sed -n "$(((runs + 1) / 2))p" <<<"$sorted")"
      read -r fastest _ <<<"$(head -n 1 <<<"$sorted")"
      read -r slowest _ <<<"$(tail -n 1 <<<"$sorted")"
      log="$base/log.poroSph.$mode.$t.$run"
      awk -v set="$set" -v mode="$mode" -v threads="$t" -v fluid="$fluid" -v porous="$porous" -v total="$total" \
          -v rssKiB="$(cat "$base/rss.$t.$run")" -v runs="$runs" -v fastest="$fastest" -v slowest="$slowest" '
        /^Time = .*\(step [0-9]+\)/ { s = $0; sub(/.*\(step /, "", s); sub(/\).*/, "", s); steps = s + 0 }
        /^pressure: [0-9]+ sweeps/  { sweeps += $2; nPressure++ }
        /^implicit: [0-9]+ CG/      { cg += $2; nImplicit++ }
        /^ExecutionTime = /         { seconds = $3 + 0 }
        /^Phase breakdown over/     { inPhases = 1; next }
        inPhases && /^[A-Z]/        { inPhases = 0 }
        inPhases && NF >= 4         { share[$1] = $4 }
        END {
          if (steps == 0 || seconds <= 0) { print "| " set " | " mode " | " threads " | no steps in the log |"; exit 1 }
          ms = 1000.0 * seconds / steps
          msText = sprintf("%.1f", ms)
          if (runs > 1) msText = msText sprintf(" (%.1f–%.1f)", 1000.0 * fastest / steps, 1000.0 * slowest / steps)
          printf "| %s | %s | %d | %d + %d / %d | %s | %.2f | %s / %s / %s / %s | %.1f | %.1f | %.0f | %.0f |\n",
                 set, mode, threads, fluid, porous, total - fluid - porous, msText, 1000.0 * ms / total,
                 share["search"], share["densities"], share["implicit"], share["pressure"],
                 nPressure ? sweeps / nPressure : 0, nImplicit ? cg / nImplicit : 0,
                 rssKiB / 1024.0, rssKiB * 1024.0 / total
        }' "$log"
    done
  done
done
echo
machine_speedup after
