// The cost of isolation: the same compiles with glslang and SPIRV-Tools in kiln-worker processes
// and in-process (--in-process), on the shipped materials (every shader_feature combination) and
// on a generated shader of 1000 variants with 1000 distinct fragment programs. No cache; all
// cores. bench/check_targets.py holds the workers within 10% of in-process (issue 13).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>

#include "kiln/compile.h"
#include "support/test_support.h"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> ShippedMaterials() {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(kiln::test::DataPath("../materials"))) {
        if (e.path().extension() == ".shader")
            out.push_back(e.path().string());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Three multi_compile sets of ten keywords each; every keyword changes the fragment program.
std::string ThousandVariantShader() {
    const std::string path = (fs::temp_directory_path() / "kiln_bench_1000.shader").string();
    std::string pragmas, body;
    for (const char* set : {"A", "B", "C"}) {
        pragmas += "            #pragma multi_compile";
        for (int k = 0; k < 10; ++k) {
            const std::string kw = std::string("_") + set + std::to_string(k);
            pragmas += " " + kw;
            body += "            #ifdef " + kw + "\n            c = c * " +
                    std::to_string(k + 2) + ".5 + float4(" + set[0] + "_OFFSET, 0, 0, 0);\n" +
                    "            #endif\n";
        }
        pragmas += "\n";
    }
    std::ofstream(path) << "Shader \"Bench/Thousand\" {\n"
                           "    Properties { _Color (\"Color\", Color) = (1,1,1,1) }\n"
                           "    SubShader { Pass {\n"
                           "            CGPROGRAM\n"
                           "            #pragma vertex vert\n"
                           "            #pragma fragment frag\n"
                        << pragmas
                        << "            #define A_OFFSET 0.125\n"
                           "            #define B_OFFSET 0.25\n"
                           "            #define C_OFFSET 0.5\n"
                           "            #include \"UnityCG.cginc\"\n"
                           "            float4 _Color;\n"
                           "            float4 vert(float4 v : POSITION) : SV_POSITION {\n"
                           "                return UnityObjectToClipPos(v); }\n"
                           "            float4 frag() : SV_Target {\n"
                           "            float4 c = _Color;\n"
                        << body
                        << "            return c; }\n"
                           "            ENDCG\n"
                           "    } }\n"
                           "}\n";
    return path;
}

void Run(benchmark::State& state, const std::vector<std::string>& files, bool all_features) {
    kiln::CompileOptions options;
    options.isolation = state.range(0) == 0 ? kiln::Isolation::kInProcess : kiln::Isolation::kWorkers;
    options.all_features = all_features;
    size_t programs = 0;
    for (auto _ : state) {
        kiln::DiagnosticList diags;
        const kiln::CompileOutput out = kiln::CompileShaders(files, options, diags);
        if (!out.ok) {
            state.SkipWithError("the compile failed");
            return;
        }
        programs = out.stats.glslang_compiles;
    }
    state.counters["programs"] = double(programs);
    state.SetLabel(state.range(0) == 0 ? "in-process" : "workers");
}

void BM_CompileShippedMaterials(benchmark::State& state) {
    static const std::vector<std::string> files = ShippedMaterials();
    Run(state, files, true);
}
BENCHMARK(BM_CompileShippedMaterials)
    ->ArgName("workers")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(5)
    ->UseRealTime();

void BM_Compile1000Variants(benchmark::State& state) {
    static const std::string file = ThousandVariantShader();
    Run(state, {file}, false);
}
BENCHMARK(BM_Compile1000Variants)
    ->ArgName("workers")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->UseRealTime();

}  // namespace
