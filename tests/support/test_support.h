// Helpers shared by Kiln's tests.
#ifndef KILN_TESTS_SUPPORT_TEST_SUPPORT_H_
#define KILN_TESTS_SUPPORT_TEST_SUPPORT_H_

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kiln/diagnostic.h"
#include "kiln/pack/reader.h"
#include "kiln/shaderlab/parse.h"
#include "kiln/source.h"
#include "support/result_asserts.h"

namespace kiln::test {

std::string ReadFile(const std::string& path);
void WriteFile(const std::string& path, const std::string& text);
std::string DataPath(const std::string& relative);  // under tests/
// An empty folder `name`_<pid> in the system's temporary folder (emptied if it was there).
std::string FreshTempDir(const std::string& name);

// The kiln binary run with `args` (a shell command line), its output captured.
struct RunResult {
    int exit_code = -1;
    std::string out;
    std::string err;
};
RunResult RunKiln(const std::string& args);
// The same, killed after `seconds` (exit code 137 then): for inputs that once hung.
RunResult RunKilnWithin(const std::string& args, int seconds);
// Another program of the build (`binary`) run the same way.
RunResult RunProgram(const std::string& binary, const std::string& args, int seconds = 0);

// Parses and checks `text` as "test.shader".
struct ParseOutcome {
    std::optional<shaderlab::Shader> shader;
    DiagnosticList diags;
};
ParseOutcome ParseText(const std::string& text, const std::string& name = "test.shader");

// Pack::Open and MappedFile::Map into an existing object, as assertions:
// ASSERT_TRUE(OpenInto(bytes, pack)) prints the reader's error when it fails.
::testing::AssertionResult OpenInto(std::span<const uint8_t> bytes, pack::Pack& out);
::testing::AssertionResult MapInto(const std::string& path, pack::MappedFile& out);

// Writes a pack's checksum again after its bytes were changed on purpose (XXH64 of the whole file
// with the checksum field zeroed, docs/pack-format.md): a forged pack the reader accepts.
void ResealPack(std::span<uint8_t> bytes);

// One line per diagnostic: "K2003 3:5 error: message" (notes indented below).
std::string Summarize(const DiagnosticList& diags);

// A deterministic ShaderLab file of at least `min_bytes`: many subshaders and passes with real
// program blocks, properties, and Category blocks nested `depth` deep.
std::string MakeStressShader(size_t min_bytes, size_t depth);

}  // namespace kiln::test

#endif  // KILN_TESTS_SUPPORT_TEST_SUPPORT_H_
