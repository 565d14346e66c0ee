#!/usr/bin/env bash
# Whole-command timings of mozzi-cli as a user runs it, start-up included
# (issue 19; figures in docs/performance.md and docs/performance/commands.md).
#
#   scripts/bench-cli.sh BUILD_DIR [RUNS]
#
# Generates the benchmark files once (tests/bench/cli_commands_bench
# --write-files, into $MOZZI_BENCH_DIR, default /tmp/mozzi_bench_cli), then
# runs each command RUNS times (default 7) after one warm-up run and prints
# the minimum and median wall time (bash's microsecond clock around the
# process) and the peak resident memory (GNU time's %M, one extra run), with
# the load average before and after. MOZZI_CLI=path times another mozzi-cli
# (e.g. a build of an older commit) on the same files; MOZZI_BENCH_ONLY=REGEX
# keeps the commands whose label matches.
set -euo pipefail
build=${1:?usage: bench-cli.sh BUILD_DIR [RUNS]}
runs=${2:-7}
root=$(cd "$(dirname "$0")/.." && pwd)
cli=${MOZZI_CLI:-$build/app/mozzi-cli}
bench=$build/tests/cli_commands_bench
export MOZZI_BENCH_DIR=${MOZZI_BENCH_DIR:-/tmp/mozzi_bench_cli}
"$bench" --write-files >/dev/null
small="$root/../shared/data/uff/TestLab 161 164 18 15 82.uff"

measure() {
  local label=$1
  shift
  [[ -z "${MOZZI_BENCH_ONLY:-}" || "$label" =~ $MOZZI_BENCH_ONLY ]] || return 0
  "$@" >/dev/null 2>&1 || { echo "$label: command failed: $*" >&2; return 1; }  # warm-up
  local times=() t0 t1
  for ((i = 0; i < runs; i++)); do
    t0=$EPOCHREALTIME
    "$@" >/dev/null 2>&1
    t1=$EPOCHREALTIME
    times+=("$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.4f", (b - a) * 1000 }')")
  done
  local rss
  rss=$(/usr/bin/time -f %M "$@" 2>&1 >/dev/null | tail -1)
  printf '%s\n' "${times[@]}" | sort -g | awk -v label="$label" -v rss="$rss" '
    { t[NR] = $1 }
    END {
      med = (NR % 2) ? t[(NR + 1) / 2] : (t[NR / 2] + t[NR / 2 + 1]) / 2
      printf "| %s | %.1f ms | %.1f ms | %.1f MB |\n", label, t[1], med, rss / 1024
    }'
}

echo "mozzi-cli: $cli ($runs runs after a warm-up); load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| command | min wall | median wall | peak RSS |"
echo "|---|---|---|---|"
measure "--version" "$cli" --version
measure "uff info, 10 kB file (TestLab)" "$cli" uff info "$small"
measure "uff info hits_10x4x65536.uff (21 MB streaming read)" "$cli" uff info "$MOZZI_BENCH_DIR/hits_10x4x65536.uff"
measure "frf hits_10x4x65536.uff --estimator H1" "$cli" frf "$MOZZI_BENCH_DIR/hits_10x4x65536.uff" --estimator H1
measure "identify 10 x 5,000, band 50-950 Hz, order 60" "$cli" identify "$MOZZI_BENCH_DIR/identify_10x5000.uff" \
  --band 50:950 --max-order 60
measure "identify 100 x 20,000, band 50-950 Hz, order 60" "$cli" identify "$MOZZI_BENCH_DIR/identify_100x20000.uff" \
  --band 50:950 --max-order 60
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
