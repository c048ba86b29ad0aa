// kiln/show.h: the text views of a compiled program, and the guard in front of SPIRV-Cross.
#include "kiln/show.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace kiln {
namespace {

TEST(CompactProgramText, DropsBlankLinesAndKeepsEveryLinesPlace) {
    const std::string text =
        "#line 1 \"<kiln prelude>\"\n"
        "\n\n\n"
        "#line 1 \"a.cginc\"\n"
        "\n\n\n\n\n"
        "float a;\n"  // a.cginc:6
        "\n"
        "float b;\n"  // a.cginc:8: a short gap stays blank
        "#line 40 \"s.shader\"\n"
        "\n\n\n"
        "float4 frag() : SV_Target { return 0; }\n";  // s.shader:43
    EXPECT_EQ(CompactProgramText(text),
              "#line 6 \"a.cginc\"\n"
              "float a;\n"
              "\n"
              "float b;\n"
              "#line 43 \"s.shader\"\n"
              "float4 frag() : SV_Target { return 0; }\n");
}

TEST(CompactProgramText, ATextWithoutDirectivesGetsOneForItsFirstLine) {
    EXPECT_EQ(CompactProgramText("\n\n\nx;\ny;\n"), "#line 4 \"\"\nx;\ny;\n");
    EXPECT_EQ(CompactProgramText(""), "");
}

// Bytes that are not a valid module never reach SPIRV-Cross: a coded error instead of a crash.
TEST(ViewModule, RefusesWhatIsNotValidSpirv) {
    const std::vector<uint32_t> header_only = {0x07230203u, 0x00010000u, 0u, 8u, 0u};
    for (ModuleView view : {ModuleView::kSpirv, ModuleView::kGlsl, ModuleView::kEssl,
                            ModuleView::kMsl, ModuleView::kCrossHlsl}) {
        const Result<std::string> shown = ViewModule(header_only, view);
        ASSERT_FALSE(shown) << ModuleViewName(view);
        EXPECT_EQ(shown.error().code, DiagCode::kCannotShowModule);
        EXPECT_NE(shown.error().message.find("not valid SPIR-V"), std::string::npos)
            << shown.error().message;
    }
    const std::vector<uint32_t> garbage(64, 0xdeadbeefu);
    EXPECT_FALSE(ViewModule(garbage, ModuleView::kMsl));
    EXPECT_FALSE(ViewModule({}, ModuleView::kGlsl));
}

}  // namespace
}  // namespace kiln
