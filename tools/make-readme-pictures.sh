#!/usr/bin/env bash
# Regenerates the README pictures of the three seed examples (docs/validation.md, "Seed examples"):
# builds if needed (tools/build.sh), runs decks/{taylor_bar,crossed_cylinders,oblique_rod}.dyn
# into out/seed/<name>/ with ncpu=2, then renders each with postimpact and the command file
# tools/pictures/<name>.cmd into docs/images/<name>_*.png.
#
#   bash tools/make-readme-pictures.sh                 # build, run the three decks, render
#   bash tools/make-readme-pictures.sh --pictures-only # render from the runs already in out/seed
#   bash tools/make-readme-pictures.sh taylor_bar      # only the examples named
#
# The full run of the oblique rod (~80,000 cycles) takes minutes; the other two seconds.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

run=1
names=()
for a in "$@"; do
    case "$a" in
        --pictures-only) run=0 ;;
        taylor_bar|crossed_cylinders|oblique_rod) names+=("$a") ;;
        -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
        *) echo "make-readme-pictures: unknown argument '$a'" >&2; exit 3 ;;
    esac
done
[ ${#names[@]} -gt 0 ] || names=(taylor_bar crossed_cylinders oblique_rod)

bash tools/build.sh
impact3d="$root/build/impact3d"
postimpact="$root/build/postimpact/postimpact"
images="$root/docs/images"
mkdir -p "$images"

for name in "${names[@]}"; do
    dir="$root/out/seed/$name"
    if [ "$run" = 1 ]; then
        rm -rf "$dir"
        mkdir -p "$dir"
        echo "== $name: impact3d i=decks/$name.dyn ncpu=2 (out/seed/$name/)"
        (cd "$dir" && "$impact3d" i="$root/decks/$name.dyn" o=d3hsp g=d3plot ncpu=2 > run.log) ||
            { echo "make-readme-pictures: $name: impact3d failed (out/seed/$name/run.log)" >&2; exit 1; }
        grep -E '^ *cycles [0-9]+, elapsed' "$dir/d3hsp" || true
    fi
    [ -f "$dir/d3plot" ] || { echo "make-readme-pictures: $dir/d3plot missing (run without --pictures-only)" >&2; exit 1; }
    echo "== $name: postimpact -c tools/pictures/$name.cmd"
    (cd "$dir" && "$postimpact" d3plot -d "$images" -c "$root/tools/pictures/$name.cmd" > render.log) ||
        { cat "$dir/render.log" >&2; exit 1; }
    mv -f "$images/$name"_*.csv "$dir/"   # the plotted data (CSV) stay with the run
done
ls -l "$images"/*.png | awk '{ printf "%8d  %s\n", $5, $NF }'
