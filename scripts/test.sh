#!/usr/bin/env bash
# Runs every Kiln check from a clean checkout: installs dependencies, then
#   1. the -Werror build and its full test suite (unit, golden, CLI, fuzz-corpus replay),
#   2. the same suite under AddressSanitizer + UndefinedBehaviorSanitizer (KILN_SANITIZE),
#   3. the libFuzzer targets (clang: ShaderLab parser, pack reader) on their corpora, then bounded
#      fuzz runs,
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
cmake --build build/fuzz --target kiln_fuzz_shaderlab kiln_fuzz_pack kiln_fuzz_material
# New inputs go to a scratch folder; the checked-in corpus is only read.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
build/fuzz/bin/kiln_fuzz_shaderlab -runs=0 tests/fuzz/corpus/shaderlab tests/golden/parse tests/lecture
build/fuzz/bin/kiln_fuzz_shaderlab -max_total_time="${KILN_FUZZ_SECONDS:-60}" -timeout=10 \
    -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix="$scratch/" \
    "$scratch" tests/fuzz/corpus/shaderlab tests/golden/parse tests/lecture

build/fuzz/bin/kiln_fuzz_pack -runs=0 tests/fuzz/corpus/pack
build/fuzz/bin/kiln_fuzz_pack -max_total_time="${KILN_FUZZ_SECONDS:-60}" -timeout=10 \
    -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix="$scratch/" \
    "$scratch" tests/fuzz/corpus/pack

mkdir -p "$scratch/material"
build/fuzz/bin/kiln_fuzz_material -runs=0 tests/fuzz/corpus/material materials
build/fuzz/bin/kiln_fuzz_material -max_total_time="${KILN_FUZZ_SECONDS:-60}" -timeout=10 \
    -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1 -artifact_prefix="$scratch/" \
    "$scratch/material" tests/fuzz/corpus/material

step "benchmarks"
build/release/bin/kiln_bench --benchmark_out="$ROOT/build/release/bench.json" \
    --benchmark_out_format=json
python3 bench/check_targets.py build/release/bench.json
