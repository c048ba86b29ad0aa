#!/usr/bin/env bash
# The main job, end to end: install dependencies, build Kiln (which checks the shipped materials),
# and run the front end over the shipped materials and the lecture's shaders.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/release

echo
echo "== kiln parse materials/*.shader"
build/release/bin/kiln parse materials/*.shader
echo
echo "== kiln parse tests/lecture/*.shader (the lecture's shaders, assembled)"
build/release/bin/kiln parse --quiet tests/lecture/*.shader
echo "all $(ls tests/lecture/*.shader | wc -l) lecture shaders parse without diagnostics"
