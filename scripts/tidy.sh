#!/usr/bin/env bash
# clang-tidy 14 over the C++ sources a change touches (issue 24), with the
# checks of .clang-tidy and the compile commands of the build folder.
#
#   scripts/tidy.sh [BASE]      files changed since BASE (default: main), plus
#                               uncommitted changes
#   scripts/tidy.sh --all PATH  every .cpp under PATH (e.g. core/gap)
#
# A changed header is checked through the .cpp files of its folder that
# include it (clang-tidy needs a translation unit). Exit status 1 when
# clang-tidy reports anything. MOZZI_TIDY_BUILD_DIR (default build/test)
# holds compile_commands.json; configure it first (README). Runs on
# $(nproc) files at a time.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
build=${MOZZI_TIDY_BUILD_DIR:-build/test}
tidy=${CLANG_TIDY:-clang-tidy-14}
if [ ! -f "$build/compile_commands.json" ]; then
  echo "tidy.sh: $build/compile_commands.json not found: configure the build first" >&2
  exit 2
fi
if [ "${1:-}" = "--all" ]; then
  mapfile -t files < <(git ls-files "${2:?--all needs a path}" | grep -E '\.cpp$' || true)
else
  base=${1:-main}
  mapfile -t changed < <({ git diff --name-only --diff-filter=d "$base"...HEAD; git diff --name-only --diff-filter=d HEAD; } |
    grep -E '^(core|devices|views|app|tests)/.*\.(cpp|h)$' | sort -u || true)
  files=()
  for f in "${changed[@]}"; do
    if [[ $f == *.cpp ]]; then
      files+=("$f")
    else
      # A header: the sources of its folder that include it.
      while IFS= read -r s; do files+=("$s"); done < <(grep -l "#include \"$f\"" "$(dirname "$f")"/*.cpp 2>/dev/null || true)
    fi
  done
  mapfile -t files < <(printf '%s\n' "${files[@]}" | sort -u | sed '/^$/d')
fi
# Only files the build compiles (a test of a disabled target, a GUI file in a
# build without the GUI: nothing to check against).
known=()
for f in "${files[@]}"; do
  if grep -q "\"file\": \"$root/$f\"" "$build/compile_commands.json"; then known+=("$f"); fi
done
if [ ${#known[@]} -eq 0 ]; then
  echo "tidy.sh: no compiled C++ source changed"
  exit 0
fi
echo "tidy.sh: ${#known[@]} file(s)"
log=$(mktemp)
printf '%s\n' "${known[@]}" | xargs -P "$(nproc)" -n 1 "$tidy" -p "$build" --quiet 2> /dev/null > "$log" || true
if grep -qE '^[^ ]+:[0-9]+:[0-9]+: (warning|error):' "$log"; then
  cat "$log"
  echo "tidy.sh: $(grep -cE '^[^ ]+:[0-9]+:[0-9]+: (warning|error):' "$log") finding(s)" >&2
  rm -f "$log"
  exit 1
fi
rm -f "$log"
echo "tidy.sh: clean"
