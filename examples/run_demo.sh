#!/usr/bin/env bash
# The README's main command: installs what is missing, builds libmoa and its `moa` tool,
# reconstructs the bundled sample cloud (examples/kitten.xyz, 5,210 points of a genus-1
# surface), shows what came out and draws it into a PNG picture.
set -euo pipefail
cd "$(dirname "$0")/.."

bash tests/install_deps.sh
build=build/demo
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DMOA_BUILD_TESTS=OFF -DMOA_BUILD_BINDINGS=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target moa_cli >/dev/null
mkdir -p "$build/out"
"$build/src/cli/moa" reconstruct examples/kitten.xyz -o "$build/out/kitten.ply" \
  --stats "$build/out/kitten_stats.json" --render "$build/out/kitten.png"
echo
"$build/src/cli/moa" check "$build/out/kitten.ply" --points examples/kitten.xyz
echo
echo "mesh: $build/out/kitten.ply   statistics: $build/out/kitten_stats.json"
echo "picture: $build/out/kitten.png"
