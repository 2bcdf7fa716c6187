#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (CTest), then the short fuzz run
# (every fuzz target on its fixed sequence of inputs, tools/fuzz.sh; docs/fuzzing.md "Fuzzing and sanitizers").
#
#   tools/test.sh              the tests (build/) and the short fuzz run (build-fuzz/)
#   tools/test.sh --no-fuzz    the tests only
#   tools/test.sh --sanitize   the whole test suite built with AddressSanitizer and
#                              UndefinedBehaviorSanitizer (g++) in build-asan/
set -euo pipefail
cd "$(dirname "$0")/.."
mode=all
case "${1:-}" in
  "") ;;
  --no-fuzz) mode=tests ;;
  --sanitize) mode=sanitize ;;
  *) echo "usage: tools/test.sh [--no-fuzz | --sanitize]" >&2; exit 3 ;;
esac
bash tools/install-deps.sh

if [ "$mode" = sanitize ]; then
  B=build-asan
  mkdir -p "$B"
  SAN="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g1"
  cmake -S . -B "$B" -DCMAKE_BUILD_TYPE=Release -DIMPACT3D_BUILD_BENCH=OFF "-DCMAKE_CXX_FLAGS=$SAN" \
    "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" > "$B/build.log" 2>&1 || { cat "$B/build.log"; exit 1; }
  cmake --build "$B" -j "$(nproc)" >> "$B/build.log" 2>&1 || { tail -50 "$B/build.log"; exit 1; }
  # Every process the tests start (impact3d, postimpact) is instrumented too: any report fails it.
  export ASAN_OPTIONS="abort_on_error=0:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1"
  export LSAN_OPTIONS="suppressions=$PWD/tools/lsan.supp:print_suppressions=0"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  cd "$B"
  ctest --output-on-failure -j "$(nproc)" --timeout 3000
  exit
fi

bash tools/build.sh
(cd build && ctest --output-on-failure -j "$(nproc)" --timeout 1200)
[ "$mode" = all ] && bash tools/fuzz.sh
exit 0
