// One render-state table, three readers: every value the ShaderLab parser accepts compiles into a
// pack whose state the runtime resolves to the same Unity enum and maps to Vulkan; every value a
// .material override accepts resolves the same way; a word outside the table is rejected by all.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kiln/material/material.h"
#include "kiln/pack/reader.h"
#include "kiln/pack/render_state.h"
#include "kiln/shaderlab/parse.h"
#include "support/compile_support.h"
#include "support/test_support.h"
#include "vk/pipeline.h"

namespace kiln {
namespace {

using pack::StateValues;

std::string Name(StateValues set, size_t i) {
    const auto names = pack::StateValueNames(set);
    return std::string(names[i % names.size()]);
}

// Pass i sets every enum-valued command to value i of its set (modulo the set's size).
std::string StateShader(size_t passes) {
    std::string text = "Shader \"Bridge/States\" {\n  SubShader {\n";
    for (size_t i = 0; i < passes; ++i) {
        text += "    Pass {\n";
        text += "      Cull " + Name(StateValues::kCull, i) + "\n";
        text += "      ZTest " + Name(StateValues::kCompare, i) + "\n";
        text += "      ZWrite " + Name(StateValues::kOnOff, i) + "\n";
        text += "      ZClip " + Name(StateValues::kOnOff, i + 1) + "\n";
        text += "      Blend " + Name(StateValues::kBlendFactor, i) + " " +
                Name(StateValues::kBlendFactor, i + 1) + "\n";
        text += "      BlendOp " + Name(StateValues::kBlendOp, i) + "\n";
        text += "      Stencil { Comp " + Name(StateValues::kCompare, i + 2) + " Pass " +
                Name(StateValues::kStencilOp, i) + " Fail " + Name(StateValues::kStencilOp, i + 1) +
                " }\n";
        text +=
            "      CGPROGRAM\n#pragma vertex vert\n#pragma fragment frag\n"
            "float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n"
            "float4 frag() : SV_Target { return 1; }\n      ENDCG\n    }\n";
    }
    return text + "  }\n}\n";
}

// The pack of StateShader(passes), compiled for real.
struct CompiledStates {
    explicit CompiledStates(size_t passes) {
        const test::CompileRun run =
            test::Compile({dir.Write("states.shader", StateShader(passes))});
        diagnostics = test::Brief(run.diags);
        bytes = run.out.pack;
        ok = run.out.ok && test::OpenInto(bytes, pack);
    }
    test::ScratchDir dir;
    std::vector<uint8_t> bytes;
    pack::Pack pack;
    std::string diagnostics;
    bool ok = false;
};

template <class E>
uint32_t U(E e) {
    return static_cast<uint32_t>(e);
}

TEST(RenderStateAgreement, EveryShaderLabValueCompilesAndResolves) {
    const size_t passes = pack::StateValueNames(StateValues::kBlendOp).size();  // the largest set
    const CompiledStates states(passes);
    ASSERT_TRUE(states.ok) << states.diagnostics;
    const pack::Pack& pk = states.pack;
    ASSERT_EQ(pk.Count(pack::SectionTag::kPasses), passes);
    for (uint32_t i = 0; i < passes; ++i) {
        SCOPED_TRACE("pass " + std::to_string(i));
        const Result<pack::PassState> s = pack::ResolvePassState(pk, i, nullptr, {});
        ASSERT_TRUE(s.ok()) << s.error().message;
        const pack::PassState& st = s.value();
        EXPECT_EQ(U(st.cull), i % 3);
        EXPECT_EQ(U(st.ztest), i % 9);
        EXPECT_EQ(st.zwrite, i % 2 == 1);
        EXPECT_EQ(st.zclip, (i + 1) % 2 == 1);
        EXPECT_EQ(U(st.targets[0].src), i % 11);
        EXPECT_EQ(U(st.targets[0].dst), (i + 1) % 11);
        EXPECT_EQ(U(st.targets[0].op), i);
        EXPECT_EQ(U(st.front.compare), (i + 2) % 9);
        EXPECT_EQ(U(st.front.pass), i % 8);
        EXPECT_EQ(U(st.back.fail), (i + 1) % 8);
        // The runtime's mapping: Disabled turns the depth test off, logical ops become the
        // attachment's logic op, advanced ones are flagged for the extension check.
        const vk::RenderState v = vk::ToVulkan(st);
        EXPECT_EQ(v.depth_test, i % 9 != 0);
        EXPECT_EQ(v.logic_op_enable,
                  i >= pack::kFirstLogicalBlendOp && i < pack::kFirstAdvancedBlendOp);
        EXPECT_EQ(v.targets[0].advanced, i >= pack::kFirstAdvancedBlendOp);
    }
}

// A .material overriding `field` with `value`, parsed.
bool ParseOverride(const std::string& field, const std::string& value, material::Material& m) {
    DiagnosticList issues;
    const std::string json =
        "{\"shader\": \"x\", \"render_state\": {\"" + field + "\": " + value + "}}";
    return material::ParseMaterial(json, "override.material", m, issues) && issues.all().empty();
}

TEST(RenderStateAgreement, EveryMaterialValueIsTheTable) {
    const CompiledStates states(1);
    ASSERT_TRUE(states.ok) << states.diagnostics;
    const pack::Pack& pk = states.pack;
    const struct {
        const char* field;
        StateValues set;
    } kFields[] = {{"Cull", StateValues::kCull},
                   {"ZTest", StateValues::kCompare},
                   {"ZWrite", StateValues::kOnOff},
                   {"Blend", StateValues::kBlendFactor}};
    for (const auto& f : kFields) {
        const auto names = pack::StateValueNames(f.set);
        for (uint32_t i = 0; i < names.size(); ++i) {
            const std::string word(names[i]);
            SCOPED_TRACE(std::string(f.field) + " " + word);
            const std::string value = std::string(f.field) == "Blend"
                                          ? "[\"" + word + "\", \"" + word + "\"]"
                                          : "\"" + word + "\"";
            material::Material m;
            ASSERT_TRUE(ParseOverride(f.field, value, m));
            ASSERT_EQ(m.render_state.size(), 1u);
            EXPECT_EQ(m.render_state[0].values[0], word);
            const pack::StateOverride o{m.render_state[0].field, m.render_state[0].values};
            const Result<pack::PassState> s = pack::ResolvePassState(pk, 0, nullptr, {&o, 1});
            ASSERT_TRUE(s.ok()) << s.error().message;
            const pack::PassState& st = s.value();
            const uint32_t got = f.set == StateValues::kCull      ? U(st.cull)
                                 : f.set == StateValues::kCompare ? U(st.ztest)
                                 : f.set == StateValues::kOnOff   ? uint32_t(st.zwrite)
                                                                  : U(st.targets[0].dst);
            EXPECT_EQ(got, i);
            // The ShaderLab parser takes the same word for the same command.
            const std::string shader_word =
                std::string(f.field) == "Blend" ? word + " " + word : word;
            DiagnosticList diags;
            const SourceFile src("one.shader", "Shader \"o\" { SubShader { Pass { " +
                                                   std::string(f.field) + " " + shader_word +
                                                   " } } }");
            ASSERT_TRUE(shaderlab::Parse(src, diags).has_value());
            EXPECT_EQ(diags.error_count(), 0u);
        }
        // A word outside the table: rejected by .material, by ShaderLab and by the resolver.
        material::Material m;
        EXPECT_FALSE(ParseOverride(
            f.field, std::string(f.field) == "Blend" ? "[\"Sideways\", \"One\"]" : "\"Sideways\"",
            m));
        DiagnosticList diags;
        const SourceFile src("bad.shader", "Shader \"o\" { SubShader { Pass { " +
                                               std::string(f.field) + " Sideways One } } }");
        (void)shaderlab::Parse(src, diags);
        EXPECT_GT(diags.error_count(), 0u);
        const pack::StateOverride o{f.field, {"Sideways", "One"}};
        EXPECT_FALSE(pack::ResolvePassState(pk, 0, nullptr, {&o, 1}).ok());
    }
    // ColorMask: any channel order, each at most once, or 0; the canonical spelling is RGBA order.
    material::Material m;
    ASSERT_TRUE(ParseOverride("ColorMask", "\"ar\"", m));
    EXPECT_EQ(m.render_state[0].values[0], "RA");
    EXPECT_EQ(pack::ParseColorMask("AR"), pack::ParseColorMask("RA"));
    EXPECT_FALSE(pack::ParseColorMask("RR").has_value());
    EXPECT_FALSE(ParseOverride("ColorMask", "\"RR\"", m));
}

TEST(RenderStateAgreement, OutOfRangePassIsRejected) {
    const CompiledStates states(1);
    ASSERT_TRUE(states.ok) << states.diagnostics;
    const pack::Pack& pk = states.pack;
    const Result<pack::PassState> s = pack::ResolvePassState(pk, 100000, nullptr, {});
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("out of range"), std::string::npos);
}

}  // namespace
}  // namespace kiln
