// Golden AST dumps. For every X.shader in the golden folders, X.shader.expected.json holds the
// AST (kiln parse --json form) and X.shader.expected.diag the diagnostics exactly as the CLI
// prints them (absent when there are none). Goldens are reviewed, never blindly regenerated:
// after a deliberate change run `kiln_golden_tests --update` and read the diff.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "support/test_support.h"

namespace fs = std::filesystem;
using namespace kiln;

namespace {

const char* const kGoldenDirs[] = {"golden/parse", "lecture"};

struct Outcome {
    std::string json;
    std::string diag;
};

Outcome Run(const fs::path& path) {
    // Diagnostics name the file relative to its folder, so goldens do not depend on the checkout.
    const SourceFile file(path.filename().string(), test::ReadFile(path.string()));
    DiagnosticList diags;
    const auto shader = shaderlab::ParseAndCheck(file, diags);
    return {(shader ? shaderlab::DumpJson(*shader) : std::string("null")) + "\n",
            FormatDiagnosticsText(diags, {&file})};
}

bool Compare(const fs::path& expected_path, const std::string& actual, bool update) {
    const bool exists = fs::exists(expected_path);
    if (update) {
        if (actual.empty()) {
            fs::remove(expected_path);
        } else {
            test::WriteFile(expected_path.string(), actual);
        }
        return true;
    }
    const std::string expected = exists ? test::ReadFile(expected_path.string()) : std::string();
    if (expected == actual) {
        return true;
    }
    std::fprintf(stderr, "MISMATCH %s\n--- expected\n%s\n--- actual\n%s\n",
                 expected_path.string().c_str(), expected.c_str(), actual.c_str());
    return false;
}

}  // namespace

int main(int argc, char** argv) {
    const bool update = argc > 1 && std::strcmp(argv[1], "--update") == 0;
    int passed = 0;
    int failed = 0;
    for (const char* dir : kGoldenDirs) {
        std::vector<fs::path> inputs;
        for (const auto& entry : fs::directory_iterator(test::DataPath(dir))) {
            if (entry.path().extension() == ".shader") {
                inputs.push_back(entry.path());
            }
        }
        std::sort(inputs.begin(), inputs.end());
        for (const fs::path& input : inputs) {
            const Outcome out = Run(input);
            // Both files are compared (and updated), whatever the first says.
            const bool json_ok = Compare(input.string() + ".expected.json", out.json, update);
            const bool diag_ok = Compare(input.string() + ".expected.diag", out.diag, update);
            const bool ok = json_ok && diag_ok;
            std::printf("%s %s\n", ok ? "ok  " : "FAIL", input.filename().string().c_str());
            (ok ? passed : failed)++;
        }
    }
    if (passed + failed == 0) {
        std::fprintf(stderr, "no golden inputs found\n");
        return 1;
    }
    std::printf("%s%d passed, %d failed\n", update ? "updated: " : "golden: ", passed, failed);
    return failed == 0 ? 0 : 1;
}
