// Front-end benchmarks. The target "a 1 MB, deeply nested file parses in under a second" is
// checked by bench/check_targets.py over this binary's JSON output, not by a timed unit test.
#include <benchmark/benchmark.h>

#include "kiln/shaderlab/parse.h"
#include "support/test_support.h"

namespace {

void BM_ParseAndCheckStress1MB(benchmark::State& state) {
    const std::string text = kiln::test::MakeStressShader(1 << 20, 50);
    const kiln::SourceFile file("stress.shader", text);
    for (auto _ : state) {
        kiln::DiagnosticList diags;
        auto shader = kiln::shaderlab::ParseAndCheck(file, diags);
        benchmark::DoNotOptimize(shader);
        if (diags.has_errors()) {
            state.SkipWithError("stress shader has errors");
        }
    }
    state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_ParseAndCheckStress1MB)->Unit(benchmark::kMillisecond);

void BM_ParseLectureSpotLight(benchmark::State& state) {
    const kiln::SourceFile file(
        "s.shader", kiln::test::ReadFile(kiln::test::DataPath("lecture/11_SpotLight.shader")));
    for (auto _ : state) {
        kiln::DiagnosticList diags;
        auto shader = kiln::shaderlab::ParseAndCheck(file, diags);
        benchmark::DoNotOptimize(shader);
    }
}
BENCHMARK(BM_ParseLectureSpotLight)->Unit(benchmark::kMicrosecond);

void BM_DumpJsonStress1MB(benchmark::State& state) {
    const kiln::SourceFile file("stress.shader", kiln::test::MakeStressShader(1 << 20, 50));
    kiln::DiagnosticList diags;
    const auto shader = kiln::shaderlab::ParseAndCheck(file, diags);
    for (auto _ : state) {
        benchmark::DoNotOptimize(kiln::shaderlab::DumpJson(*shader));
    }
}
BENCHMARK(BM_DumpJsonStress1MB)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
