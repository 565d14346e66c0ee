#!/usr/bin/env bash
# Whole-command timings of mozzi-cli as a user runs it, start-up included
# (issue 19; figures in docs/performance.md and docs/performance/commands.md).
#
#   scripts/bench-cli.sh BUILD_DIR [RUNS]
#
# Generates the benchmark files once (tests/bench/cli_commands_bench
# --write-files, into $MOZZI_BENCH_DIR, default /tmp/mozzi_bench_cli), then
# runs each command RUNS times (default 7) after one warm-up run and prints
# the median CPU time (user + sys) and wall time of the process and its peak
# resident memory (wait4's rusage, read by python3), with the load average before and
# after. On a shared machine quote the CPU time: the wall time grows with the
# load (about 3x at a load average of 9 on 2 cores). MOZZI_CLI=path times another mozzi-cli
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

timer='
import os, subprocess, sys, time
t0 = time.perf_counter()
p = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
_, status, ru = os.wait4(p.pid, 0)
print(time.perf_counter() - t0, ru.ru_utime, ru.ru_stime, ru.ru_maxrss)'

measure() {
  local label=$1
  shift
  [[ -z "${MOZZI_BENCH_ONLY:-}" || "$label" =~ $MOZZI_BENCH_ONLY ]] || return 0
  "$@" >/dev/null 2>&1 || { echo "$label: command failed: $*" >&2; return 1; }  # warm-up
  local rows=() i
  for ((i = 0; i < runs; i++)); do
    # wall, user + sys CPU [s] and peak RSS [kB] of the process, from wait4
    # (microsecond CPU times; GNU time rounds them to 10 ms)
    rows+=("$(python3 -c "$timer" "$@")")
  done
  printf '%s\n' "${rows[@]}" | awk -v label="$label" '
    function median(a, n,   i, j, t) {
      for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] > a[j]; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
      return (n % 2) ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
    }
    { wall[NR] = $1 * 1000; cpu[NR] = ($2 + $3) * 1000; if ($4 > rss) rss = $4 }
    END {
      printf "| %s | %.1f ms | %.1f ms | %.1f MiB |\n", label, median(cpu, NR), median(wall, NR), rss / 1024
    }'
}

echo "mozzi-cli: $cli ($runs runs after a warm-up); load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| command | median CPU (user + sys) | median wall | peak RSS |"
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
