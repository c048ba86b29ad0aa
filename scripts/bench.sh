#!/usr/bin/env bash
# Kiln's benchmark suite in one command (issue 19; docs/performance.md holds the results):
#   1. bench/kiln_bench (Google Benchmark, a release build): ShaderLab parsing, the cost of worker
#      isolation, the runtime's variant lookup, pack open at 3 MB and 125 MB, a frame's CPU cost
#      per draw at 100 and 1,000 objects (Vulkan: lavapipe without a GPU); checked by
#      bench/check_targets.py;
#   2. bench/compile_suite.py: `kiln compile` cold, warm, one include edited, one keyword added,
#      -j 1 against every core, peak memory, the naive glslangValidator + spirv-opt + spirv-val
#      process chain and the floor, on the shipped materials, a generated forward shader at 8, 64,
#      512 and 1024 variants, Unity's Standard (from ../shared, when present) and 10,240 variants.
# Usage: scripts/bench.sh [--ci]   --ci: the subset CI runs (scripts/test.sh), a few minutes.
# Both steps fail on a missed ratio or count target, never on an absolute time.
set -euo pipefail
cd "$(dirname "$0")/.."
ci=
if [ "${1:-}" = "--ci" ]; then ci=--ci; elif [ -n "${1:-}" ]; then
    echo "usage: scripts/bench.sh [--ci]" >&2
    exit 2
fi
if [ ! -x build/release/bin/kiln ] || [ ! -x build/release/bin/kiln_bench ]; then
    cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
fi
cmake --build build/release
status=0
build/release/bin/kiln_bench --benchmark_out=build/release/bench.json --benchmark_out_format=json
python3 bench/check_targets.py build/release/bench.json || status=1
python3 bench/compile_suite.py --kiln build/release/bin/kiln $ci \
    --json build/release/compile_suite.json --markdown build/release/compile_suite.md || status=1
exit $status
