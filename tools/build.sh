#!/usr/bin/env bash
# Configures and builds IMPACT-3D (Release) in ./build; the compiler output goes to
# build/build.log and is shown only when the build fails.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p build
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build/build.log 2>&1 || { cat build/build.log; exit 1; }
cmake --build build -j "$(nproc)" >> build/build.log 2>&1 || { tail -50 build/build.log; exit 1; }
echo "built: build/impact3d $( [ -x build/postimpact/postimpact ] && echo build/postimpact/postimpact)"
