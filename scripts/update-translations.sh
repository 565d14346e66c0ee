#!/usr/bin/env bash
# Refreshes translations/*.ts from the tr() strings in app/ and views/.
# New strings appear as unfinished in mozzi_it.ts: translate them in Qt Linguist
# (or by editing the file) before committing; the test translations_current checks.
set -euo pipefail
cd "$(dirname "$0")/.."
LUPDATE=${LUPDATE:-$(command -v lupdate || echo /usr/lib/qt5/bin/lupdate)}
for ts in translations/mozzi_*.ts; do
  "$LUPDATE" -no-obsolete -locations relative -I . app views -ts "$ts"
done
