// Structure: Shader, Category, SubShader, Pass, UsePass, GrabPass, Tags, LOD, Fallback,
// CustomEditor, Dependency, program blocks at every level, comments, case-insensitivity.
#include <gtest/gtest.h>

#include "support/test_support.h"

namespace kiln::test {
namespace {

using namespace kiln::shaderlab;

const SubShader& Sub(const Shader& s, size_t i) {
    return std::get<SubShader>(s.subshaders.at(i));
}

TEST(Parser, FullStructure) {
    ParseOutcome out = ParseText(R"(// leading comment
Shader "Custom/Full" {
    Properties { _Color ("Color", Color) = (1, 0, 0, 1) }
    CGINCLUDE
    float4 shared_code;
    ENDCG
    /* a block comment
       over two lines */
    SubShader {
        Tags { "RenderType" = "Opaque" "Queue" = "Geometry+1" }
        LOD 300
        Cull Front
        HLSLINCLUDE
        // subshader-level include
        ENDHLSL
        Pass {
            Name "FORWARD"
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            ENDCG
        }
        UsePass "Other/SHADOWCASTER"
        GrabPass { "_Background" }
        GrabPass { Name "GRAB" Tags { "A" = "B" } }
    }
    Fallback "Diffuse"
    CustomEditor "MyEditor"
    Dependency "BaseMapShader" = "Custom/Base"
}
)");
    ASSERT_FALSE(out.diags.has_errors()) << Summarize(out.diags);
    ASSERT_TRUE(out.shader);
    const Shader& s = *out.shader;
    EXPECT_EQ(s.name, "Custom/Full");
    EXPECT_EQ(s.name_range.begin.line, 2u);
    EXPECT_EQ(s.name_range.begin.column, 8u);
    ASSERT_EQ(s.programs.size(), 1u);
    EXPECT_EQ(s.programs[0].kind, ProgramKind::kCgInclude);
    EXPECT_EQ(s.programs[0].text, "\n    float4 shared_code;\n    ");
    const SubShader& sub = Sub(s, 0);
    ASSERT_EQ(sub.tags.size(), 2u);
    EXPECT_EQ(sub.tags[1].key, "Queue");
    EXPECT_EQ(sub.tags[1].value, "Geometry+1");
    EXPECT_EQ(sub.lod, 300);
    ASSERT_TRUE(sub.state.cull);
    EXPECT_EQ(sub.state.cull->value.text, "Front");
    ASSERT_EQ(sub.programs.size(), 1u);
    EXPECT_EQ(sub.programs[0].kind, ProgramKind::kHlslInclude);
    ASSERT_EQ(sub.passes.size(), 4u);
    const Pass& pass = std::get<Pass>(sub.passes[0]);
    EXPECT_EQ(pass.name, "FORWARD");
    EXPECT_EQ(pass.tags.at(0).value, "ForwardBase");
    ASSERT_EQ(pass.programs.size(), 1u);
    EXPECT_EQ(pass.programs[0].pragmas.size(), 2u);
    EXPECT_EQ(std::get<UsePass>(sub.passes[1]).target, "Other/SHADOWCASTER");
    EXPECT_EQ(std::get<GrabPass>(sub.passes[2]).texture_name, "_Background");
    EXPECT_EQ(std::get<GrabPass>(sub.passes[3]).name, "GRAB");
    ASSERT_TRUE(s.fallback);
    EXPECT_FALSE(s.fallback->off);
    EXPECT_EQ(s.fallback->name, "Diffuse");
    EXPECT_EQ(s.custom_editor, "MyEditor");
    ASSERT_EQ(s.dependencies.size(), 1u);
    EXPECT_EQ(s.dependencies[0].value, "Custom/Base");
}

TEST(Parser, ProgramBlockKeepsExactStartPosition) {
    ParseOutcome out = ParseText(
        "Shader \"x\" {\n SubShader {\n  Pass {\n   CGPROGRAM   // c\n"
        "   float4 a;\n   ENDCG\n  }\n }\n}\n");
    ASSERT_FALSE(out.diags.has_errors()) << Summarize(out.diags);
    const ProgramBlock& p = std::get<Pass>(Sub(*out.shader, 0).passes[0]).programs.at(0);
    EXPECT_EQ(p.range.begin.line, 4u);
    EXPECT_EQ(p.range.begin.column, 4u);
    EXPECT_EQ(p.body_begin.line, 4u);
    EXPECT_EQ(p.body_begin.column, 13u);  // right after "CGPROGRAM"
    EXPECT_EQ(p.text, "   // c\n   float4 a;\n   ");
    EXPECT_EQ(p.range.end.line, 6u);
    EXPECT_EQ(p.range.end.column, 9u);  // after "ENDCG"
}

TEST(Parser, ProgramBodyIsVerbatimIncludingBracesAndLookalikes) {
    // Braces, strings and words that merely contain ENDCG do not end or confuse the block.
    const std::string body = "\n{ } \"}\" int ENDCGX = 1; // MY_ENDCG\n";
    ParseOutcome out =
        ParseText("Shader \"x\" { SubShader { Pass { CGPROGRAM" + body + "ENDCG } } }");
    ASSERT_FALSE(out.diags.has_errors()) << Summarize(out.diags);
    EXPECT_EQ(std::get<Pass>(Sub(*out.shader, 0).passes[0]).programs.at(0).text, body);
}

TEST(Parser, CategoryNestsAndHoldsState) {
    ParseOutcome out = ParseText(R"(Shader "x" {
  Category {
    ZWrite Off
    Tags { "Queue" = "Transparent" }
    Category {
      Blend SrcAlpha OneMinusSrcAlpha
      SubShader { Pass { } }
    }
    SubShader { }
  }
  Fallback Off
})");
    ASSERT_FALSE(out.diags.has_errors()) << Summarize(out.diags);
    const auto& outer = *std::get<std::unique_ptr<Category>>(out.shader->subshaders.at(0));
    EXPECT_EQ(outer.state.zwrite->value.text, "Off");
    EXPECT_EQ(outer.tags.at(0).key, "Queue");
    ASSERT_EQ(outer.children.size(), 2u);
    const auto& inner = *std::get<std::unique_ptr<Category>>(outer.children[0]);
    EXPECT_EQ(inner.state.blend.at(0).src.text, "SrcAlpha");
    EXPECT_EQ(std::get<SubShader>(inner.children.at(0)).passes.size(), 1u);
    EXPECT_TRUE(out.shader->fallback->off);
}

TEST(Parser, CommandsAndValuesAreCaseInsensitive) {
    ParseOutcome out = ParseText(
        "shader \"x\" { subshader { PASS { cull BACK zwrite off ztest lequal "
        "blend srcalpha oneminussrcalpha } } FALLBACK OFF }");
    ASSERT_FALSE(out.diags.has_errors()) << Summarize(out.diags);
    const RenderState& st = std::get<Pass>(Sub(*out.shader, 0).passes[0]).state;
    EXPECT_EQ(st.cull->value.text, "Back");  // canonical spelling
    EXPECT_EQ(st.ztest->value.text, "LEqual");
    EXPECT_EQ(st.blend.at(0).dst.text, "OneMinusSrcAlpha");
}

TEST(Parser, FixedFunctionCommandsAreParsed) {
    ParseOutcome out = ParseText(R"(Shader "x" { SubShader {
    Lighting On SeparateSpecular On ColorMaterial AmbientAndDiffuse
    Material { Diffuse [_Color] Ambient (0.5, 0.5, 0.5) Shininess [_Shininess] Specular (1,1,1,1) }
    Pass {
        AlphaTest Greater [_Cutoff]
        Color (1, 0, 0, 1)
        BindChannels { Bind "Vertex", vertex Bind "texcoord1", texcoord0 }
        Fog { Mode Off }
        SetTexture [_MainTex] { constantColor [_Tint] combine texture * primary DOUBLE, constant }
        SetTexture [_Detail] { combine one - previous lerp (texture alpha) constant }
        SetTexture [_Last] { combine texture * previous +- constant Quad }
        Cull Off
    } } })");
    ASSERT_FALSE(out.diags.has_errors()) << Summarize(out.diags);
    EXPECT_EQ(out.diags.all().size(), 0u) << Summarize(out.diags);  // Fog Mode Off is no loss
    const SubShader& sub = Sub(*out.shader, 0);
    EXPECT_EQ(sub.fixed.lighting, true);
    EXPECT_EQ(sub.fixed.separate_specular, true);
    EXPECT_EQ(sub.fixed.color_material, "AmbientAndDiffuse");
    EXPECT_EQ(sub.fixed.diffuse->property, "_Color");
    EXPECT_EQ(sub.fixed.ambient->numbers, (std::vector<double>{0.5, 0.5, 0.5, 1.0}));
    EXPECT_EQ(sub.fixed.shininess->property, "_Shininess");
    const Pass& pass = std::get<Pass>(sub.passes[0]);
    EXPECT_EQ(pass.state.cull->value.text, "Off");
    EXPECT_EQ(pass.fixed.alpha_test, "Greater");
    EXPECT_EQ(pass.fixed.alpha_ref->property, "_Cutoff");
    EXPECT_EQ(pass.fixed.color->numbers, (std::vector<double>{1, 0, 0, 1}));
    EXPECT_EQ(pass.fixed.bindings.size(), 2u);
    EXPECT_EQ(pass.fixed.bindings[1],
              (std::pair<std::string, std::string>{"texcoord1", "texcoord0"}));
    ASSERT_EQ(pass.fixed.stages.size(), 3u);
    const TextureStage& s0 = pass.fixed.stages[0];
    EXPECT_EQ(s0.texture, "_MainTex");
    EXPECT_EQ(s0.constant_color->property, "_Tint");
    EXPECT_EQ(s0.color.op, CombineOp::kMultiply);
    EXPECT_EQ(s0.color.scale, 2);
    EXPECT_EQ(s0.color.sources[1].name, "primary");
    ASSERT_TRUE(s0.alpha);
    EXPECT_EQ(s0.alpha->sources[0].name, "constant");
    const Combiner& lerp = pass.fixed.stages[1].color;
    EXPECT_EQ(lerp.op, CombineOp::kLerp);
    EXPECT_TRUE(lerp.sources[0].one_minus);
    EXPECT_TRUE(lerp.sources[1].alpha);
    EXPECT_EQ(pass.fixed.stages[2].color.op, CombineOp::kMultiplyAddSigned);
    EXPECT_EQ(pass.fixed.stages[2].color.scale, 4);
}

TEST(Parser, FixedFunctionMistakesAreReported) {
    ParseOutcome out = ParseText(R"(Shader "x" { SubShader {
    SetTexture [_A] { combine texture }
    Pass {
        Lighting Maybe
        SetTexture [_B] { combine texture * nothing }
        Material { Glow (1,1,1,1) }
        Fog { Color (1,0,0,1) }
        SetTexture [_C] { matrix [_M] combine texture }
    } } })");
    EXPECT_EQ(Summarize(out.diags),
              "K2016 2:5 error: 'SetTexture' is not allowed here; it belongs in a Pass\n"
              "K2005 4:18 error: invalid value 'Maybe' for 'Lighting'; expected On or Off\n"
              "K2005 5:45 error: expected a combine source (previous, primary, texture or "
              "constant), found 'nothing'\n"
              "K2004 6:20 error: unknown command 'Glow' in a Material block; expected Diffuse, "
              "Ambient, Specular, Emission or Shininess\n"
              "K2014 7:9 warning: fixed-function 'Fog' settings are ignored: Kiln's "
              "fixed-function passes are drawn without fog\n"
              "K2014 8:27 warning: texture 'matrix' of a SetTexture stage is ignored; the "
              "texture's tiling and offset (_ST) apply\n");
}

TEST(Parser, DuplicateTagWarnsWithNote) {
    ParseOutcome out =
        ParseText("Shader \"x\" { SubShader { Tags { \"A\" = \"1\" \"A\" = \"2\" } } }");
    EXPECT_FALSE(out.diags.has_errors());
    ASSERT_EQ(out.diags.all().size(), 1u);
    EXPECT_EQ(out.diags.all()[0].code, DiagCode::kDuplicateTag);
    EXPECT_EQ(out.diags.all()[0].notes.size(), 1u);
}

TEST(Parser, LectureShadersParseWithoutDiagnostics) {
    const char* files[] = {
        "01_Lambert.shader",         "02_LambertAmbient.shader",
        "03_Phong.shader",           "04_DiffuseSpecular.shader",
        "05_Textured.shader",        "06_EnergyConservation.shader",
        "07_PhysicallyBased.shader", "08_MultipleLights.shader",
        "09_PointLight.shader",      "10_PointAndDirectional.shader",
        "11_SpotLight.shader",       "12_Deferred.shader",
    };
    for (const char* f : files) {
        const std::string path = DataPath(std::string("lecture/") + f);
        const SourceFile file(path, ReadFile(path));
        DiagnosticList diags;
        const auto shader = ParseAndCheck(file, diags);
        EXPECT_TRUE(shader) << f;
        EXPECT_TRUE(diags.all().empty()) << f << "\n" << Summarize(diags);
    }
}

TEST(Parser, LectureSpotLightPassHasTheThreeLightKeywords) {
    const std::string path = DataPath("lecture/11_SpotLight.shader");
    ParseOutcome out = ParseText(ReadFile(path));
    const Pass& add = std::get<Pass>(Sub(*out.shader, 0).passes.at(1));
    EXPECT_EQ(add.tags.at(0).value, "ForwardAdd");
    EXPECT_EQ(add.state.blend.at(0).src.text, "One");
    EXPECT_EQ(add.state.zwrite->value.text, "Off");
    const Pragma& mc = add.programs.at(0).pragmas.at(1);
    EXPECT_EQ(mc.name, "multi_compile");
    ASSERT_EQ(mc.args.size(), 3u);
    EXPECT_EQ(mc.args[2].text, "SPOT");
}

}  // namespace
}  // namespace kiln::test
