#!/usr/bin/env bash
# Runs every Kiln check from a clean checkout: installs dependencies, then
#   1. the -Werror build and its full test suite (unit, golden, CLI, fuzz-corpus replay),
#   2. the same suite under AddressSanitizer + UndefinedBehaviorSanitizer (KILN_SANITIZE),
#   3. the libFuzzer targets (clang: ShaderLab parser, pack reader, material parser, glTF loader,
#      compile driver with its worker processes) on their corpora, then bounded fuzz runs,
#   4. the benchmarks, checked against the speed targets in bench/check_targets.py.
# Environment: KILN_FUZZ_SECONDS (default 60) bounds step 3.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)

bash scripts/setup.sh

step() { printf '\n==== %s\n' "$*"; }

step "build (RelWithDebInfo, -Werror)"
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DKILN_WERROR=ON
cmake --build build/release
step "tests"
ctest --test-dir build/release --output-on-failure -j "$(nproc)"

step "build (address,undefined sanitizers)"
cmake -S . -B build/asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DKILN_WERROR=ON \
    -DKILN_SANITIZE=address,undefined
cmake --build build/asan
step "tests under sanitizers"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build/asan --output-on-failure -j "$(nproc)"

step "fuzz (libFuzzer, clang, address,undefined)"
CC=clang CXX=clang++ cmake -S . -B build/fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DKILN_WERROR=ON -DKILN_FUZZ=ON -DKILN_SANITIZE=address,undefined
cmake --build build/fuzz --target kiln_fuzz_shaderlab kiln_fuzz_pack kiln_fuzz_material \
    kiln_fuzz_gltf kiln_fuzz_compile kiln-worker
# New inputs go to a scratch folder; the checked-in corpus is only read.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# fuzz TARGET MAX_LEN TIMEOUT SEED_DIR...: replays the seeds, then fuzzes for KILN_FUZZ_SECONDS.
fuzz() {
    local target=$1 max_len=$2 timeout=$3
    shift 3
    mkdir -p "$scratch/$target"
    build/fuzz/bin/kiln_fuzz_$target -runs=0 "$@"
    build/fuzz/bin/kiln_fuzz_$target -max_total_time="${KILN_FUZZ_SECONDS:-60}" \
        -timeout="$timeout" -rss_limit_mb=2048 -max_len="$max_len" -print_final_stats=1 \
        -artifact_prefix="$scratch/" "$scratch/$target" "$@"
}
fuzz shaderlab 65536 10 tests/fuzz/corpus/shaderlab tests/golden/parse tests/lecture
fuzz pack 65536 10 tests/fuzz/corpus/pack
fuzz material 16384 10 tests/fuzz/corpus/material materials
fuzz gltf 65536 10 tests/fuzz/corpus/gltf
# Each compile input runs glslang in kiln-worker processes, whose own limit is 10 s a program.
fuzz compile 16384 60 tests/fuzz/corpus/compile

step "benchmarks"
build/release/bin/kiln_bench --benchmark_out="$ROOT/build/release/bench.json" \
    --benchmark_out_format=json
python3 bench/check_targets.py build/release/bench.json
