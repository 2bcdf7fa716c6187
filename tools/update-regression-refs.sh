#!/usr/bin/env bash
# Rewrites the stored references of the regression suite (docs/regression-suites.md, "Regression suite") with
# `postimpact suite tests/regression --update`, the one code path that stores references (users'
# suites use the same command; the CTest tests run `postimpact suite tests/regression --job NAME`,
# the same runs: SOURCE_DATE_EPOCH=0, ncpu=1, plotwords=8, plus a deck's options/NAME.txt):
# every deck of tests/regression/decks/ gets reference/<name>/d3plot*, every deck of
# tests/regression/summary_decks.txt summaries/<name>.txt.  References of decks that no longer
# exist are removed.  Review `git diff --stat tests/regression` and commit the new references
# with the change that explains them.
#
# Environment: BUILD (default ./build; configured and built first when POSTIMPACT is not given),
# POSTIMPACT and IMPACT3D (programs to use instead of BUILD's), JOBS (decks at once, default 2),
# SUITE (the suite folder, default tests/regression: a scratch copy for checking this script).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build=${BUILD:-$root/build}
jobs=${JOBS:-2}
reg=${SUITE:-$root/tests/regression}
if [ -z "${POSTIMPACT:-}" ]; then
  [ -f "$build/CMakeCache.txt" ] || cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$build" -j "$jobs" --target impact3d postimpact
fi
postimpact=${POSTIMPACT:-$build/postimpact/postimpact}
impact3d=${IMPACT3D:-$build/impact3d}
out=$build/regression_update
mkdir -p "$build"
"$postimpact" suite "$reg" --update --no-pictures -j "$jobs" --impact3d "$impact3d" -o "$out"
# stored references of decks that no longer exist
decks=$("$postimpact" suite "$reg" --list)
for dir in "$reg"/reference/*/; do
  [ -d "$dir" ] || continue
  name=$(basename "$dir")
  grep -qx "$name" <<<"$decks" || { echo "removing $dir (no deck)"; rm -rf "$dir"; }
done
for f in "$reg"/summaries/*.txt; do
  [ -f "$f" ] || continue
  name=$(basename "$f" .txt)
  grep -qx "$name" <<<"$decks" || { echo "removing $f (no deck)"; rm -f "$f"; }
done
du -sh "$reg/reference"
git -C "$root" status --short -- "$reg" 2>/dev/null || true
