#include "kiln/diagnostic.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace kiln::test {
namespace {

SourceRange Range(const SourceFile& f, uint32_t begin, uint32_t end) {
    return {f.LocAt(begin), f.LocAt(end)};
}

TEST(Diagnostics, CodesAreFourDigits) {
    EXPECT_EQ(FormatDiagCode(DiagCode::kCannotReadFile), "K0001");
    EXPECT_EQ(FormatDiagCode(DiagCode::kUnclosedBlock), "K2006");
}

TEST(Diagnostics, TextFormatHasLocationCodeSourceLineAndUnderline) {
    const SourceFile f("m.shader", "Shader \"x\" {\n    Cull Sideways\n}\n");
    DiagnosticList diags;
    Diagnostic& d = diags.Error(DiagCode::kInvalidValue, "m.shader", Range(f, 22, 30),
                                "invalid value 'Sideways' for 'Cull'");
    d.notes.push_back({"m.shader", Range(f, 11, 12), "block opened here"});
    EXPECT_EQ(FormatDiagnosticsText(diags, {&f}),
              "m.shader:2:10: error: invalid value 'Sideways' for 'Cull' [K2005]\n"
              " 2 |     Cull Sideways\n"
              "   |          ^~~~~~~~\n"
              "m.shader:1:12: note: block opened here\n"
              " 1 | Shader \"x\" {\n"
              "   |            ^\n");
}

TEST(Diagnostics, TextFormatKeepsTabsAlignedAndHidesControlBytes) {
    const SourceFile f("t.shader", "\tab\x01 cd\n");
    DiagnosticList diags;
    diags.Error(DiagCode::kUnknownCommand, "t.shader", Range(f, 5, 7), "x");
    const std::string text = FormatDiagnosticsText(diags, {&f});
    EXPECT_NE(text.find(" 1 | \tab? cd\n   | \t    ^~\n"), std::string::npos) << text;
}

TEST(Diagnostics, LongLinesAreWindowedAroundTheCaret) {
    const std::string line = std::string(5000, 'a') + "XYZ" + std::string(5000, 'b');
    const SourceFile f("l.shader", line);
    DiagnosticList diags;
    diags.Error(DiagCode::kUnknownCommand, "l.shader", Range(f, 5000, 5003), "x");
    const std::string text = FormatDiagnosticsText(diags, {&f});
    EXPECT_LT(text.size(), 400u);
    EXPECT_NE(text.find("XYZ"), std::string::npos);
    // The caret sits under the X.
    const size_t source_line = text.find(" 1 | ");
    const size_t caret_line = text.find("   | ", source_line + 1);
    EXPECT_EQ(text.find('X', source_line) - source_line, text.find('^', caret_line) - caret_line);
}

TEST(Diagnostics, JsonFormat) {
    const SourceFile f("j.shader", "abc\ndef\n");
    DiagnosticList diags;
    diags.Warning(DiagCode::kDuplicateTag, "j.shader", Range(f, 4, 6), "duplicate tag 'A'")
        .notes.push_back({"j.shader", Range(f, 0, 1), "previous value set here"});
    const auto j = nlohmann::json::parse(FormatDiagnosticsJson(diags));
    ASSERT_EQ(j.size(), 1u);
    EXPECT_EQ(j[0]["severity"], "warning");
    EXPECT_EQ(j[0]["code"], "K3010");
    EXPECT_EQ(j[0]["file"], "j.shader");
    EXPECT_EQ(j[0]["range"]["begin"]["line"], 2);
    EXPECT_EQ(j[0]["range"]["begin"]["column"], 1);
    EXPECT_EQ(j[0]["range"]["end"]["column"], 3);
    EXPECT_EQ(j[0]["notes"][0]["message"], "previous value set here");
}

TEST(Diagnostics, JsonSurvivesInvalidUtf8InMessages) {
    DiagnosticList diags;
    diags.Error(DiagCode::kUnknownCommand, "x", {}, "unknown command '\xff\xfe'");
    nlohmann::json j;
    ASSERT_NO_THROW(j = nlohmann::json::parse(FormatDiagnosticsJson(diags)));
    // Invalid bytes are escaped as the text form escapes them (issue 37: one form everywhere).
    EXPECT_EQ(j[0]["message"], "unknown command '\\xff\\xfe'");
    EXPECT_NE(FormatDiagnosticsText(diags, {}, false).find("unknown command '\\xff\\xfe'"),
              std::string::npos);
}

TEST(Diagnostics, ErrorLimitAddsOneTooManyErrorsAndStops) {
    DiagnosticList diags;
    diags.set_error_limit(3);
    for (int i = 0; i < 10; ++i) {
        diags.Error(DiagCode::kUnknownCommand, "x", {}, "e");
    }
    diags.Warning(DiagCode::kDuplicateTag, "x", {}, "w");
    EXPECT_TRUE(diags.saturated());
    ASSERT_EQ(diags.all().size(), 4u);
    EXPECT_EQ(diags.all().back().code, DiagCode::kTooManyErrors);
}


// The JSON a Kiln tool prints reads back as the same diagnostics (kiln compile --scene reads
// kiln-render's this way); anything else is an error.
// The -W options (WarningPolicy): by code and by group, in order, the later winning; errors are
// never touched; a misspelled option is an error with the closest valid name.
std::vector<std::string> Kept(const WarningPolicy& policy) {
    DiagnosticList diags(policy);
    diags.Warning(DiagCode::kLintKeywordChangesNothing, "a", kNoPosition, "k7001");
    diags.Warning(DiagCode::kLintStateContradictsPass, "a", kNoPosition, "k7011");
    diags.Warning(DiagCode::kGlobalNotAProperty, "a", kNoPosition, "k5006");
    diags.Error(DiagCode::kHlslError, "a", kNoPosition, "k5001");
    std::vector<std::string> out;
    for (const Diagnostic& d : diags.all())
        out.push_back(std::string(SeverityName(d.severity)) + " " + FormatDiagCode(d.code));
    return out;
}

WarningPolicy Policy(std::initializer_list<const char*> options) {
    WarningPolicy p;
    for (const char* o : options)
        EXPECT_TRUE(p.Add(o).ok()) << o;
    return p;
}

TEST(WarningOptions, SilenceOrPromoteOneCodeOrAGroup) {
    using V = std::vector<std::string>;
    EXPECT_EQ(Kept(Policy({})),
              (V{"warning K7001", "warning K7011", "warning K5006", "error K5001"}));
    EXPECT_EQ(Kept(Policy({"-Wno-K7001"})), (V{"warning K7011", "warning K5006", "error K5001"}));
    EXPECT_EQ(Kept(Policy({"-Werror=K5006"})),
              (V{"warning K7001", "warning K7011", "error K5006", "error K5001"}));
    EXPECT_EQ(Kept(Policy({"-Wno-lint"})), (V{"warning K5006", "error K5001"}));
    EXPECT_EQ(Kept(Policy({"-Werror=lint-state", "-Wno-interface"})),
              (V{"warning K7001", "error K7011", "error K5001"}));
    // -Werror, and a code kept a warning under it; lower-case codes are accepted.
    EXPECT_EQ(Kept(Policy({"-Werror", "-Wno-error=k7011"})),
              (V{"error K7001", "warning K7011", "error K5006", "error K5001"}));
    EXPECT_EQ(Kept(Policy({"-Werror", "-Wno-error"})),
              (V{"warning K7001", "warning K7011", "warning K5006", "error K5001"}));
    // Later options win: a group silenced, one of its codes shown again; and the reverse.
    EXPECT_EQ(Kept(Policy({"-Wno-all", "-WK7011"})), (V{"warning K7011", "error K5001"}));
    EXPECT_EQ(Kept(Policy({"-WK7011", "-Wno-all"})), (V{"error K5001"}));
    // -Werror=X shows X even after -Wno-X; errors are not silenced.
    EXPECT_EQ(Kept(Policy({"-Wno-K7001", "-Werror=K7001", "-Wno-K5001"})),
              (V{"error K7001", "warning K7011", "warning K5006", "error K5001"}));
}

TEST(WarningOptions, AMisspelledOptionIsAnErrorWithTheClosestName) {
    WarningPolicy p;
    const Status code = p.Add("-Wno-K7100");
    ASSERT_FALSE(code.ok());
    EXPECT_EQ(code.error().code, DiagCode::kBadCommandLine);
    EXPECT_NE(code.error().message.find("unknown warning option '-Wno-K7100'"), std::string::npos)
        << code.error().message;
    EXPECT_NE(code.error().message.find("did you mean 'K7010'?"), std::string::npos)
        << code.error().message;
    const Status group = p.Add("-Werror=lnit");
    ASSERT_FALSE(group.ok());
    EXPECT_NE(group.error().message.find("did you mean 'lint'?"), std::string::npos)
        << group.error().message;
    EXPECT_FALSE(p.Add("-W").ok());
    EXPECT_FALSE(p.Add("-Werror=").ok());
    EXPECT_TRUE(p.empty());  // a refused option changes nothing
}

TEST(DiagnosticsJson, ReadsBackWhatItWrote) {
    DiagnosticList d;
    Diagnostic& e = d.Error(DiagCode::kMissingVariant, "scene.gltf", {{0, 3, 4}, {0, 3, 9}},
                            "shader 'S' pass 'P' has no variant");
    e.notes.push_back({"x.shader", {{0, 1, 2}, {0, 1, 5}}, "declared here"});
    d.Warning(DiagCode::kDefaultLight, "scene.gltf", kNoPosition, "default light");
    const Result<DiagnosticList> back = ParseDiagnosticsJson(FormatDiagnosticsJson(d));
    ASSERT_TRUE(back.ok());
    ASSERT_EQ(back.value().all().size(), 2u);
    const Diagnostic& b = back.value().all()[0];
    EXPECT_EQ(b.code, DiagCode::kMissingVariant);
    EXPECT_EQ(b.severity, Severity::kError);
    EXPECT_EQ(b.range.begin.line, 3u);
    EXPECT_EQ(b.range.end.column, 9u);
    ASSERT_EQ(b.notes.size(), 1u);
    EXPECT_EQ(b.notes[0].message, "declared here");
    EXPECT_EQ(back.value().all()[1].severity, Severity::kWarning);
    for (const char* bad : {"", "{}", "[{\"code\": \"K1\"}]", "[1]",
                            "[{\"severity\": \"error\", \"code\": \"X0006\", \"file\": \"\", "
                            "\"message\": \"m\", \"range\": {}}]"}) {
        EXPECT_FALSE(ParseDiagnosticsJson(bad).ok()) << bad;
    }
}

}  // namespace
}  // namespace kiln::test
