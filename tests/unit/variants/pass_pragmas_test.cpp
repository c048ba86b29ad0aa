#include "variants/pass_pragmas.h"

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace kiln::variants {
namespace {

struct Read {
    PassPragmas pragmas;
    DiagnosticList diags;
};

// Pragma lines start on line 5 of the generated shader.
Read ReadPragmas(const std::string& lines) {
    const std::string text =
        "Shader \"T\" { SubShader { Pass {\nCGPROGRAM\n#pragma vertex v\n"
        "#pragma fragment f\n" +
        lines + "\nENDCG\n} } }\n";
    test::ParseOutcome parsed = test::ParseText(text);
    EXPECT_FALSE(parsed.diags.has_errors()) << test::Summarize(parsed.diags);
    const auto& ss = std::get<shaderlab::SubShader>(parsed.shader->subshaders[0]);
    const auto& pass = std::get<shaderlab::Pass>(ss.passes[0]);
    Read r;
    r.pragmas = ReadPassPragmas({&pass.programs[0]}, "test.shader", pass.range, r.diags);
    return r;
}

std::string Sets(const PassPragmas& p) {
    std::string s;
    for (const auto& set : p.sets) {
        s += set.kind == pack::KeywordSetKind::kShaderFeature ? "feature" : "multi";
        if (set.flags & pack::kKeywordSetLocal)
            s += "+local";
        if (set.flags & pack::kKeywordSetVertexOnly)
            s += "+vertex";
        if (set.flags & pack::kKeywordSetFragmentOnly)
            s += "+fragment";
        s += ":";
        for (const auto& k : set.keywords)
            s += " " + (k.empty() ? std::string("_") : k);
        s += "\n";
    }
    return s;
}

TEST(PassPragmas, EntryPointsAndTarget) {
    Read r = ReadPragmas("#pragma target 3.5");
    EXPECT_EQ(r.pragmas.vertex->name, "v");
    EXPECT_EQ(r.pragmas.fragment->name, "f");
    EXPECT_EQ(r.pragmas.shader_target, 35);
    EXPECT_EQ(test::Summarize(r.diags), "");
    EXPECT_EQ(ReadPragmas("").pragmas.shader_target, 25);
}

TEST(PassPragmas, EveryKeywordPragmaForm) {
    Read r = ReadPragmas(
        "#pragma multi_compile A B\n"
        "#pragma multi_compile_local _ C\n"
        "#pragma shader_feature D\n"
        "#pragma shader_feature_local __ E F\n"
        "#pragma multi_compile_vertex _ G\n"
        "#pragma multi_compile_fragment ___ H\n"
        "#pragma shader_feature_local_fragment I\n"
        "#pragma multi_compile_local_vertex J K\n"
        "#pragma multi_compile ONLY");
    EXPECT_EQ(test::Summarize(r.diags), "");
    EXPECT_EQ(Sets(r.pragmas),
              "multi: A B\n"
              "multi+local: _ C\n"
              "feature: _ D\n"
              "feature+local: _ E F\n"
              "multi+vertex: _ G\n"
              "multi+fragment: _ H\n"
              "feature+local+fragment: _ I\n"
              "multi+local+vertex: J K\n"
              "multi: ONLY\n");
}

TEST(PassPragmas, BuiltinShortcutsExpandToDocumentedSets) {
    EXPECT_EQ(Sets(ReadPragmas("#pragma multi_compile_fwdadd").pragmas),
              "multi: POINT DIRECTIONAL SPOT POINT_COOKIE DIRECTIONAL_COOKIE\n");
    const Read base = ReadPragmas("#pragma multi_compile_fwdbase");
    EXPECT_EQ(Sets(base.pragmas),
              "multi: DIRECTIONAL\nmulti: _ LIGHTMAP_ON\nmulti: _ DIRLIGHTMAP_COMBINED\n"
              "multi: _ DYNAMICLIGHTMAP_ON\nmulti: _ SHADOWS_SCREEN\nmulti: _ SHADOWS_SHADOWMASK\n"
              "multi: _ LIGHTMAP_SHADOW_MIXING\nmulti: _ LIGHTPROBE_SH\nmulti: _ VERTEXLIGHT_ON\n");
    ASSERT_EQ(base.pragmas.rules.size(), 3u);
    EXPECT_EQ(base.pragmas.rules[1].keyword, "VERTEXLIGHT_ON");
    EXPECT_EQ(base.pragmas.rules[1].none_of,
              (std::vector<std::string>{"LIGHTMAP_ON", "DYNAMICLIGHTMAP_ON"}));
    EXPECT_EQ(base.pragmas.rules[1].pragma, "multi_compile_fwdbase");
    EXPECT_EQ(Sets(ReadPragmas("#pragma multi_compile_fog").pragmas),
              "multi: _ FOG_LINEAR FOG_EXP FOG_EXP2\n");
    EXPECT_EQ(Sets(ReadPragmas("#pragma multi_compile_instancing").pragmas),
              "multi: _ INSTANCING_ON\n");
    EXPECT_EQ(Sets(ReadPragmas("#pragma multi_compile_shadowcaster").pragmas),
              "multi: SHADOWS_DEPTH SHADOWS_CUBE\n");
    EXPECT_EQ(ReadPragmas("#pragma multi_compile_fwdadd_fullshadows").pragmas.sets.size(), 5u);
    EXPECT_EQ(ReadPragmas("#pragma multi_compile_lightpass").pragmas.rules.size(), 5u);
    EXPECT_EQ(Sets(ReadPragmas("#pragma multi_compile_particles").pragmas),
              "multi: _ SOFTPARTICLES_ON\n");
    EXPECT_EQ(Sets(ReadPragmas("#pragma multi_compile_shadowcollector").pragmas),
              "multi: _ SHADOWS_SPLIT_SPHERES\nmulti: _ SHADOWS_SINGLE_CASCADE\n");
    EXPECT_EQ(ReadPragmas("#pragma multi_compile_prepassfinal").pragmas.sets.size(), 7u);
    EXPECT_FALSE(BuiltinShortcut("multi_compile_fwdadd_nope"));
}

// `#pragma multi_compile_fwdbase nolightmap ...` (Unity's TreeCreatorLeavesFast, and the passes
// Unity generates for surface shaders) removes those keywords; an unknown modifier is a warning.
TEST(PassPragmas, ShortcutModifiersRemoveTheirKeywords) {
    const Read base = ReadPragmas(
        "#pragma multi_compile_fwdbase nolightmap nodynlightmap nodirlightmap novertexlight "
        "noshadowmask");
    EXPECT_EQ(Sets(base.pragmas),
              "multi: DIRECTIONAL\nmulti: _ SHADOWS_SCREEN\nmulti: _ LIGHTMAP_SHADOW_MIXING\n"
              "multi: _ LIGHTPROBE_SH\n");
    EXPECT_TRUE(base.diags.all().empty()) << test::Summarize(base.diags);
    EXPECT_EQ(Sets(ReadPragmas("#pragma multi_compile_fwdadd_fullshadows noshadow").pragmas),
              "multi: POINT DIRECTIONAL SPOT POINT_COOKIE DIRECTIONAL_COOKIE\n"
              "multi: _ SHADOWS_SHADOWMASK\nmulti: _ LIGHTMAP_SHADOW_MIXING\n");
    const Read typo = ReadPragmas("#pragma multi_compile_fwdbase nolightmaps");
    EXPECT_EQ(typo.pragmas.sets.size(), 9u);
    EXPECT_EQ(test::Summarize(typo.diags),
              "K4001 5:31 warning: '#pragma multi_compile_fwdbase' has no modifier "
              "'nolightmaps'; it is ignored; did you mean 'nolightmap'?\n");
}

TEST(PassPragmas, RenderersAreRecordedAndWarnWithoutVulkan) {
    Read r = ReadPragmas("#pragma only_renderers d3d11 glcore");
    EXPECT_EQ(r.pragmas.only_renderers, (std::vector<std::string>{"d3d11", "glcore"}));
    EXPECT_EQ(r.diags.all().size(), 1u);
    EXPECT_EQ(r.diags.all()[0].code, DiagCode::kRendererRestricted);
    EXPECT_EQ(ReadPragmas("#pragma only_renderers vulkan d3d11").diags.all().size(), 0u);
    EXPECT_EQ(ReadPragmas("#pragma exclude_renderers vulkan").diags.all().size(), 1u);
}

TEST(PassPragmas, Problems) {
    EXPECT_EQ(test::Summarize(ReadPragmas("#pragma kernel k").diags),
              "K4002 5:1 error: '#pragma kernel' is not supported: Kiln compiles vertex, "
              "fragment, geometry, hull and domain stages\n");
    EXPECT_EQ(test::Summarize(ReadPragmas("#pragma hull h").diags),
              "K4003 5:14 error: tessellation needs both stages: program has '#pragma hull' but "
              "no '#pragma domain'\n");
    EXPECT_EQ(test::Summarize(ReadPragmas("#pragma frobnicate").diags),
              "K4001 5:1 warning: unknown pragma 'frobnicate' is ignored\n");
    EXPECT_EQ(test::Summarize(ReadPragmas("#pragma target 9.9").diags),
              "K4005 5:16 error: unknown shader target '9.9'; expected 2.0, 2.5, 3.0, 3.5, 4.0, "
              "4.5, 4.6 or 5.0\n");
    EXPECT_EQ(
        test::Summarize(ReadPragmas("#pragma multi_compile A B\n#pragma multi_compile C A").diags),
        "K4007 6:25 error: keyword 'A' is already in another keyword set of this pass\n"
        "  note 5:23: first declared here\n");
    // The same set twice (a surface pass's shortcut and the shader's own pragma) is one set.
    const auto repeated = ReadPragmas(
        "#pragma multi_compile_instancing\n#pragma multi_compile __ SHADOWS_SHADOWMASK\n"
        "#pragma multi_compile_instancing\n#pragma multi_compile SHADOWS_SHADOWMASK _");
    EXPECT_TRUE(repeated.diags.all().empty()) << test::Summarize(repeated.diags);
    EXPECT_EQ(repeated.pragmas.sets.size(), 2u);
    EXPECT_EQ(
        test::Summarize(ReadPragmas("#pragma multi_compile _ A\n#pragma shader_feature _ A").diags),
        "K4007 6:26 error: keyword 'A' is already in another keyword set of this pass\n"
        "  note 5:25: first declared here\n");
    EXPECT_EQ(test::Summarize(ReadPragmas("#pragma multi_compile A A").diags),
              "K4007 5:25 error: keyword 'A' appears twice in one keyword set\n");
    EXPECT_EQ(test::Summarize(ReadPragmas("#pragma multi_compile A 9B").diags),
              "K4006 5:25 error: keyword '9B' is not an identifier\n");
    EXPECT_EQ(test::Summarize(ReadPragmas("#pragma multi_compile").diags),
              "K4009 5:1 error: '#pragma multi_compile' needs at least one keyword\n");
    EXPECT_EQ(test::Summarize(ReadPragmas("#pragma vertex other").diags),
              "K4004 5:1 error: second '#pragma vertex' in one program\n"
              "  note 3:16: first entry point given here\n");
    EXPECT_EQ(test::Summarize(ReadPragmas("#pragma skip_variants NOPE").diags),
              "K4012 5:23 warning: skip_variants names 'NOPE', which no keyword set declares\n");
}

TEST(PassPragmas, RequireRaisesTheShaderTargetAsInUnity) {
    EXPECT_EQ(ReadPragmas("#pragma require 2darray").pragmas.shader_target, 35);
    EXPECT_EQ(ReadPragmas("#pragma require geometry\n#pragma target 3.0").pragmas.shader_target,
              40);
    EXPECT_EQ(ReadPragmas("#pragma target 5.0\n#pragma require sampleLOD").pragmas.shader_target,
              50);
    EXPECT_EQ(ReadPragmas("#pragma require cubeArray").pragmas.shader_target, 46);
    EXPECT_EQ(ReadPragmas("#pragma require somethingnew").diags.all().size(), 0u);
}

}  // namespace
}  // namespace kiln::variants
