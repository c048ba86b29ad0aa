// The cost of isolation: the same compiles with glslang and SPIRV-Tools in kiln-worker processes
// and in-process (--in-process), on the shipped materials (every shader_feature combination) and
// on a generated shader of 1000 variants with 1000 distinct fragment programs. No cache; all
// cores. Each iteration is a fresh `kiln compile` process, as a build runs it: in one long-lived
// process the in-process mode would keep a warm heap and glslang's tables from one iteration to
// the next, which no build sees. bench/check_targets.py holds the workers within 15% of
// in-process (issue 13; docs/variants.md has the measurements).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

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

std::string CompileCommand(const std::vector<std::string>& files, bool all_features, bool workers) {
    std::string cmd = std::string(KILN_BINARY) + " compile";
    for (const std::string& f : files)
        cmd += " '" + f + "'";
    cmd += " -o '" + (fs::temp_directory_path() / "kiln_bench.kpack").string() + "' --no-cache";
    cmd += all_features ? " --all-features" : "";
    return cmd + (workers ? "" : " --in-process");
}

double Median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

// Runs the two modes alternately, `pairs` times each, so that a machine that speeds up or slows
// down during the run affects both alike; reports each mode's median and their ratio.
void Compare(benchmark::State& state, const std::vector<std::string>& files, bool all_features) {
    constexpr int kPairs = 5;
    std::vector<double> in_process, workers;
    for (auto _ : state) {
        for (int i = 0; i < kPairs; ++i) {
            for (bool w : {false, true}) {
                const auto start = std::chrono::steady_clock::now();
                if (std::system(CompileCommand(files, all_features, w).c_str()) != 0) {
                    state.SkipWithError("the compile failed");
                    return;
                }
                const std::chrono::duration<double, std::milli> ms =
                    std::chrono::steady_clock::now() - start;
                (w ? workers : in_process).push_back(ms.count());
            }
        }
    }
    state.counters["in_process_ms"] = Median(in_process);
    state.counters["workers_ms"] = Median(workers);
    state.counters["ratio"] = Median(workers) / Median(in_process);
}

void BM_IsolationShippedMaterials(benchmark::State& state) {
    static const std::vector<std::string> files = ShippedMaterials();
    Compare(state, files, true);
}
BENCHMARK(BM_IsolationShippedMaterials)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->UseRealTime();

void BM_Isolation1000Variants(benchmark::State& state) {
    static const std::string file = ThousandVariantShader();
    Compare(state, {file}, false);
}
BENCHMARK(BM_Isolation1000Variants)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

}  // namespace
