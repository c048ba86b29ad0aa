// Helpers for tests that run the variant compiler on files written to a scratch folder.
#ifndef KILN_TESTS_SUPPORT_COMPILE_SUPPORT_H_
#define KILN_TESTS_SUPPORT_COMPILE_SUPPORT_H_

#include <string>
#include <vector>

#include "kiln/compile.h"
#include "kiln/diagnostic.h"

namespace kiln::test {

// A fresh folder per test under the gtest temp dir.
class ScratchDir {
  public:
    ScratchDir();
    const std::string& path() const { return path_; }
    // Writes `text` to path()/name (creating folders) and returns the full path.
    std::string Write(const std::string& name, const std::string& text) const;

  private:
    std::string path_;
};

struct CompileRun {
    CompileOutput out;
    DiagnosticList diags;
};

CompileRun Compile(const std::vector<std::string>& files, CompileOptions options = {});

// "file:line:col code message" per diagnostic with the file's base name, notes indented.
std::string Brief(const DiagnosticList& diags);

// A forward pass with `pragmas` (one per line) and an optional #include line.
std::string PassShader(const std::string& pragmas,
                       const std::string& extra_code = "",
                       const std::string& include = "");

// `text` with the first `from` replaced by `to` (which must be present).
std::string Replace(std::string text, const std::string& from, const std::string& to);

}  // namespace kiln::test

#endif  // KILN_TESTS_SUPPORT_COMPILE_SUPPORT_H_
