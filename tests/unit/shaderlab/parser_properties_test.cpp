// Properties: every type, default form and attribute.
#include <gtest/gtest.h>

#include "support/test_support.h"

namespace kiln::test {
namespace {

using namespace kiln::shaderlab;

std::vector<Property> ParseProps(const std::string& body, DiagnosticList* diags_out = nullptr) {
    ParseOutcome out = ParseText("Shader \"x\" {\nProperties {\n" + body + "\n}\n}\n");
    EXPECT_FALSE(out.diags.has_errors()) << Summarize(out.diags);
    if (diags_out != nullptr) {
        diags_out->Append(out.diags);
    }
    return out.shader ? out.shader->properties : std::vector<Property>{};
}

TEST(Properties, EveryTypeAndDefault) {
    const auto props = ParseProps(R"(
        _C ("Color", Color) = (1, 0.5, 0.25, 0.75)
        _C3 ("Color3", Color) = (0.5, 0.5, 0.5)
        _V ("Vector", Vector) = (-1, 2.5e1, .5, 1.)
        _F ("Float", Float) = -0.5
        _I ("Int", Int) = 3
        _N ("Integer", Integer) = +7
        _R ("Range", Range(-1, 2)) = 1.5
        _T ("Tex", 2D) = "white" {}
        _B ("Bump", 2D) = "bump" {}
        _G ("Gray", 2D) = "gray"
        _K ("Black", 2D) = "black" {}
        _Red ("Red", 2D) = "red" {}
        _Empty ("Empty", 2D) = "" {}
        _3 ("Volume", 3D) = "" {}
        _Cu ("Cube", Cube) = "" {}
        _A ("Array", 2DArray) = "" {}
        _CA ("CubeArray", CubeArray) = "" {}
    )");
    ASSERT_EQ(props.size(), 17u);
    EXPECT_EQ(props[0].type, PropertyType::kColor);
    EXPECT_EQ(props[0].default_value, (std::vector<double>{1, 0.5, 0.25, 0.75}));
    EXPECT_EQ(props[1].default_value, (std::vector<double>{0.5, 0.5, 0.5, 1}));  // alpha 1
    EXPECT_EQ(props[2].type, PropertyType::kVector);
    EXPECT_EQ(props[2].default_value, (std::vector<double>{-1, 25, 0.5, 1}));
    EXPECT_EQ(props[3].default_value, std::vector<double>{-0.5});
    EXPECT_EQ(props[4].type, PropertyType::kInt);
    EXPECT_EQ(props[5].type, PropertyType::kInteger);
    EXPECT_EQ(props[5].default_value, std::vector<double>{7});
    EXPECT_EQ(props[6].type, PropertyType::kRange);
    EXPECT_EQ(props[6].range_min, -1);
    EXPECT_EQ(props[6].range_max, 2);
    EXPECT_EQ(props[7].type, PropertyType::kTexture2D);
    EXPECT_EQ(props[7].default_texture, "white");
    EXPECT_EQ(props[8].default_texture, "bump");
    EXPECT_EQ(props[9].default_texture, "gray");
    EXPECT_EQ(props[11].default_texture, "red");
    EXPECT_EQ(props[13].type, PropertyType::kTexture3D);
    EXPECT_EQ(props[14].type, PropertyType::kCube);
    EXPECT_EQ(props[15].type, PropertyType::kTexture2DArray);
    EXPECT_EQ(props[16].type, PropertyType::kCubeArray);
    EXPECT_EQ(props[0].display_name, "Color");
    EXPECT_EQ(props[0].name_range.begin.line, 4u);
}

TEST(Properties, EveryAttribute) {
    const auto props = ParseProps(R"(
        [HDR] [Gamma] _C ("C", Color) = (1, 1, 1, 1)
        [NoScaleOffset] [Normal] [MainTexture] _N ("N", 2D) = "bump" {}
        [MainColor] [HideInInspector] [PerRendererData] _M ("M", Color) = (1, 1, 1, 1)
        [Toggle(_ALPHATEST_ON)] _T ("T", Float) = 0
        [Toggle] _T2 ("T2", Float) = 0
        [ToggleOff(_SPECULAR_OFF)] _TO ("TO", Float) = 1
        [KeywordEnum(None, Add, Multiply)] _Overlay ("Overlay", Float) = 0
        [Enum(UnityEngine.Rendering.BlendMode)] _Src ("Src", Float) = 1
        [Enum(One, 1, SrcAlpha, 5)] _Dst ("Dst", Float) = 1
        [PowerSlider(3.0)] _Shin ("Shininess", Range(0.01, 1)) = 0.08
        [IntRange] _Steps ("Steps", Range(0, 255)) = 100
        [Header(Specular settings, with a comma)] [Space] [Space(20)] _S ("S", Float) = 0
        [MyCustomDrawer(1, 2)] _Custom ("Custom", Float) = 0
    )");
    ASSERT_EQ(props.size(), 13u);
    EXPECT_EQ(props[0].attributes.size(), 2u);
    EXPECT_EQ(props[0].attributes[0].name, "HDR");
    EXPECT_EQ(props[2].attributes[2].name, "PerRendererData");
    EXPECT_EQ(props[3].attributes[0].args, std::vector<std::string>{"_ALPHATEST_ON"});
    EXPECT_FALSE(props[4].attributes[0].has_parens);
    EXPECT_EQ(props[5].attributes[0].name, "ToggleOff");
    EXPECT_EQ(props[6].attributes[0].args, (std::vector<std::string>{"None", "Add", "Multiply"}));
    EXPECT_EQ(props[7].attributes[0].raw_args, "UnityEngine.Rendering.BlendMode");
    EXPECT_EQ(props[8].attributes[0].args.size(), 4u);
    EXPECT_EQ(props[9].attributes[0].args, std::vector<std::string>{"3.0"});
    EXPECT_EQ(props[10].attributes[0].name, "IntRange");
    EXPECT_EQ(props[11].attributes[0].raw_args, "Specular settings, with a comma");
    EXPECT_EQ(props[11].attributes[2].args, std::vector<std::string>{"20"});
    EXPECT_EQ(props[12].attributes[0].name, "MyCustomDrawer");  // kept, not rejected
}

TEST(Properties, AttributeNamesAreCanonicalised) {
    const auto props = ParseProps("[hdr] _C (\"C\", Color) = (1, 1, 1, 1)");
    ASSERT_EQ(props.size(), 1u);
    EXPECT_EQ(props[0].attributes[0].name, "HDR");
}

TEST(Properties, LegacyTextureOptionsAreSkipped) {
    const auto props = ParseProps(
        "_T (\"T\", 2D) = \"white\" { TexGen CubeReflect }\n"
        "_U (\"U\", Float) = 2");
    ASSERT_EQ(props.size(), 2u);
    EXPECT_EQ(props[1].default_value, std::vector<double>{2});
}

TEST(Properties, WarningsForOutOfRangeDefaultAndUnknownTexture) {
    DiagnosticList diags;
    ParseProps("_R (\"R\", Range(0, 1)) = 2\n_T (\"T\", 2D) = \"purple\" {}", &diags);
    ASSERT_EQ(diags.all().size(), 2u) << Summarize(diags);
    EXPECT_EQ(diags.all()[0].code, DiagCode::kDefaultOutOfRange);
    EXPECT_EQ(diags.all()[0].severity, Severity::kWarning);
    EXPECT_EQ(diags.all()[1].code, DiagCode::kUnknownTextureDefault);
}

// Unity accepts Range(10, 0.1) (Ronja's HSV tutorial): a warning, and a default between the two
// is in range; one outside both is still reported.
TEST(Properties, ARangeWhoseMinimumIsAboveItsMaximumIsAWarningAsInUnity) {
    DiagnosticList diags;
    ParseProps("_A (\"A\", Range(10, 0.1)) = 1\n_B (\"B\", Range(1, 0)) = 2", &diags);
    ASSERT_EQ(diags.all().size(), 3u) << Summarize(diags);
    EXPECT_EQ(diags.all()[0].code, DiagCode::kBadRange);
    EXPECT_EQ(diags.all()[0].severity, Severity::kWarning);
    EXPECT_EQ(diags.all()[1].code, DiagCode::kBadRange);
    EXPECT_EQ(diags.all()[2].code, DiagCode::kDefaultOutOfRange);
    EXPECT_FALSE(diags.has_errors());
}

TEST(Properties, UnityAnyAndRectTypesAndDottedAttributes) {
    ParseOutcome out = ParseText(R"(Shader "x" { Properties {
    [TextureStack.Stack] _A ("A", Any) = "white" {}
    _B ("B", any) = "" {}
    _C ("C", RECT) = "white" {}
} })");
    ASSERT_FALSE(out.diags.has_errors()) << Summarize(out.diags);
    const auto& props = out.shader->properties;
    ASSERT_EQ(props.size(), 3u);
    EXPECT_EQ(props[0].type, PropertyType::kTextureAny);
    EXPECT_TRUE(IsTextureType(props[0].type));
    EXPECT_STREQ(PropertyTypeName(props[0].type), "Any");
    ASSERT_EQ(props[0].attributes.size(), 1u);
    EXPECT_EQ(props[0].attributes[0].name, "TextureStack.Stack");
    EXPECT_EQ(props[1].type, PropertyType::kTextureAny);
    EXPECT_EQ(props[2].type, PropertyType::kTexture2D);
}

}  // namespace
}  // namespace kiln::test
