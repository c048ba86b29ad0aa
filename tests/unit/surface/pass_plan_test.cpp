// The passes a surface shader's directive gives (surface/pass_plan.h), per option as the manual
// documents them.
#include "surface/pass_plan.h"

#include <gtest/gtest.h>

#include "shaderlab/program_scan.h"
#include "support/test_support.h"

namespace kiln::surface {
namespace {

SurfaceDirective Directive(const std::string& line) {
    DiagnosticList diags;
    const std::vector<shaderlab::Pragma> p = shaderlab::ScanPragmas(line, {0, 1, 1});
    std::optional<SurfaceDirective> d = ParseSurfaceDirective(p.at(0), "t.shader", diags);
    EXPECT_TRUE(d) << test::Summarize(diags);
    return d.value_or(SurfaceDirective{});
}

// "FORWARD/ForwardBase [ZWrite Off; Blend One One] {multi_compile_fog; ...}" per pass.
std::vector<std::string> Describe(const std::string& line, const std::string& program = "") {
    const SurfaceDirective d = Directive(line);
    std::vector<std::string> out;
    for (const PlannedPass& p : PlanSurfacePasses(d, FindLightingModel(program, d.lighting.text))) {
        std::string s = p.name + "/" + p.light_mode + " [";
        for (size_t i = 0; i < p.state.size(); ++i)
            s += (i ? "; " : "") + p.state[i];
        s += "] {";
        for (size_t i = 0; i < p.pragmas.size(); ++i)
            s += (i ? "; " : "") + p.pragmas[i];
        out.push_back(s + "}");
    }
    return out;
}

TEST(SurfacePasses, AnOpaqueStandardSurfaceGetsUnitysFourPasses) {
    EXPECT_EQ(Describe("#pragma surface surf Standard fullforwardshadows"),
              (std::vector<std::string>{
                  "FORWARD/ForwardBase [] {multi_compile_instancing; multi_compile_fog; "
                  "multi_compile_fwdbase}",
                  "FORWARD_DELTA/ForwardAdd [ZWrite Off; Blend One One] {multi_compile_fog; "
                  "multi_compile_fwdadd_fullshadows}",
                  "DEFERRED/Deferred [] {multi_compile_instancing; exclude_renderers nomrt; "
                  "multi_compile_prepassfinal}",
                  "Meta/Meta [Cull Off] {shader_feature EDITOR_VISUALIZATION}"}));
}

TEST(SurfacePasses, TransparencyBlendsAndLeavesTheGBufferOut) {
    // alpha (auto) is fade for Lambert, premultiplied for Standard.
    EXPECT_EQ(Describe("#pragma surface surf Lambert alpha noforwardadd nometa nofog"),
              (std::vector<std::string>{
                  "FORWARD/ForwardBase [ZWrite Off; Blend SrcAlpha OneMinusSrcAlpha; ColorMask "
                  "RGB] {multi_compile_instancing; multi_compile_fwdbasealpha}"}));
    const std::vector<std::string> premul = Describe("#pragma surface surf Standard alpha");
    ASSERT_EQ(premul.size(), 3u);  // forward base and add, meta
    EXPECT_NE(premul[0].find("Blend One OneMinusSrcAlpha"), std::string::npos) << premul[0];
    EXPECT_NE(premul[1].find("Blend One One]"), std::string::npos) << premul[1];
    const std::vector<std::string> fade = Describe("#pragma surface surf Standard alpha:fade");
    EXPECT_NE(fade[1].find("Blend SrcAlpha One]"), std::string::npos) << fade[1];
}

// Unity's terrain AddPass: an additive decal that also adds into the G-buffer.
TEST(SurfacePasses, AnAdditiveDecalAddsInEveryPath) {
    EXPECT_EQ(Describe("#pragma surface surf Lambert decal:add vertex:SplatmapVert "
                       "finalcolor:SplatmapFinalColor finalgbuffer:SplatmapFinalGBuffer "
                       "fullforwardshadows nometa"),
              (std::vector<std::string>{
                  "FORWARD/ForwardBase [ZWrite Off; Blend One One] {multi_compile_instancing; "
                  "multi_compile_fwdbasealpha}",
                  "FORWARD_DELTA/ForwardAdd [ZWrite Off; Blend One One] "
                  "{multi_compile_fwdadd_fullshadows}",
                  "DEFERRED/Deferred [ZWrite Off; Blend One One] {multi_compile_instancing; "
                  "exclude_renderers nomrt; multi_compile_prepassfinal}"}));
}

TEST(SurfacePasses, CodeGenerationOptionsAndCustomModels) {
    const std::vector<std::string> passes = Describe(
        "#pragma surface surf Lambert addshadow nolightmap nodynlightmap noinstancing "
        "exclude_path:deferred");
    ASSERT_EQ(passes.size(), 4u);
    EXPECT_EQ(passes[0],
              "FORWARD/ForwardBase [] {multi_compile_fog; multi_compile_fwdbase nolightmap "
              "nodynlightmap}");
    EXPECT_EQ(passes[2],
              "ShadowCaster/ShadowCaster [ZWrite On; ZTest LEqual] {multi_compile_shadowcaster}");
    // A custom model gets a deferred pass only with its _Deferred form.
    const std::string forward_only =
        "half4 LightingToon(SurfaceOutput s, half3 viewDir, UnityGI gi) { return 1; }";
    EXPECT_EQ(Describe("#pragma surface surf Toon", forward_only).size(), 3u);
    const std::string with_deferred =
        forward_only +
        "half4 LightingToon_Deferred(SurfaceOutput s, half3 viewDir, UnityGI gi, out half4 a, "
        "out half4 b, out half4 c) { a = b = c = 0; return 0; }";
    EXPECT_EQ(Describe("#pragma surface surf Toon", with_deferred).size(), 4u);
    EXPECT_TRUE(
        Describe("#pragma surface surf Toon exclude_path:forward nometa", forward_only).empty());
}

}  // namespace
}  // namespace kiln::surface
