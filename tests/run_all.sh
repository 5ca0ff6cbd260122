#!/usr/bin/env bash
# Installs what is missing, builds everything from scratch in build/ci and runs every test
# (all labels but `slow`). This is the README's test command and what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."

bash tests/install_deps.sh --bindings
build=build/ci
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DMOA_BUILD_TESTS=ON
cmake --build "$build" -j"$(nproc)"
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" -LE slow --timeout 900
