// Render state: every command, every form, literal and property-reference values.
#include <gtest/gtest.h>

#include "support/test_support.h"

namespace kiln::test {
namespace {

using namespace kiln::shaderlab;

constexpr const char* kProps = R"(Properties {
    _Cull ("Cull", Float) = 2
    _Src ("Src", Float) = 1
    _Dst ("Dst", Float) = 0
    _Op ("Op", Float) = 0
    _Ref ("Ref", Int) = 1
    _ZW ("ZW", Float) = 1
    _Mask ("Mask", Float) = 15
    _OffF ("OffF", Range(-1, 1)) = 0
})";

RenderState PassState(const std::string& commands) {
    ParseOutcome out = ParseText(std::string("Shader \"x\" {\n") + kProps +
                                 "\nSubShader { Pass {\n" + commands + "\n} } }");
    EXPECT_FALSE(out.diags.has_errors()) << Summarize(out.diags);
    if (!out.shader) {
        return {};
    }
    const auto& sub = std::get<SubShader>(out.shader->subshaders.at(0));
    return std::get<Pass>(sub.passes.at(0)).state;
}

TEST(RenderStateParse, SimpleCommands) {
    const RenderState s = PassState(
        "Cull Off\nZTest Greater\nZWrite On\nZClip False\nAlphaToMask On\nConservative True");
    EXPECT_EQ(s.cull->value.text, "Off");
    EXPECT_EQ(s.ztest->value.text, "Greater");
    EXPECT_EQ(s.zwrite->value.text, "On");
    EXPECT_EQ(s.zclip->value.text, "Off");  // canonical: True/False are aliases
    EXPECT_EQ(s.alpha_to_mask->value.text, "On");
    EXPECT_EQ(s.conservative->value.text, "On");
    EXPECT_EQ(s.cull->range.begin.line, 13u);
}

TEST(RenderStateParse, EveryZTestFunction) {
    for (const char* f :
         {"Less", "Greater", "LEqual", "GEqual", "Equal", "NotEqual", "Always", "Never"}) {
        EXPECT_EQ(PassState(std::string("ZTest ") + f).ztest->value.text, f);
    }
}

TEST(RenderStateParse, BlendForms) {
    const RenderState s = PassState(
        "Blend Off\nBlend 1 SrcAlpha OneMinusSrcAlpha\nBlend 2 One Zero, DstColor "
        "SrcAlphaSaturate\n"
        "Blend 3 Off\nBlend 4 [_Src] [_Dst], One [_Dst]");
    ASSERT_EQ(s.blend.size(), 5u);
    EXPECT_TRUE(s.blend[0].off);
    EXPECT_EQ(s.blend[0].target, -1);
    EXPECT_EQ(s.blend[1].target, 1);
    EXPECT_EQ(s.blend[1].src.text, "SrcAlpha");
    EXPECT_FALSE(s.blend[1].src_alpha);
    EXPECT_EQ(s.blend[2].dst_alpha->text, "SrcAlphaSaturate");
    EXPECT_TRUE(s.blend[3].off);
    EXPECT_EQ(s.blend[3].target, 3);
    EXPECT_EQ(s.blend[4].src.kind, StateValue::Kind::kPropertyRef);
    EXPECT_EQ(s.blend[4].src.text, "_Src");
    EXPECT_EQ(s.blend[4].dst_alpha->text, "_Dst");
}

TEST(RenderStateParse, BlendOpColorMaskOffset) {
    const RenderState s = PassState(
        "BlendOp RevSub\nBlendOp 1 Min, Max\nBlendOp [_Op]\nColorMask RGB\nColorMask 0 1\n"
        "ColorMask abgr 2\nColorMask [_Mask]\nOffset -1, -1\nOffset [_OffF], 2.5");
    ASSERT_EQ(s.blend_op.size(), 3u);
    EXPECT_EQ(s.blend_op[0].op.text, "RevSub");
    EXPECT_EQ(s.blend_op[1].target, 1);
    EXPECT_EQ(s.blend_op[1].op_alpha->text, "Max");
    EXPECT_EQ(s.blend_op[2].op.kind, StateValue::Kind::kPropertyRef);
    ASSERT_EQ(s.color_mask.size(), 4u);
    EXPECT_EQ(s.color_mask[0].mask.text, "RGB");
    EXPECT_EQ(s.color_mask[1].mask.text, "0");
    EXPECT_EQ(s.color_mask[1].target, 1);
    EXPECT_EQ(s.color_mask[2].mask.text, "RGBA");  // canonical channel order
    EXPECT_EQ(s.color_mask[3].mask.kind, StateValue::Kind::kPropertyRef);
    ASSERT_TRUE(s.offset);  // the last Offset wins
    EXPECT_EQ(s.offset->factor.text, "_OffF");
    EXPECT_EQ(s.offset->units.number, 2.5);
}

TEST(RenderStateParse, StencilWithFrontAndBack) {
    const RenderState s = PassState(R"(Stencil {
        Ref [_Ref]
        ReadMask 255
        WriteMask 0
        Comp Equal
        Pass IncrSat
        Fail Zero
        ZFail DecrWrap
        CompFront Always
        PassFront Replace
        FailFront Keep
        ZFailFront Invert
        CompBack Never
        PassBack IncrWrap
        FailBack DecrSat
        ZFailBack Keep
    })");
    ASSERT_TRUE(s.stencil);
    ASSERT_EQ(s.stencil->entries.size(), 15u);
    EXPECT_EQ(s.stencil->entries[0].key, "Ref");
    EXPECT_EQ(s.stencil->entries[0].value.kind, StateValue::Kind::kPropertyRef);
    EXPECT_EQ(s.stencil->entries[1].value.number, 255);
    EXPECT_EQ(s.stencil->entries[4].value.text, "IncrSat");
    EXPECT_EQ(s.stencil->entries[14].key, "ZFailBack");
}

TEST(RenderStateParse, PropertyReferencesInSimpleCommands) {
    const RenderState s = PassState("Cull [_Cull]\nZWrite [_ZW]");
    EXPECT_EQ(s.cull->value.kind, StateValue::Kind::kPropertyRef);
    EXPECT_EQ(s.cull->value.text, "_Cull");
    EXPECT_EQ(s.cull->value.range.begin.column, 6u);
    EXPECT_EQ(s.cull->value.range.end.column, 13u);
}

TEST(RenderStateParse, StateAtSubShaderAndCategoryLevels) {
    ParseOutcome out = ParseText(
        "Shader \"x\" { Category { Cull Off SubShader { ZWrite Off Pass { ZTest Always } } } }");
    ASSERT_FALSE(out.diags.has_errors()) << Summarize(out.diags);
    const auto& cat = *std::get<std::unique_ptr<Category>>(out.shader->subshaders[0]);
    EXPECT_EQ(cat.state.cull->value.text, "Off");
    const auto& sub = std::get<SubShader>(cat.children[0]);
    EXPECT_EQ(sub.state.zwrite->value.text, "Off");
    EXPECT_EQ(std::get<Pass>(sub.passes[0]).state.ztest->value.text, "Always");
}

TEST(RenderStateParse, DuplicateCommandWarnsAndLastWins) {
    ParseOutcome out = ParseText("Shader \"x\" { SubShader { Pass { Cull Back\nCull Front } } }");
    EXPECT_FALSE(out.diags.has_errors());
    ASSERT_EQ(out.diags.all().size(), 1u);
    EXPECT_EQ(out.diags.all()[0].code, DiagCode::kDuplicateCommand);
    EXPECT_EQ(out.diags.all()[0].range.begin.line, 2u);
    const auto& sub = std::get<SubShader>(out.shader->subshaders[0]);
    EXPECT_EQ(std::get<Pass>(sub.passes[0]).state.cull->value.text, "Front");
}

TEST(RenderStateParse, DuplicatesPerRenderTargetWarn) {
    ParseOutcome out = ParseText(
        "Shader \"x\" { SubShader { Pass {\nBlendOp Add\nBlendOp 1 Min\nBlendOp Max\n"
        "ColorMask RGB 1\nColorMask A\nColorMask 0 1\nStencil { Ref 1 Ref 2 }\n} } }");
    EXPECT_FALSE(out.diags.has_errors());
    std::vector<uint32_t> lines;
    for (const Diagnostic& d : out.diags.all()) {
        EXPECT_EQ(d.code, DiagCode::kDuplicateCommand);
        EXPECT_EQ(d.notes.size(), 1u);
        lines.push_back(d.range.begin.line);
    }
    EXPECT_EQ(lines, (std::vector<uint32_t>{4, 7, 8})) << Summarize(out.diags);
}

TEST(RenderStateParse, UnitySpellingsAreAcceptedAsTheirCanonicalWords) {
    // Unity's built-in shaders write AlphaToMask True and ZTest Off.
    const RenderState s = PassState("AlphaToMask True\nZTest Off");
    EXPECT_EQ(s.alpha_to_mask->value.text, "On");
    EXPECT_EQ(s.ztest->value.text, "Always");
    EXPECT_EQ(PassState("AlphaToMask False").alpha_to_mask->value.text, "Off");
    EXPECT_EQ(PassState("ZWrite True").zwrite->value.text, "On");
    // An alias only stands for a word the command takes.
    ParseOutcome bad = ParseText("Shader \"x\" { SubShader { Pass { Cull True } } }");
    ASSERT_TRUE(bad.diags.has_errors());
    EXPECT_EQ(bad.diags.all()[0].code, DiagCode::kInvalidValue);
}

TEST(RenderStateParse, LodInAPassOverridesTheSubShader) {
    ParseOutcome out =
        ParseText("Shader \"x\" { SubShader { LOD 200 Pass { LOD 100 Cull Off } Pass { } } }");
    ASSERT_FALSE(out.diags.has_errors()) << Summarize(out.diags);
    const auto& sub = std::get<SubShader>(out.shader->subshaders.at(0));
    EXPECT_EQ(std::get<Pass>(sub.passes.at(0)).lod, 100);
    EXPECT_FALSE(std::get<Pass>(sub.passes.at(1)).lod);
}

}  // namespace
}  // namespace kiln::test
