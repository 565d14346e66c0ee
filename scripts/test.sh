#!/usr/bin/env bash
# Installs what is missing, builds everything (Release, warnings are errors) and
# runs the whole ctest suite; GUI tests run on a virtual X display (Xvfb, with
# Mesa's software OpenGL for VTK). Extra arguments go to ctest, e.g. -L unit.
# Then the sanitizer stage (scripts/sanitize.sh: ASan + UBSan over the unit
# tests and the fuzz corpora); MOZZI_SKIP_SANITIZE=1 leaves it out. Fails when
# either fails.
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
if [ -z "${DISPLAY:-}" ]; then
  ctest_cmd=(xvfb-run -a -s "-screen 0 1920x1080x24 -nolisten tcp" "${ctest_cmd[@]}")
fi
start=$(date +%s)
suite=0
"${ctest_cmd[@]}" || suite=$?
echo "test.sh: test suite took $(( $(date +%s) - start )) s"
sanitize=0
"$root/scripts/sanitize.sh" || sanitize=$?
if [ "$suite" -ne 0 ] || [ "$sanitize" -ne 0 ]; then
  echo "test.sh: FAILED (test suite exit $suite, sanitizer stage exit $sanitize)" >&2
  exit 1
fi
