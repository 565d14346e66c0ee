#!/usr/bin/env bash
# Fails when translations/ is stale: a tr() string in app/ or views/ missing from
# the .ts files, or an Italian entry left unfinished. Works on copies, never on
# the committed files.
set -euo pipefail
src=$1
lupdate=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
for ts in "$src"/translations/mozzi_*.ts; do
  cp "$ts" "$work/"
  out=$(cd "$src" && "$lupdate" -no-obsolete -locations relative -I . app views -ts "$work/$(basename "$ts")" 2>&1)
  if ! grep -q "(0 new and" <<<"$out"; then
    echo "$(basename "$ts"): tr() strings missing; run scripts/update-translations.sh"
    grep "Found" <<<"$out"
    status=1
  fi
done
unfinished=$(grep -c 'type="unfinished"' "$work/mozzi_it.ts" || true)
if [ "$unfinished" != "0" ]; then
  echo "mozzi_it.ts: $unfinished Italian translation(s) unfinished"
  status=1
fi
[ $status = 0 ] && echo "translations current: every tr() string is in translations/ and translated to Italian"
exit $status
