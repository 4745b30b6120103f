#!/usr/bin/env bash
# Installs what is missing, configures and builds into build/ (Release): everything, or only the targets named
# (bash scripts/build.sh cavity-modes chain-rom: the two programs, what the default job needs).
set -euo pipefail
# --help / -h: this text, nothing else (no install, no build).
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  echo "usage: bash scripts/build.sh [TARGET...]"
  sed -n '2,/^set -euo/p' "$0" | grep '^#' | grep -v -- '--help / -h' | sed 's/^# \{0,1\}//'
  exit 0
fi
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# Ninja, not make: a library's objects compile while the libraries below it still link, so both cores stay busy to the
# end (docs/benchmarks.md, "Build time"). A build folder that make configured is configured anew (its objects
# rebuilt once): CMake cannot change a folder's generator.
if [ -f build/CMakeCache.txt ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' build/CMakeCache.txt; then
  echo "build.sh: build/ was configured for another generator; configuring it anew for Ninja"
  rm -rf build/CMakeCache.txt build/CMakeFiles
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > build-configure.log 2>&1 || { cat build-configure.log; exit 1; }
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j "$(nproc)" "${targets[@]}"
