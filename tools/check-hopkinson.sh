#!/usr/bin/env bash
# Runs the split-Hopkinson bar of constantinoval/pythonScripts (task ak4-diam-V1, 47,500 solids,
# g-mm-ms) from the folder the user gives and compares IMPACT-3D's elout of elements 23500 and
# 46500 with LS-DYNA's pulses shipped beside it (incident plateau within 3 %, reflected and
# transmitted within 10 %; docs/validation.md "Split-Hopkinson bar").  Not part of CI: the deck
# is that repository's, not ours.
#   tools/check-hopkinson.sh DIR [OUT] [--soft N] [--end T] [--ncpu N] [--substitute] [--no-run]
#     DIR: its verification/ folder (verification_tasks.zip, verificationTasks.py, ak4-rez.zip),
#          or a folder with the instantiated diam1.k and ak4-diam-V1-rez.json
#     OUT: where it runs (default out/hopkinson)
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 1 ] || { echo "usage: tools/check-hopkinson.sh DIR [OUT] [--soft N] [--end T] [--ncpu N] [--substitute] [--no-run]" >&2; exit 3; }
[ -x build/impact3d ] || bash tools/build.sh
DIR=$(cd "$1" && pwd)
shift
OUT=$PWD/out/hopkinson
if [ $# -ge 1 ] && [ "${1#--}" = "$1" ]; then OUT=$1; shift; fi
exec python3 tools/check_hopkinson.py "$DIR" "$OUT" "$@"
