#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) with clang in build-fuzz/ and runs each of them
# (docs/fuzzing.md, "Fuzzing and sanitizers").
#
#   tools/fuzz.sh                 replay (what CI runs): every target over its seeds, whole, and
#                                 the inputs of tests/fuzz/TARGET, under ASan + UBSan, no
#                                 mutation: the same inputs every run (CTest label fuzz)
#   tools/fuzz.sh --seconds N     short mutation run: every target N s from a fresh random seed,
#                                 two at a time (CTest label fuzz_mutate; not deterministic)
#   tools/fuzz.sh --campaign N [TARGET...]
#                                 long run: one target after the other, N s each, one process,
#                                 nice 19, keeping the grown corpus in build-fuzz/fuzz-campaign/TARGET/
#                                 and crash inputs as build-fuzz/fuzz-campaign/TARGET-crash-*
#   tools/fuzz.sh --build-only    build and make the seed corpora only
#
# Crash inputs go to build-fuzz/fuzz-short/TARGET-crash-* (mutation run) or fuzz-replay/ (replay);
# replay one with build-fuzz/fuzz/fuzz_TARGET FILE.  Keep each as a regression input in
# tests/fuzz/TARGET/ once it is fixed.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=replay
seconds=20
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) mode=mutate; seconds="$2"; shift 2 ;;
    --campaign) mode=campaign; seconds="$2"; shift 2 ;;
    --build-only) mode=build; shift ;;
    -h|--help) sed -n '2,19p' "$0"; exit 0 ;;
    *) targets+=("$1"); shift ;;
  esac
done

B=build-fuzz
mkdir -p "$B"
FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
CXX=clang++ CC=clang cmake -S . -B "$B" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DIMPACT3D_FUZZ=ON \
  -DIMPACT3D_BUILD_TESTS=OFF -DIMPACT3D_BUILD_BENCH=OFF \
  "-DCMAKE_CXX_FLAGS=$FLAGS" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" \
  "-DIMPACT3D_FUZZ_SECONDS=$seconds" > "$B/build.log" 2>&1 || { cat "$B/build.log"; exit 1; }
cmake --build "$B" -j "$(nproc)" --target fuzz_all impact3d >> "$B/build.log" 2>&1 ||
  { tail -50 "$B/build.log"; exit 1; }
# Seed corpora (impact3d of this build writes the restart-dump seeds; leaks do not matter there).
ASAN_OPTIONS=detect_leaks=0 python3 fuzz/make_corpus.py "$PWD" "$B/fuzz-corpus" "$PWD/$B/impact3d" > "$B/corpus.log" ||
  { cat "$B/corpus.log"; exit 1; }
[ "$mode" = build ] && { cat "$B/corpus.log"; exit 0; }

if [ "$mode" = replay ] || [ "$mode" = mutate ]; then
  label='^fuzz$'
  [ "$mode" = mutate ] && label='^fuzz_mutate$'
  regex=""
  prefix=fuzz_
  [ "$mode" = mutate ] && prefix=fuzz_mutate_
  [ ${#targets[@]} -gt 0 ] && regex="-R ^${prefix}($(IFS='|'; echo "${targets[*]}"))\$"
  # shellcheck disable=SC2086
  ctest --test-dir "$B/fuzz" -L "$label" -j 2 --output-on-failure $regex
  exit
fi

# campaign: one fuzzer process at a time, nice 19
[ ${#targets[@]} -eq 0 ] && targets=(fixed_deck keyword_deck plot_database postimpact_database restart_dump command_file tolerances mili_database)
C="$B/fuzz-campaign"
mkdir -p "$C"
for t in "${targets[@]}"; do
  mkdir -p "$C/$t"
  dict=()
  [ -f "fuzz/dict/$t.dict" ] && dict=("-dict=fuzz/dict/$t.dict")
  regressions=()
  [ -d "tests/fuzz/$t" ] && regressions=("tests/fuzz/$t")
  max_len=$(awk -v t="$t" '$1 == t { print "-max_len=" $2 }' fuzz/max_len.txt)
  echo "== $t: ${seconds} s"
  # (-timeout=60: under nice 19 on a loaded machine a 0.5 s input can take 15 s of wall time)
  nice -n 19 "$B/fuzz/fuzz_$t" "$C/$t" "$B/fuzz-corpus/$t" "${regressions[@]}" "${dict[@]}" $max_len -max_total_time="$seconds" \
    -timeout=60 -rss_limit_mb=2048 -malloc_limit_mb=1024 -print_final_stats=1 \
    -artifact_prefix="$C/$t-" > "$C/$t.log" 2>&1 || echo "   $t: finding, see $C/$t.log"
  grep -E '^stat::(number_of_executed_units|peak_rss_mb)|^Done|ERROR|SUMMARY' "$C/$t.log" | sed 's/^/   /' || true
done
