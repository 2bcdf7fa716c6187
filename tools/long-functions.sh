#!/usr/bin/env bash
# Lists the functions longer than a limit (default 120 lines, definition line to closing brace),
# longest first: "lines file:first-last name". Uses Universal Ctags (its end: field).
# Usage: tools/long-functions.sh [LIMIT] [FOLDER...]   (default folders: impact3d common postimpact)
# A function that must stay long says why in a comment "long-function: <reason>" on the line
# above its definition; those are listed with the reason, after the others.
set -euo pipefail
cd "$(dirname "$0")/.."
limit=${1:-120}
shift || true
folders=("$@")
[ ${#folders[@]} -gt 0 ] || folders=(impact3d common postimpact)
command -v ctags > /dev/null || { echo "tools/long-functions.sh: needs Universal Ctags (apt install universal-ctags)" >&2; exit 2; }
find "${folders[@]}" -name '*.cpp' -o -name '*.h' | sort |
  ctags -L - --languages=C++ --kinds-C++=f --fields=+ne --extras=-F -o - 2> /dev/null |
  awk -F'\t' -v limit="$limit" '
    {
      line = 0; end = 0
      for (i = 4; i <= NF; i++) {
        if ($i ~ /^line:/) line = substr($i, 6) + 0
        if ($i ~ /^end:/) end = substr($i, 5) + 0
      }
      n = end - line + 1
      if (line > 0 && end > 0 && n > limit) {
        reason = ""
        if (line > 1) {
          cmd = "sed -n " (line - 1) "p \"" $2 "\""
          cmd | getline prev; close(cmd)
          if (prev ~ /long-function:/) { sub(/.*long-function:[ ]*/, "", prev); reason = prev }
        }
        printf "%d\t%s:%d-%d\t%s\t%s\n", n, $2, line, end, $1, reason
      }
    }' | sort -t$'\t' -k1,1nr |
  awk -F'\t' '$4 == "" { printf "%5d  %s  %s\n", $1, $2, $3 }
              $4 != "" { kept[++k] = sprintf("%5d  %s  %s  (kept long: %s)", $1, $2, $3, $4) }
              END { for (i = 1; i <= k; i++) print kept[i] }'
