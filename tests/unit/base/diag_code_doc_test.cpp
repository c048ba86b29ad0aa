// The stable codes exist once, in kiln/diag_code_list.h; docs/diagnostics.md lists every one of them
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

// The codes of kiln/diag_code_list.h, the one list the enum and AllDiagCodes() are made from.
std::set<std::string> DefinedCodes() {
    std::set<std::string> codes;
    for (DiagCode c : AllDiagCodes())
        codes.insert(FormatDiagCode(c));
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
    ASSERT_GT(defined.size(), 100u);
    EXPECT_TRUE(defined.count("K0024") && defined.count("K6016") && defined.count("K9001"));
    for (const std::string& code : defined)
        EXPECT_TRUE(documented.count(code)) << code << " is not in docs/diagnostics.md";
    for (const std::string& code : documented)
        EXPECT_TRUE(defined.count(code)) << code << " is documented but not in diag_code_list.h";
}

}  // namespace
}  // namespace kiln::test
