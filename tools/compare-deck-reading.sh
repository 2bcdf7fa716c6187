#!/usr/bin/env bash
# Same reading before and after a change to the deck readers (a refactoring): runs one impact3d
# with --check, --write-keyword and --write-fixed on every deck the repository holds (decks/,
# tests/, the fuzz seeds; any file with a *KEYWORD line or a .k/.key/.dyn/.inc name) and on the
# decks of any further folders named, and compares two such runs: the messages (stdout and
# stderr), the exit codes and the converted decks, byte for byte (the output folder's name
# aside).
#
#   tools/compare-deck-reading.sh run IMPACT3D OUTDIR [FOLDER...]   # e.g. a copy of build/impact3d made before
#   tools/compare-deck-reading.sh compare OUTDIR_A OUTDIR_B
#
# Each deck is read in its own folder (*INCLUDE files are found); JOBS decks at once (2).
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
  run)
    impact3d=$(realpath "$2"); out=$3; shift 3
    rm -rf "$out"; mkdir -p "$out"; out=$(realpath "$out")
    { find decks tests fuzz/seeds -type f \( -name '*.k' -o -name '*.key' -o -name '*.dyn' -o -name '*.inc' \)
      grep -rlis '^\*KEYWORD' decks tests fuzz/seeds || true
      find tests/input/malformed tests/fuzz/keyword_deck tests/fuzz/fixed_deck -type f 2> /dev/null || true
      for d in "$@"; do find "$d" -maxdepth 1 -type f; done; } | sort -u |
      while read -r deck; do
        p=$(realpath "$deck"); echo "$p $out/$(echo "${deck#./}" | tr '/' '_')"
      done | xargs -P "${JOBS:-2}" -L 1 sh -c 'cd "$(dirname "$1")" &&
        { timeout 120 "$0" i="$1" --check > "$2.check" 2>&1; echo "exit $?" >> "$2.check";
          timeout 120 "$0" i="$1" --write-keyword="$2.conv.k" > "$2.kout" 2>&1; echo "exit $?" >> "$2.kout";
          timeout 120 "$0" i="$1" --write-fixed="$2.conv.dyn" > "$2.fout" 2>&1; echo "exit $?" >> "$2.fout"; }' "$impact3d"
    echo "$(ls "$out" | grep -c '\.check$') decks read into $out"
    ;;
  compare)
    a=$(realpath "$2"); b=$(realpath "$3"); bad=0; n=0
    for f in "$a"/*; do
      name=$(basename "$f"); n=$((n + 1))
      [ -e "$b/$name" ] || { echo "missing in $b: $name"; bad=$((bad + 1)); continue; }
      cmp -s <(sed "s#$a/##g" "$f") <(sed "s#$b/##g" "$b/$name") || { echo "differs: $name"; bad=$((bad + 1)); }
    done
    for f in "$b"/*; do [ -e "$a/$(basename "$f")" ] || { echo "missing in $a: $(basename "$f")"; bad=$((bad + 1)); }; done
    echo "$n files compared, $bad differ"
    [ "$bad" -eq 0 ]
    ;;
  *) echo "usage: $0 run IMPACT3D OUTDIR [FOLDER...] | compare OUTDIR_A OUTDIR_B" >&2; exit 2 ;;
esac
