#!/usr/bin/env bash
# Runs every real DYNA3D deck of a folder laid out like LLNL GRIZ's Src/test (image/NAME/NAME.dyn,
# derived/NAME_th.answ) and prints, per deck and per answer curve, IMPACT-3D's value against
# DYNA3D's at every answer time (largest deviation, the end time, verdict against the tolerance
# of docs/dyna3d-decks.md).  Not part of CI: the decks are LLNL's, not ours.
#   tools/check-dyna3d-decks.sh DIR [OUT]      (builds first if build/impact3d is missing)
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 1 ] || { echo "usage: tools/check-dyna3d-decks.sh DIR [OUT]" >&2; exit 3; }
[ -x build/impact3d ] && [ -x build/postimpact/postimpact ] || bash tools/build.sh
DIR=$(cd "$1" && pwd)
OUT=${2:-$PWD/out/dyna3d-check}
exec python3 tools/check_dyna3d_decks.py "$DIR" "$OUT"
