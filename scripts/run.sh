#!/usr/bin/env bash
# Installs what is missing, builds Mozzi (Release) and starts the workbench on
# the demo project (virtual specimens on simulated rigs). Extra arguments go to
# mozzi. Under a headless session run it as: xvfb-run -a scripts/run.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${MOZZI_BUILD_DIR:-$root/build/release}

"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMOZZI_BUILD_TESTS=OFF -DMOZZI_BUILD_BENCHMARKS=OFF
cmake --build "$build" --target mozzi mozzi-cli -j "$(nproc)"

demo=$build/demo.mozzi
if [ ! -f "$demo" ]; then
  "$build/app/mozzi-cli" project demo "$demo"
fi

if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  cat >&2 <<MSG
run.sh: Mozzi is built, but there is no display to show its window on.
  On a desktop, run scripts/run.sh from a terminal of that desktop.
  Headless, use a virtual display:   xvfb-run -a scripts/run.sh
  or take a screenshot and quit:     xvfb-run -a scripts/run.sh --screenshot mozzi.png
MSG
  exit 1
fi
exec "$build/app/mozzi" "$demo" "$@"
