#!/usr/bin/env bash
# The test command of README.md: set-up, build, then the whole ctest suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc)" "$@"
