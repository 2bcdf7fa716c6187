#!/usr/bin/env bash
# Same bits before and after a change that must not change results (a refactoring): runs every
# shipped deck (decks/*.dyn, decks/keyword/*.k) with one impact3d into a folder, and compares two
# such folders file by file: the plot databases d3plot*, the interface-force databases intfor*,
# the time histories (d3thdt*, glstat, matsum, rwforc, rcforc, nodout, elout) byte for byte (cmp),
# the printed file d3hsp and the run log but for their clock readings (elapsed and remaining
# seconds, timings).
#
#   tools/same-bits.sh run IMPACT3D OUTDIR     # e.g. a copy of build/impact3d made before the change
#   tools/same-bits.sh compare OUTDIR_A OUTDIR_B
#
# Runs use SOURCE_DATE_EPOCH=0 (no clock in the databases) and ncpu=1; JOBS decks at once (2).
set -euo pipefail
cd "$(dirname "$0")/.."
# a printed file without its clock readings: the cycle lines' last two columns, the timings
unclocked() {
  sed -E -e 's/^( +[0-9]+ +[-0-9.e+]+ +[-0-9.e+]+ +[0-9]+ +[-0-9.e+]+) +[0-9.]+ +[-0-9.]+$/\1/' \
         -e '/^ cycles [0-9]+, elapsed/d' -e '/^ phase times/d' "$1"
}
case "${1:-}" in
  run)
    impact3d=$(realpath "$2"); out=$3
    rm -rf "$out"; mkdir -p "$out"; out=$(realpath "$out")
    for deck in decks/*.dyn decks/keyword/*.k; do
      name=$(basename "$deck"); echo "$(realpath "$deck") $out/${name%.*}-${deck##*.}"
    done | xargs -P "${JOBS:-2}" -L 1 sh -c 'mkdir -p "$2" && cd "$2" &&
      { SOURCE_DATE_EPOCH=0 "$0" i="$1" ncpu=1 > log 2>&1; echo "exit $?" >> log; }' "$impact3d"
    ;;
  compare)
    a=$2; b=$3; bad=0; n=0
    for dir in "$a"/*/; do
      name=$(basename "$dir")
      [ -d "$b/$name" ] || { echo "missing in $b: $name"; bad=1; continue; }
      ea=$(tail -1 "$a/$name/log"); eb=$(tail -1 "$b/$name/log")
      [ "$ea" = "$eb" ] || { echo "$name: $ea vs $eb"; bad=1; }
      for f in "$dir"d3plot* "$dir"intfor* "$dir"d3thdt* "$dir"{glstat,matsum,rwforc,rcforc,nodout,elout}; do
        [ -e "$f" ] || continue
        n=$((n + 1))
        cmp -s "$f" "$b/$name/$(basename "$f")" || { echo "differs: $name/$(basename "$f")"; bad=1; }
      done
      for f in d3hsp log; do
        [ -e "$dir$f" ] || continue
        n=$((n + 1))
        cmp -s <(unclocked "$dir$f") <(unclocked "$b/$name/$f") || { echo "differs: $name/$f (clock readings aside)"; bad=1; }
      done
      [ "$(ls "$a/$name" | grep -c -E '^(d3plot|intfor|d3thdt)')" = "$(ls "$b/$name" | grep -c -E '^(d3plot|intfor|d3thdt)')" ] ||
        { echo "$name: not the same number of database files"; bad=1; }
    done
    if [ $bad = 0 ]; then echo "same bits: $n files in $(ls -d "$a"/*/ | wc -l) runs"; else exit 1; fi
    ;;
  *) sed -n '2,10p' "$0"; exit 2 ;;
esac
