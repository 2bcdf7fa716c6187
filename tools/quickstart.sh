#!/usr/bin/env bash
# Quick start: install what is missing, build, and run the seed's Taylor bar end to end.
# Output goes to out/taylor_bar/ (printed output d3hsp, plot database d3plot*, pictures).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
bash tools/build.sh
mkdir -p out/taylor_bar
cd out/taylor_bar
../../build/impact3d i=../../decks/taylor_bar.dyn o=d3hsp g=d3plot
if [ -x ../../build/postimpact/postimpact ]; then
  ../../build/postimpact/postimpact d3plot
fi
echo "results in out/taylor_bar/: $(ls | tr '\n' ' ')"
