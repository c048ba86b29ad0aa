// libFuzzer target: Kiln's glTF loader (runtime::LoadGltf, with its limits and checks in front of
// tinygltf) on arbitrary bytes, as a .gltf file, or as a .glb when the bytes start like one. Every
// scene that loads is walked (bounds, instances, lights). The corpus in corpus/gltf is replayed by
// ctest in every build through fuzz_replay_main.cpp.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "kiln/runtime/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // One scratch file per process: the loader reads paths (buffers and images relative to it).
    static const std::string stem = "/tmp/kiln_fuzz_gltf_" + std::to_string(getpid());
    const bool binary = size >= 4 && std::string(reinterpret_cast<const char*>(data), 4) == "glTF";
    const std::string path = stem + (binary ? ".glb" : ".gltf");
    FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr)
        return 0;
    std::fwrite(data, 1, size, f);
    std::fclose(f);
    kiln::DiagnosticList diags;
    const kiln::Result<kiln::runtime::Scene> scene = kiln::runtime::LoadGltf(path, diags);
    if (scene) {
        (void)kiln::runtime::SceneBounds(scene.value());
        for (const auto& light : scene.value().lights)
            (void)kiln::runtime::ShaderLightColor(light);
    }
    for (const kiln::Diagnostic& d : diags.all()) {
        if (d.severity != kiln::Severity::kWarning || d.message.empty())
            __builtin_trap();  // the loader's warnings are warnings, each with a message
    }
    std::remove(path.c_str());
    return 0;
}
