// Small glTF files written by tests: one triangle to edit, written under the test's name into a
// scratch folder and loaded, with the load's error or scene and its warnings.
#ifndef KILN_TESTS_RUNTIME_GLTF_FILES_H_
#define KILN_TESTS_RUNTIME_GLTF_FILES_H_

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "kiln/runtime/scene.h"

namespace kiln::test {

// `bytes` as a base64 data URI (RFC 4648), for buffers written in the JSON.
inline std::string DataUri(const std::string& bytes) {
    static constexpr char kDigits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out = "data:application/octet-stream;base64,";
    const size_t n = bytes.size();
    for (size_t i = 0; i < n; i += 3) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
        v |= i + 1 < n ? uint32_t(uint8_t(bytes[i + 1])) << 8 : 0u;
        v |= i + 2 < n ? uint32_t(uint8_t(bytes[i + 2])) : 0u;
        out += kDigits[(v >> 18) & 63];
        out += kDigits[(v >> 12) & 63];
        out += i + 1 < n ? kDigits[(v >> 6) & 63] : '=';
        out += i + 2 < n ? kDigits[v & 63] : '=';
    }
    return out;
}

// One triangle (positions in a data URI), its mesh on node 0, one scene with node 0.
inline nlohmann::json Triangle() {
    // -1,0,0  1,0,0  0,1,0 as little-endian float32.
    const char* positions =
        "data:application/octet-stream;base64,AACAvwAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
    return nlohmann::json{{"asset", {{"version", "2.0"}}},
                          {"buffers", {{{"byteLength", 36}, {"uri", positions}}}},
                          {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
                          {"accessors",
                           {{{"bufferView", 0},
                             {"componentType", 5126},
                             {"count", 3},
                             {"type", "VEC3"},
                             {"min", {-1, 0, 0}},
                             {"max", {1, 1, 0}}}}},
                          {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
                          {"nodes", {{{"mesh", 0}}}},
                          {"scenes", {{{"nodes", {0}}}}},
                          {"scene", 0}};
}

struct Loaded {
    std::optional<kiln::Error> error;
    runtime::Scene scene;
    DiagnosticList warnings;
};

inline std::filesystem::path ScratchDir() {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "kiln_gltf_tests";
    std::filesystem::create_directories(dir);
    return dir;
}

inline Loaded LoadFile(const std::filesystem::path& file) {
    Loaded out;
    Result<runtime::Scene> loaded = runtime::LoadGltf(file.string(), out.warnings);
    if (loaded) {
        out.scene = std::move(loaded).value();
    } else {
        out.error = loaded.error();
    }
    return out;
}

// Writes `text` as <test name><extension> and loads it.
inline Loaded LoadText(const std::string& text, const std::string& extension = ".gltf") {
    const std::filesystem::path file =
        ScratchDir() /
        (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + extension);
    std::ofstream(file, std::ios::binary) << text;
    return LoadFile(file);
}

inline Loaded Load(const nlohmann::json& gltf) {
    return LoadText(gltf.dump());
}

inline std::string AllWarnings(const Loaded& l) {
    std::string all;
    for (const Diagnostic& w : l.warnings.all()) {
        EXPECT_EQ(w.severity, Severity::kWarning);
        all += w.message + "\n";
    }
    return all;
}

}  // namespace kiln::test

#endif  // KILN_TESTS_RUNTIME_GLTF_FILES_H_
