// libFuzzer target: the whole compile driver, shader text in, diagnostics or a pack out, with
// glslang and SPIRV-Tools in kiln-worker processes as kiln runs them: whatever the workers do
// (crash, time out, answer garbage), the driver must end in diagnostics, never crash. Every pack
// produced is opened with the reader. The same bytes also go through the worker protocol's
// decoders, which read what a broken worker sends. The corpus in corpus/compile is replayed by
// ctest in every build through fuzz_replay_main.cpp.
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "kiln/compile.h"
#include "kiln/pack/reader.h"
#include "worker/protocol.h"

namespace {

void DecodeAsProtocol(const std::string& bytes) {
    using namespace kiln::worker;
    (void)DecodeRequest(bytes);
    (void)DecodeResponse(bytes);
    (void)DecodeFailure(bytes);
    FrameReader reader;
    for (size_t at = 0; at < bytes.size() && !reader.bad();) {
        const std::span<char> room = reader.Room();
        const size_t n = std::min(room.size(), bytes.size() - at);
        std::copy_n(bytes.data() + at, n, room.data());
        at += n;
        if (reader.Advance(n))
            (void)SplitFrame(reader.Take());
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    DecodeAsProtocol(text);
    static const std::string path =
        "/tmp/kiln_fuzz_compile_" + std::to_string(getpid()) + ".shader";
    FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr)
        return 0;
    std::fwrite(data, 1, size, f);
    std::fclose(f);
    kiln::CompileOptions options;
    options.jobs = 1;
    options.max_variants = 16;             // a fuzzed shader's variants are all alike
    options.program_timeout_seconds = 10;  // under the fuzzer's own -timeout
    options.program_memory_mib = 1024;
    kiln::DiagnosticList diags;
    const kiln::CompileOutput out = kiln::CompileShaders({path}, options, diags);
    if (out.ok) {
        if (!kiln::pack::Pack::Open(out.pack))
            __builtin_trap();  // the compiler wrote a pack its own reader rejects
    }
    std::vector<const kiln::SourceFile*> sources;
    for (const auto& file : out.files)
        sources.push_back(file.get());
    (void)kiln::FormatDiagnosticsText(diags, sources);
    (void)kiln::FormatDiagnosticsJson(diags);
    std::remove(path.c_str());
    return 0;
}
