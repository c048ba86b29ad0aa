// libFuzzer target: the whole ShaderLab front end (lexer, parser, checks, both dumps) on arbitrary
// bytes. Build with -DKILN_FUZZ=ON and clang; the corpus in corpus/shaderlab is replayed by ctest
// in every build through fuzz_replay_main.cpp.
#include <cstddef>
#include <cstdint>
#include <string>

#include "kiln/shaderlab/parse.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const kiln::SourceFile file("fuzz.shader",
                                std::string(reinterpret_cast<const char*>(data), size));
    kiln::DiagnosticList diags;
    const auto shader = kiln::shaderlab::ParseAndCheck(file, diags);
    if (shader) {
        (void)kiln::shaderlab::DumpJson(*shader);
        (void)kiln::shaderlab::DumpText(*shader);
    }
    (void)kiln::FormatDiagnosticsText(diags, {&file});
    (void)kiln::FormatDiagnosticsJson(diags);
    return 0;
}
