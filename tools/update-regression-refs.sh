#!/usr/bin/env bash
# Rewrites the stored references of the regression suite (README.md, "Regression suite"):
# builds impact3d and postimpact in ./build (configured first when it is not), reruns every
# deck of tests/regression/decks/ into build/regression_runs/ and copies its plot database to
# tests/regression/reference/<name>/, reruns every deck of tests/regression/summary_decks.txt
# and writes tests/regression/summaries/<name>.txt.  The runs are those of the CTest tests
# (tests/regression/run_regression.cmake: SOURCE_DATE_EPOCH=0, ncpu=1, plotwords=8).
# Review `git diff --stat tests/regression` and commit the new references with the change
# that explains them.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
reg=$root/tests/regression
jobs=${JOBS:-2}
[ -f build/CMakeCache.txt ] || cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$jobs" --target impact3d postimpact
impact3d=$root/build/impact3d
postimpact=$root/build/postimpact/postimpact
runs=$root/build/regression_runs
run() {  # MODE DECK NAME REF
  cmake -DIMPACT3D="$impact3d" -DPOSTIMPACT="$postimpact" -DDECK="$2" -DWORKDIR="$runs/$3" \
        -DMODE="$1" -DREF="$4" -DUPDATE=ON -P "$reg/run_regression.cmake"
}
for deck in "$reg"/decks/*.dyn; do
  name=$(basename "$deck" .dyn)
  run plot "$deck" "$name" "$reg/reference/$name"
done
# stored references of decks that no longer exist
for dir in "$reg"/reference/*/; do
  [ -d "$dir" ] || continue
  name=$(basename "$dir")
  [ -f "$reg/decks/$name.dyn" ] || { echo "removing $dir (no deck)"; rm -rf "$dir"; }
done
mkdir -p "$reg/summaries"
while read -r rel; do
  case "$rel" in ''|'#'*) continue ;; esac
  name=$(basename "$rel" .dyn)
  run summary "$root/$rel" "$name" "$reg/summaries/$name.txt"
done < "$reg/summary_decks.txt"
du -sh "$reg/reference"
git -C "$root" status --short -- tests/regression
