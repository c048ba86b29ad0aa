// kiln lint's fixtures (tests/lint/checks/README.md): each .shader carries its expectations in
// comments, clang -verify style. Every diagnostic in the file must be expected and every
// expectation met, so a fixture fails on a finding gone missing and on a false one alike.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "kiln/diagnostic.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

std::string FixtureDir() {
    return DataPath("lint/checks");
}

std::vector<std::string> FixtureNames() {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(FixtureDir())) {
        if (e.path().extension() == ".shader")
            names.push_back(e.path().stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

struct Finding {
    int line = 0;
    std::string severity, code, text;  // text: the expectation's {{...}} or the message
};

struct Fixture {
    std::vector<Finding> expected;
    std::string args;
};

Fixture ReadFixture(const std::string& path) {
    Fixture fx;
    std::istringstream in(ReadFile(path));
    const std::regex expect(
        R"(expect-(warning|error)(?:@([+-]\d+))?\s+(K\d{4})(?:\s+\{\{(.*?)\}\})?)");
    const std::regex args(R"(lint-args:(.*)$)");
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        for (auto it = std::sregex_iterator(line.begin(), line.end(), expect);
             it != std::sregex_iterator(); ++it) {
            const std::smatch& m = *it;
            const int offset = m[2].matched ? std::stoi(m[2].str()) : 0;
            fx.expected.push_back({n + offset, m[1].str(), m[3].str(), m[4].str()});
        }
        std::smatch m;
        if (std::regex_search(line, m, args))
            fx.args += " " + m[1].str();
    }
    return fx;
}

std::string Describe(const Finding& f) {
    return "line " + std::to_string(f.line) + ": " + f.severity + " " + f.code + " {{" + f.text +
           "}}";
}

class LintFixture : public ::testing::TestWithParam<std::string> {};

TEST_P(LintFixture, FindsWhatItsCommentsExpectAndNothingElse) {
    const std::string path = FixtureDir() + "/" + GetParam() + ".shader";
    const Fixture fx = ReadFixture(path);
    const RunResult r = RunKiln("lint --no-cache --json" + fx.args + " " + path);
    ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.err;
    const nlohmann::json report = nlohmann::json::parse(r.out);
    std::vector<Finding> actual;
    for (const auto& d : report["diagnostics"]) {
        actual.push_back(
            {d["range"]["begin"]["line"].get<int>(), d["severity"], d["code"], d["message"]});
        EXPECT_EQ(d["file"], path) << "a diagnostic outside the fixture: " << d.dump();
    }
    std::vector<bool> used(actual.size(), false);
    for (const Finding& e : fx.expected) {
        bool met = false;
        for (size_t i = 0; i < actual.size() && !met; ++i) {
            const Finding& a = actual[i];
            if (!used[i] && a.line == e.line && a.code == e.code && a.severity == e.severity &&
                a.text.find(e.text) != std::string::npos)
                used[i] = met = true;
        }
        EXPECT_TRUE(met) << "expected but not seen: " << Describe(e) << "\nfound:\n"
                         << report["diagnostics"].dump(1);
    }
    for (size_t i = 0; i < actual.size(); ++i)
        EXPECT_TRUE(used[i]) << "seen but not expected: " << Describe(actual[i]);
    // An error expected means the lint fails; warnings alone do not.
    const bool errors = std::any_of(fx.expected.begin(), fx.expected.end(),
                                    [](const Finding& f) { return f.severity == "error"; });
    EXPECT_EQ(r.exit_code, errors ? 1 : 0) << r.err;
}

INSTANTIATE_TEST_SUITE_P(Checks,
                         LintFixture,
                         ::testing::ValuesIn(FixtureNames()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

// Every K7xxx code has a fixture that expects it: a new lint check comes with its fixture.
TEST(LintFixtures, EveryLintCodeIsExpectedByAFixture) {
    std::set<std::string> expected;
    for (const std::string& name : FixtureNames()) {
        for (const Finding& f : ReadFixture(FixtureDir() + "/" + name + ".shader").expected)
            expected.insert(f.code);
    }
    size_t lint_codes = 0;
    for (DiagCode c : AllDiagCodes()) {
        const auto n = static_cast<unsigned>(c);
        if (n < 7000 || n > 7999)
            continue;
        ++lint_codes;
        EXPECT_TRUE(expected.count(FormatDiagCode(c)))
            << FormatDiagCode(c) << " has no fixture in tests/lint/checks";
    }
    EXPECT_GE(lint_codes, 11u);
}

}  // namespace
}  // namespace kiln::test
