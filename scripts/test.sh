#!/usr/bin/env bash
# Installs what is missing, builds everything (Release, warnings are errors) and
# runs the whole ctest suite; GUI tests run on a virtual X display (Xvfb, with
# Mesa's software OpenGL for VTK). Extra arguments go to ctest, e.g. -L unit.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${MOZZI_BUILD_DIR:-$root/build/test}
jobs=$(nproc)

"$root/scripts/install-deps.sh"
"$root/scripts/check-format.sh"
start=$(date +%s)
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$jobs"
echo "test.sh: build took $(( $(date +%s) - start )) s"

export LIBGL_ALWAYS_SOFTWARE=1 QT_QPA_PLATFORM=xcb
ctest_cmd=(ctest --test-dir "$build" --output-on-failure -j "$jobs" "$@")
if [ -n "${DISPLAY:-}" ]; then
  exec "${ctest_cmd[@]}"
fi
exec xvfb-run -a -s "-screen 0 1920x1080x24 -nolisten tcp" "${ctest_cmd[@]}"
