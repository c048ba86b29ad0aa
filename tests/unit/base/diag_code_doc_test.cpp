// The stable codes exist once, in kiln/diag_code.h; docs/diagnostics.md lists every one of them
// and no other, so a code added without its meaning (or documented but never defined) fails.
#include "kiln/diag_code.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>

#include "kiln/diagnostic.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {

// The numbers of "kName = 1234," in the enum (the range markers of a section have none).
std::set<std::string> DefinedCodes() {
    const std::string header = ReadFile(DataPath("../base/include/kiln/diag_code.h"));
    std::set<std::string> codes;
    const std::regex value(R"(\s(k\w+) = (\d+),)");
    for (auto it = std::sregex_iterator(header.begin(), header.end(), value);
         it != std::sregex_iterator(); ++it) {
        codes.insert(FormatDiagCode(static_cast<DiagCode>(std::stoi((*it)[2].str()))));
    }
    return codes;
}

// The codes of the table's rows: "| K0012 | warning | ...", except reserved ones ("| - |").
std::set<std::string> DocumentedCodes() {
    const std::string doc = ReadFile(DataPath("../docs/diagnostics.md"));
    std::set<std::string> codes;
    const std::regex row(R"(\n\| (K\d{4}) \| ([^|]+) \|)");
    for (auto it = std::sregex_iterator(doc.begin(), doc.end(), row); it != std::sregex_iterator();
         ++it) {
        if ((*it)[2].str() != "-")
            codes.insert((*it)[1].str());
    }
    return codes;
}

TEST(DiagCodes, EveryCodeIsDocumentedAndEveryDocumentedCodeExists) {
    const std::set<std::string> defined = DefinedCodes();
    const std::set<std::string> documented = DocumentedCodes();
    ASSERT_GT(defined.size(), 100u);  // the regex found the enum
    EXPECT_TRUE(defined.count("K0024") && defined.count("K6016") && defined.count("K9001"));
    for (const std::string& code : defined)
        EXPECT_TRUE(documented.count(code)) << code << " is not in docs/diagnostics.md";
    for (const std::string& code : documented)
        EXPECT_TRUE(defined.count(code)) << code << " is documented but not in kiln/diag_code.h";
}

}  // namespace
}  // namespace kiln::test
