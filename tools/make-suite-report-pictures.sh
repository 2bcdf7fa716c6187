#!/usr/bin/env bash
# Regenerates the README pictures of a suite report (docs/regression-suites.md, "Regression suites for users"):
# a suite of three regression decks (tests/regression/decks) in out/suite_demo/suite, references
# stored with `postimpact suite --update`, then one stress value of column_uniaxial_strain's
# reference scaled by 1.001 (the first value of 1 MPa..1 TPa magnitude before the middle of
# d3plot01), the suite run, and the failed deck's report pictures copied to
# docs/images/suite_{ref,new,worst,worst_diff}.png and its HTML page to out/suite_demo/out/.
#
#   POSTIMPACT=build/postimpact/postimpact IMPACT3D=build/impact3d bash tools/make-suite-report-pictures.sh
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
postimpact=${POSTIMPACT:-$root/build/postimpact/postimpact}
export IMPACT3D=${IMPACT3D:-$root/build/impact3d}
demo=$root/out/suite_demo
rm -rf "$demo"
mkdir -p "$demo/suite/decks"
for n in column_rate_failure column_uniaxial_strain one_hex; do
    cp "$root/tests/regression/decks/$n.dyn" "$demo/suite/decks/"
done
cp "$root/tests/regression/tolerances.txt" "$demo/suite/"
"$postimpact" suite "$demo/suite" --update --no-pictures -o "$demo/update" > /dev/null
python3 - "$demo/suite/reference/column_uniaxial_strain/d3plot01" <<'PY'
import struct, sys
f = sys.argv[1]
b = bytearray(open(f, 'rb').read())
for i in range(len(b) // 2 - (len(b) // 2) % 8, 0, -8):
    v = struct.unpack('<d', b[i:i + 8])[0]
    if 1e6 < abs(v) < 1e12:
        b[i:i + 8] = struct.pack('<d', v * 1.001)
        break
open(f, 'wb').write(b)
PY
"$postimpact" suite "$demo/suite" -o "$demo/out" || true   # exit 1: the damaged deck fails
for p in ref new worst worst_diff; do
    cp "$demo/out/column_uniaxial_strain/$p.png" "$root/docs/images/suite_$p.png"
done
echo "report: $demo/out/report.html"
