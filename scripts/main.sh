#!/usr/bin/env bash
# The main job, end to end: install dependencies, build Kiln (which compiles the shipped materials
# into a variant pack), describe that pack, and parse the lecture's shaders.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/release

echo
echo "== kiln variants materials/*.shader"
build/release/bin/kiln variants materials/*.shader
echo
echo "== kiln compile materials/*.shader -o build/release/materials/materials.kpack"
build/release/bin/kiln compile materials/*.shader -o build/release/materials/materials.kpack \
    --cache-dir build/release/kiln-cache --stats
build/release/bin/kiln info build/release/materials/materials.kpack
echo
echo "== kiln parse tests/lecture/*.shader (the lecture's shaders, assembled)"
build/release/bin/kiln parse --quiet tests/lecture/*.shader
echo "all $(ls tests/lecture/*.shader | wc -l) lecture shaders parse without diagnostics"
echo "(compiling them needs the full shader library: the next issue)"
