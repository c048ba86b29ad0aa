#!/usr/bin/env bash
# Runs every Kiln check from a clean checkout: installs dependencies, then
#   1. the -Werror build and its full test suite (unit, golden, CLI, fuzz-corpus replay),
#   2. one clang build with AddressSanitizer + UndefinedBehaviorSanitizer (KILN_SANITIZE) and the
#      libFuzzer targets (KILN_FUZZ): the same suite under the sanitizers, then each target
#      (ShaderLab parser, pack reader, material parser, usage-file and diagnostics readers, glTF
#      loader, image readers, compile driver with its worker processes) on its corpus and a
#      bounded fuzz run,
#   3. the benchmarks' CI subset (scripts/bench.sh --ci), checked against their ratio and count
#      targets (bench/check_targets.py, bench/compile_suite.py; docs/performance.md).
# Environment: KILN_FUZZ_SECONDS (default 30; set it higher for a longer run) bounds each fuzz
# run of step 2.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh

step() { printf '\n==== %s\n' "$*"; }

step "build (RelWithDebInfo, -Werror)"
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DKILN_WERROR=ON
cmake --build build/release
step "tests"
ctest --test-dir build/release --output-on-failure -j "$(nproc)"

# One clang build serves the sanitizers and the fuzzer: AddressSanitizer + UndefinedBehaviorSanitizer
# and libFuzzer's coverage instrumentation on every target, -O2 with assertions on (no NDEBUG).
step "build (clang, address,undefined sanitizers, libFuzzer targets)"
CC=clang CXX=clang++ cmake -S . -B build/sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g" \
    -DKILN_WERROR=ON -DKILN_SANITIZE=address,undefined -DKILN_FUZZ=ON
cmake --build build/sanitize
step "tests under sanitizers"
# The corpus replays (fuzz.replay.*) are left to the fuzz step: libFuzzer runs every seed first.
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build/sanitize --output-on-failure -j "$(nproc)" -E '^fuzz\.replay\.'

step "fuzz (libFuzzer, address,undefined)"
# New inputs go to a scratch folder; the checked-in corpus is only read.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# fuzz TARGET MAX_LEN TIMEOUT SECONDS SEED_DIR...: libFuzzer first runs every seed whole, then
# mutates them until SECONDS have passed since it started.
fuzz() {
    local target=$1 max_len=$2 timeout=$3 seconds=$4
    shift 4
    # libFuzzer would cut a seed longer than -max_len: refuse that instead.
    local long
    long=$(find "$@" -type f -size +"$max_len"c)
    if [ -n "$long" ]; then
        echo "seeds longer than $max_len bytes for kiln_fuzz_$target:" "$long" >&2
        exit 1
    fi
    mkdir -p "$scratch/$target"
    build/sanitize/bin/kiln_fuzz_$target -max_total_time="$seconds" -timeout="$timeout" \
        -rss_limit_mb=2048 -max_len="$max_len" -print_final_stats=1 \
        -artifact_prefix="$scratch/" "$scratch/$target" "$@"
}
seconds=${KILN_FUZZ_SECONDS:-30}
fuzz shaderlab 65536 10 "$seconds" tests/fuzz/corpus/shaderlab tests/golden/parse tests/lecture \
    materials
fuzz pack 65536 10 "$seconds" tests/fuzz/corpus/pack
fuzz material 16384 10 "$seconds" tests/fuzz/corpus/material materials
fuzz usage 65536 10 "$((seconds / 2))" tests/fuzz/corpus/usage
fuzz direct_bundle 65536 10 "$((seconds / 2))" tests/fuzz/corpus/direct_bundle
fuzz module_bundle 65536 10 "$((seconds / 2))" tests/fuzz/corpus/module_bundle
fuzz gltf 65536 10 "$seconds" tests/fuzz/corpus/gltf
fuzz image 65536 10 "$seconds" tests/fuzz/corpus/image
# glslang's preprocessor in-process, as it is and with skipped text blanked: must agree.
fuzz inactive_text 65536 10 "$((seconds / 2))" tests/fuzz/corpus/preprocess templates
# The reduction over preprocessed text: its tokens must be the tokenizer's.
fuzz reduce 65536 10 "$((seconds / 2))" tests/fuzz/corpus/reduce tests/fuzz/corpus/preprocess \
    templates
# Each compile input runs glslang in kiln-worker processes, whose own limit is 10 s a program. Its
# seeds take about 90 s on a 2-core machine before mutation starts: the budget adds them.
fuzz compile 16384 60 "$((seconds + 90))" tests/fuzz/corpus/compile

step "benchmarks (CI subset: scripts/bench.sh runs them all)"
bash scripts/bench.sh --ci
