// The variant compiler end to end through the library API: variants, dedup, determinism, cache,
// diagnostics mapped to .shader and include positions, and cross-stage checks.
#include <gtest/gtest.h>

#include <filesystem>

#include "hlsl/assemble.h"
#include "kiln/pack/reader.h"
#include "spirv/optimize.h"
#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {
namespace fs = std::filesystem;

std::string MultiLight() {
    return DataPath("data/compile/multi_light.shader");
}

TEST(Compile, ThreeLightTypesGiveThreeValidVariantsAndOneVertexProgram) {
    CompileRun run = Compile({MultiLight()});
    ASSERT_TRUE(run.out.ok) << Brief(run.diags);
    ASSERT_EQ(run.out.passes.size(), 1u);
    EXPECT_EQ(run.out.passes[0].variants, 3u);
    EXPECT_EQ(run.out.passes[0].unique_vertex, 1u);    // no keyword reaches the vertex stage
    EXPECT_EQ(run.out.passes[0].unique_fragment, 2u);  // POINT and SPOT share their code
    EXPECT_EQ(run.out.stats.stage_programs, 6u);
    EXPECT_EQ(run.out.stats.unique_programs, 3u);
    EXPECT_EQ(run.out.stats.glslang_compiles, 3u);

    pack::Pack p;
    ASSERT_TRUE(kiln::test::OpenInto(run.out.pack, p));
    // SPOT's modules are POINT's: SPOT is stored as an alias of POINT, and still found.
    ASSERT_EQ(p.Count(pack::SectionTag::kVariants), 2u);
    EXPECT_EQ(run.out.stats.aliased_variants, 1u);
    EXPECT_TRUE(p.FindVariant(0, p.KeyFor(0, {"SPOT"})));
    for (uint32_t m = 0; m < p.Count(pack::SectionTag::kModules); ++m) {
        const auto bytes = p.Spirv(p.Module(m).value());
        std::vector<uint32_t> words(bytes.size() / 4);
        std::memcpy(words.data(), bytes.data(), bytes.size());
        std::string msg;
        EXPECT_TRUE(spirv::Validate(words, msg)) << msg;
    }
}

TEST(Compile, PacksAreByteIdenticalWhateverTheJobCount) {
    CompileOptions one;
    one.jobs = 1;
    CompileOptions many;
    many.jobs = 8;
    CompileRun a = Compile({MultiLight(), DataPath("../materials/Unlit.shader")}, one);
    CompileRun b = Compile({MultiLight(), DataPath("../materials/Unlit.shader")}, many);
    ASSERT_TRUE(a.out.ok && b.out.ok) << Brief(a.diags) << Brief(b.diags);
    EXPECT_EQ(a.out.pack, b.out.pack);
}

TEST(Compile, WarmCacheRebuildDoesNoGlslangWork) {
    ScratchDir dir;
    CompileOptions o;
    o.cache_dir = dir.path() + "/cache";
    CompileRun cold = Compile({MultiLight()}, o);
    ASSERT_TRUE(cold.out.ok) << Brief(cold.diags);
    EXPECT_EQ(cold.out.stats.glslang_compiles, 3u);
    EXPECT_EQ(cold.out.stats.cache_hits, 0u);
    CompileRun warm = Compile({MultiLight()}, o);
    ASSERT_TRUE(warm.out.ok);
    EXPECT_EQ(warm.out.stats.glslang_compiles, 0u);
    EXPECT_EQ(warm.out.stats.cache_hits, 3u);
    EXPECT_EQ(cold.out.pack, warm.out.pack);

    // Another optimization level is another key: nothing is reused.
    o.opt_level = OptimizationLevel::kNone;
    CompileRun o0 = Compile({MultiLight()}, o);
    EXPECT_EQ(o0.out.stats.glslang_compiles, 3u);

    // A damaged entry is a miss, not a failure.
    for (const auto& e : fs::recursive_directory_iterator(o.cache_dir)) {
        if (e.is_regular_file())
            fs::resize_file(e.path(), 10);
    }
    CompileRun damaged = Compile({MultiLight()}, o);
    ASSERT_TRUE(damaged.out.ok) << Brief(damaged.diags);
    EXPECT_EQ(damaged.out.stats.glslang_compiles, 3u);
}

// Documented in docs/variants.md: a stage is compiled from what its entry point reaches, so a
// function neither entry point calls is not compiled (glslang drops uncalled functions too).
TEST(Compile, FunctionsNoEntryPointReachesAreNotCompiled) {
    ScratchDir dir;
    const std::string path = dir.Write(
        "dead.shader", PassShader("", "            float3 broken() { return undefined_name; }\n"));
    CompileRun run = Compile({path});
    EXPECT_TRUE(run.out.ok);
    EXPECT_EQ(Brief(run.diags), "");
}

// glslang only warns when the entry point does not exist and emits a stage that does nothing.
TEST(Compile, AnEntryPointThatIsNotAFunctionIsAnErrorAtItsPragma) {
    ScratchDir dir;
    const std::string frag = dir.Write(
        "frag.shader", Replace(PassShader(""), "#pragma fragment frag", "#pragma fragment fragg"));
    CompileRun run = Compile({frag});
    EXPECT_FALSE(run.out.ok);
    EXPECT_EQ(Brief(run.diags),
              "frag.shader:8:30 K4014 fragment entry point 'fragg' is not a function of this "
              "program; did you mean 'frag'?\n");
    const std::string vert = dir.Write(
        "vert.shader", Replace(PassShader(""), "#pragma vertex vert", "#pragma vertex shade"));
    run = Compile({vert});
    EXPECT_FALSE(run.out.ok);
    EXPECT_EQ(Brief(run.diags),
              "vert.shader:7:28 K4014 vertex entry point 'shade' is not a function of this "
              "program\n");
}

// [Toggle(KW)] and [KeywordEnum] properties are keyword switches and render state reads [Enum]
// properties: no K5005 "unused" warning for either; a material's value of a switch chooses the
// shader_feature combination built, as in Unity.
TEST(Compile, KeywordSwitchPropertiesDriveTheCombinationsAMaterialNeeds) {
    ScratchDir dir;
    std::string text =
        Replace(PassShader("            #pragma shader_feature _RIMLIGHT\n"
                           "            #pragma shader_feature _Q_LOW _Q_HIGH\n"),
                "Properties { _Tint (\"Tint\", Color) = (1, 1, 1, 1) }",
                "Properties { _Tint (\"Tint\", Color) = (1, 1, 1, 1)\n"
                "        [Toggle(_RIMLIGHT)] _Rim (\"Rim\", Float) = 0\n"
                "        [KeywordEnum(Low, High)] _Q (\"Q\", Float) = 0\n"
                "        [Enum(UnityEngine.Rendering.CullMode)] _Cull (\"C\", Float) "
                "= 2 }");
    text = Replace(text, "Name \"FORWARD\"", "Name \"FORWARD\"\n            Cull [_Cull]");
    const std::string path = dir.Write("switch.shader", text);
    CompileOptions every;
    every.all_features = true;
    CompileRun all = Compile({path}, every);
    ASSERT_TRUE(all.out.ok) << Brief(all.diags);
    EXPECT_EQ(Brief(all.diags), "") << "no K5005 for keyword switches";
    EXPECT_EQ(all.out.stats.variants, 4u);

    CompileOptions material;
    material.materials["Test/Pass"] = {{{}, {{"_Rim", 1.0}, {"_Q", 1.0}}}};
    CompileRun one = Compile({path}, material);
    ASSERT_TRUE(one.out.ok) << Brief(one.diags);
    EXPECT_EQ(one.out.stats.variants, 2u);                      // all-off + (_RIMLIGHT, _Q_HIGH)
    material.materials["Test/Pass"] = {{{}, {{"_Rim", 0.0}}}};  // _Q's default: _Q_LOW
    CompileRun off = Compile({path}, material);
    ASSERT_TRUE(off.out.ok) << Brief(off.diags);
    EXPECT_EQ(off.out.stats.variants, 1u) << "the all-off combination is (_Q_LOW)";
}

TEST(Compile, TypeErrorInReachedCodePointsIntoTheShader) {
    ScratchDir dir;
    const std::string path =
        dir.Write("bad.shader",
                  "Shader \"Test/Bad\" {\n"
                  "    SubShader { Pass {\n"
                  "        CGPROGRAM\n"
                  "        #pragma vertex vert\n"
                  "        #pragma fragment frag\n"
                  "        float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n"
                  "        float4 frag() : SV_Target {\n"
                  "            float4 c = float3(1, 2, 3);\n"
                  "            return c + undefined_name;\n"
                  "        }\n"
                  "        ENDCG\n"
                  "    } }\n"
                  "}\n");
    CompileRun run = Compile({path});
    EXPECT_FALSE(run.out.ok);
    EXPECT_TRUE(run.out.pack.empty());
    EXPECT_EQ(Brief(run.diags), "bad.shader:8:22 K5001 cannot convert from 'float3' to 'float4'\n")
        << "glslang stops at the first error of a declaration; the next line is not reported";
}

// Issue 38: glslang stops at the first errors of a text. The variant's own program (reduced to
// what its entry point reaches) fails in frag, but the unreduced text, compiled again for exact
// columns, failed first in a function nothing calls: that error was reported, the real one never.
TEST(Compile, AVariantsOwnErrorIsReportedNotOneInAFunctionNothingCalls) {
    ScratchDir dir;
    const std::string path =
        dir.Write("masked.shader",
                  "Shader \"Test/Masked\" {\n"
                  "    SubShader { Pass {\n"
                  "        CGPROGRAM\n"
                  "        #pragma vertex vert\n"
                  "        #pragma fragment frag\n"
                  "        float4 unused(float4 p) { return p +* ; }\n"
                  "        float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n"
                  "        float4 frag() : SV_Target {\n"
                  "            return missing_in_frag;\n"
                  "        }\n"
                  "        ENDCG\n"
                  "    } }\n"
                  "}\n");
    CompileRun run = Compile({path});
    EXPECT_FALSE(run.out.ok);
    const std::string brief = Brief(run.diags);
    EXPECT_NE(brief.find("masked.shader:9:20 K5001 unknown variable 'missing_in_frag'"),
              std::string::npos)
        << brief;
    EXPECT_EQ(brief.find("masked.shader:6:"), std::string::npos) << brief;
}

// Issue 38: Unity's UNITY_LIGHT_ATTENUATION ends in `;`, so tutorials write it without one; Kiln's
// lacked it and the declaration fused with the next statement (16 tutorial shaders failed).
TEST(Compile, UnityLightAttenuationWithoutASemicolonCompilesAsInUnity) {
    ScratchDir dir;
    const std::string path = dir.Write(
        "atten.shader",
        "Shader \"Test/Atten\" { SubShader { Pass { Tags { \"LightMode\" = \"ForwardBase\" }\n"
        "CGPROGRAM\n"
        "#pragma vertex vert\n"
        "#pragma fragment frag\n"
        "#pragma multi_compile_fwdbase\n"
        "#include \"UnityCG.cginc\"\n"
        "#include \"Lighting.cginc\"\n"
        "#include \"AutoLight.cginc\"\n"
        "struct v2f { float4 pos : SV_POSITION; float3 worldPos : TEXCOORD0; SHADOW_COORDS(1) };\n"
        "v2f vert(appdata_base v) {\n"
        "    v2f o;\n"
        "    o.pos = UnityObjectToClipPos(v.vertex);\n"
        "    o.worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;\n"
        "    TRANSFER_SHADOW(o)\n"
        "    return o;\n"
        "}\n"
        "float4 frag(v2f i) : SV_Target {\n"
        "    UNITY_LIGHT_ATTENUATION(attenuation, i, i.worldPos)\n"
        "    float3 light = attenuation * _LightColor0.rgb;\n"
        "    return float4(light, 1);\n"
        "}\n"
        "ENDCG } } }\n");
    CompileRun run = Compile({path});
    EXPECT_TRUE(run.out.ok) << Brief(run.diags);
}

// Two of glslang's differences from Unity's compiler are reported with what Unity does and how
// to write the code portably (docs/unity-compat.md explains why they are not rewritten).
// fxc keeps a write to a global private to the invocation (Unity 2018's UnityMetaPass.cginc
// does it); Kiln gives the global a static copy (hlsl/rewrite_globals.cpp). The uniform keeps its
// name: the pack still asks for _Tint.
TEST(Compile, WriteToAGlobalIsPrivateToTheInvocationAsInUnity) {
    ScratchDir dir;
    const std::string path =
        dir.Write("global.shader",
                  Replace(PassShader("",
                                     "            void Brighten() { _Tint.rgb *= 2; }\n"
                                     "            float4 Use() { Brighten(); return _Tint; }\n"),
                          "SV_Target { return _Tint; }", "SV_Target { return Use(); }"));
    CompileRun run = Compile({path});
    ASSERT_TRUE(run.out.ok) << Brief(run.diags);
    EXPECT_EQ(Brief(run.diags), "");
    const std::string pack(run.out.pack.begin(), run.out.pack.end());
    EXPECT_NE(pack.find("_Tint"), std::string::npos);
    EXPECT_EQ(pack.find("kiln_private__Tint"), std::string::npos) << "the copy is not a uniform";
}

// The rewrite reads what an entry point reaches, as fxc compiles only that: a function nothing
// calls neither gives a global a private copy nor warns (X3206); one the entry point calls does
// both, in the stage that calls it only.
TEST(Compile, WhatNoEntryPointReachesIsNeitherRewrittenNorWarnedAbout) {
    ScratchDir dir;
    const std::string unused =
        "            float Square(float x) { return x * x; }\n"
        "            void Brighten() { _Tint.rgb *= Square(_Tint.rg); }\n";
    const std::string path = dir.Write("unused.shader", PassShader("", unused));
    CompileOptions options;
    options.keep_programs = true;
    CompileRun run = Compile({path}, options);
    ASSERT_TRUE(run.out.ok) << Brief(run.diags);
    EXPECT_EQ(Brief(run.diags), "");
    ASSERT_EQ(run.out.programs.size(), 2u);
    for (const ProgramText& p : run.out.programs)
        EXPECT_EQ(p.text.find("kiln_private__Tint"), std::string::npos) << p.text;

    const std::string used =
        dir.Write("used.shader", Replace(PassShader("", unused), "SV_Target { return _Tint; }",
                                         "SV_Target { Brighten(); return _Tint; }"));
    CompileRun called = Compile({used}, options);
    ASSERT_TRUE(called.out.ok) << Brief(called.diags);
    EXPECT_EQ(Brief(called.diags),
              "used.shader:14:51 K5002 implicit truncation of vector type: '_Tint.rg' is a "
              "'float2' passed to scalar parameter 'x' of 'Square', so its first component is "
              "used, as Unity's compiler does (X3206)\n");
    ASSERT_EQ(called.out.programs.size(), 2u);
    for (const ProgramText& p : called.out.programs) {
        EXPECT_EQ(p.text.find("kiln_private__Tint") != std::string::npos,
                  p.stage == pack::Stage::kFragment)
            << p.text;
    }
}

// A call of a function the program does not have is an unknown function: the suggestion is the
// closest function, not a variable (it was "did you mean 's'?" for a local), and there is no note
// about vector truncation (glslang reports both as "no matching overloaded function").
TEST(Compile, AnUnknownFunctionSuggestsTheClosestFunctionNotAVariable) {
    ScratchDir dir;
    const std::string path = dir.Write(
        "unknown.shader",
        Replace(PassShader("",
                           "            float Square(float x) { return x * x; }\n"
                           "            float4 Use() { float s = 2; return Sqare(s); }\n"),
                "SV_Target { return _Tint; }", "SV_Target { return Use(); }"));
    CompileRun run = Compile({path});
    EXPECT_FALSE(run.out.ok);
    EXPECT_EQ(Brief(run.diags),
              "unknown.shader:14:48 K5001 unknown function 'Sqare'; did you mean 'Square'?\n");
}

// fxc's VPOS fragment input (the pixel position) with Unity's LOD cross-fade, which reads it,
// and a float switch selector, which fxc converts to int: each used to fail (a varying nothing
// writes, K5004; "condition must be a scalar integer expression").
TEST(Compile, VposCrossFadeAndAFloatSwitchCompileAsInUnity) {
    ScratchDir dir;
    const std::string path = dir.Write("vpos.shader", R"(Shader "Test/Vpos" {
    Properties { _Band ("Band", Float) = 3 }
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #pragma multi_compile _ LOD_FADE_CROSSFADE
        #include "UnityCG.cginc"
        float _Band;
        struct v2f { float2 uv : TEXCOORD0; };
        v2f vert(float4 p : POSITION, float2 uv : TEXCOORD0, out float4 pos : SV_POSITION) {
            v2f o;
            o.uv = uv;
            pos = UnityObjectToClipPos(p);
            return o;
        }
        float4 frag(v2f i, UNITY_VPOS_TYPE screenPos : VPOS) : SV_Target {
            UNITY_APPLY_DITHER_CROSSFADE(screenPos.xy);
            float4 c = 0;
            switch (i.uv.x * _Band) {
                case 0: c = 1; break;
                case 1: c = 0.5; break;
                default: c = frac(screenPos.x / 8); break;
            }
            return c;
        }
        ENDCG
    } }
})");
    CompileRun run = Compile({path});
    EXPECT_TRUE(run.out.ok) << Brief(run.diags);
    EXPECT_EQ(Brief(run.diags), "");
}

// Unity 2018's HLSLSupport.cginc defines half3x3 as min16float3x3 on Vulkan (Standard's
// CreateTangentToWorldPerVertex); glslang 12 has no minimum-precision matrices.
TEST(Compile, MinimumPrecisionMatricesCompileAsUnity2018DefinesHalfMatrices) {
    ScratchDir dir;
    const std::string path = dir.Write(
        "min16.shader",
        Replace(PassShader("",
                           "            #define hmat3 min16float3x3\n"
                           "            hmat3 Basis(half3 n) { return hmat3(n, n, n); }\n"
                           "            float4 Use() { return float4(mul(Basis(_Tint.xyz), "
                           "_Tint.xyz), 1); }\n"),
                "SV_Target { return _Tint; }", "SV_Target { return Use(); }"));
    CompileRun run = Compile({path});
    EXPECT_TRUE(run.out.ok) << Brief(run.diags);
    EXPECT_EQ(Brief(run.diags), "");
}

// A vector passed to a scalar parameter: fxc truncates it with warning X3206, and so does Kiln
// where the argument is known to be a vector and the call has one candidate
// (hlsl/rewrite_calls.cpp); other shapes keep glslang's error with a note saying what to write.
TEST(Compile, VectorArgumentToAScalarParameterIsTruncatedWithUnitysWarning) {
    ScratchDir dir;
    const std::string path =
        dir.Write("truncate.shader",
                  Replace(PassShader("",
                                     "            float Square(float x) { return x * x; }\n"
                                     "            float4 Use() { return Square(_Tint.rgb); }\n"),
                          "SV_Target { return _Tint; }", "SV_Target { return Use(); }"));
    CompileRun run = Compile({path});
    ASSERT_TRUE(run.out.ok) << Brief(run.diags);
    EXPECT_EQ(Brief(run.diags),
              "truncate.shader:14:42 K5002 implicit truncation of vector type: '_Tint.rgb' is a "
              "'float3' passed to scalar parameter 'x' of 'Square', so its first component is "
              "used, as Unity's compiler does (X3206)\n");
}

TEST(Compile, VectorArgumentOfAnUnknownTypeToAScalarParameterExplainsUnitysTruncation) {
    ScratchDir dir;
    const std::string path = dir.Write(
        "truncate.shader",
        Replace(PassShader("",
                           "            float Square(float x) { return x * x; }\n"
                           "            float4 Use() { return Square(_Tint.rgb * 2); }\n"),
                "SV_Target { return _Tint; }", "SV_Target { return Use(); }"));
    CompileRun run = Compile({path});
    EXPECT_FALSE(run.out.ok);
    EXPECT_EQ(Brief(run.diags),
              "truncate.shader:14:35 K5001 no matching overloaded function found 'Square'\n"
              "  note: if an argument is a vector where the parameter is a scalar or a shorter "
              "vector: Unity's compiler truncates it (warning X3206), glslang does not; pass the "
              "components, as in 'f(v.x)'\n");
}

TEST(Compile, ErrorInCgIncludeIsReportedAtItsOwnLine) {
    ScratchDir dir;
    const std::string path =
        dir.Write("inc.shader",
                  "Shader \"Test/Inc\" {\n"
                  "    CGINCLUDE\n"
                  "    float4 Helper(float4 x) {\n"
                  "        return x * missing_factor;\n"
                  "    }\n"
                  "    ENDCG\n"
                  "    SubShader { Pass {\n"
                  "        CGPROGRAM\n"
                  "        #pragma vertex vert\n"
                  "        #pragma fragment frag\n"
                  "        float4 vert(float4 p : POSITION) : SV_POSITION { return Helper(p); }\n"
                  "        float4 frag() : SV_Target { return 1; }\n"
                  "        ENDCG\n"
                  "    } }\n"
                  "}\n");
    CompileRun run = Compile({path});
    EXPECT_EQ(Brief(run.diags), "inc.shader:4:20 K5001 unknown variable 'missing_factor'\n");
}

// The reduction drops a cbuffer nothing reached names (hlsl/reduce.h); a misspelt member is still
// a name the program could have meant.
TEST(Compile, AnUnknownNameSuggestsAMemberOfACbufferTheReductionDropped) {
    ScratchDir dir;
    const std::string path =
        dir.Write("cb.shader",
                  "Shader \"Test/Cb\" {\n"
                  "    SubShader { Pass {\n"
                  "        CGPROGRAM\n"
                  "        #pragma vertex vert\n"
                  "        #pragma fragment frag\n"
                  "        cbuffer Timing { float4 _Timestep; float4 _Other; };\n"
                  "        float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n"
                  "        float4 frag() : SV_Target { return _Timestap; }\n"
                  "        ENDCG\n"
                  "    } }\n"
                  "}\n");
    CompileRun run = Compile({path});
    EXPECT_EQ(Brief(run.diags),
              "cb.shader:8:44 K5001 unknown variable '_Timestap'; did you mean '_Timestep'?\n");
}

TEST(Compile, ErrorInIncludedFileIsReportedInThatFile) {
    ScratchDir dir;
    dir.Write("lib/helpers.cginc",
              "#ifndef HELPERS\n#define HELPERS\n\nfloat3 Shade(float3 n) {\n"
              "    return n *  not_declared;\n}\n#endif\n");
    const std::string path = dir.Write(
        "use.shader",
        Replace(PassShader("", "            float3 unused_helper() { return Shade(1); }\n",
                           "            #include \"lib/helpers.cginc\"\n            #include "
                           "\"lib/helpers.cginc\""),
                "return _Tint; }", "return float4(Shade(_Tint.xyz), 1); }"));
    CompileRun run = Compile({path});
    // The pass has one variant: no counts, but the note names the pass that includes the file.
    EXPECT_EQ(Brief(run.diags),
              "helpers.cginc:5:17 K5001 unknown variable 'not_declared'\n"
              "  note: fails in shader \"Test/Pass\" pass \"FORWARD\"\n");
    EXPECT_EQ(run.diags.all()[0].file, dir.path() + "/lib/helpers.cginc");
}

TEST(Compile, SharedErrorIsReportedOnceWithTheKeywordsItFailsIn) {
    ScratchDir dir;
    const std::string path = dir.Write(
        "kw.shader",
        Replace(PassShader("            #pragma multi_compile DIRECTIONAL POINT SPOT\n"
                           "            #pragma multi_compile _ SHADOWS",
                           ""),
                "return _Tint; }",
                "\n#ifdef SPOT\n        return spot_only;\n#endif\n        return _Tint; }"));
    CompileRun run = Compile({path});
    EXPECT_EQ(Brief(run.diags),
              "kw.shader:16:16 K5001 unknown variable 'spot_only'\n"
              "  note: fails in 2 of 6 variants of shader \"Test/Pass\" pass \"FORWARD\": SPOT\n"
              "  note: smallest failing keyword combination: SPOT\n");
}

TEST(Compile, IncludeResolutionOrderIsIncluderThenDashIThenTemplates) {
    ScratchDir dir;
    const std::string shader =
        dir.Write("s/order.shader", PassShader("", "", "            #include \"which.cginc\""));
    const std::string local = dir.Write("s/which.cginc", "#define WHICH 1\n");
    const std::string dash_i = dir.Write("inc/which.cginc", "#define WHICH 2\n");
    const std::string templ = dir.Write("templates/which.cginc", "#define WHICH 3\n");
    // A CGPROGRAM includes these first, as in Unity; here from this templates folder.
    for (const char* implicit : hlsl::kImplicitIncludes)
        dir.Write(std::string("templates/") + implicit, "\n");
    CompileOptions o;
    o.include_dirs = {dir.path() + "/inc"};
    o.templates_dir = dir.path() + "/templates";
    auto read = [&](const CompileRun& r, const std::string& f) {
        for (const auto& file : r.out.files) {
            if (file->path() == f)
                return true;
        }
        return false;
    };
    CompileRun a = Compile({shader}, o);
    ASSERT_TRUE(a.out.ok) << Brief(a.diags);
    EXPECT_TRUE(read(a, local));
    EXPECT_FALSE(read(a, dash_i));
    fs::remove(local);
    CompileRun b = Compile({shader}, o);
    EXPECT_TRUE(read(b, dash_i));
    EXPECT_FALSE(read(b, templ));
    fs::remove(dash_i);
    CompileRun c = Compile({shader}, o);
    EXPECT_TRUE(read(c, templ));
    fs::remove(templ);
    CompileRun d = Compile({shader}, o);
    EXPECT_FALSE(d.out.ok);
    EXPECT_NE(
        Brief(d.diags).find("order.shader:10:23 K5001 cannot find include file 'which.cginc'"),
        std::string::npos)
        << Brief(d.diags);
}

TEST(Compile, StageInterfaceMismatchIsAnError) {
    ScratchDir dir;
    const std::string path = dir.Write(
        "io.shader",
        "Shader \"Test/IO\" {\n"
        "    SubShader { Pass {\n"
        "        CGPROGRAM\n"
        "        #pragma vertex vert\n"
        "        #pragma fragment frag\n"
        "        struct VOut { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };\n"
        "        struct FIn { float4 pos : SV_POSITION; float4 color : COLOR0; };\n"
        "        VOut vert(float4 p : POSITION) { VOut o; o.pos = p; o.uv = p.xy; return o; }\n"
        "        float4 frag(FIn i) : SV_Target { return i.color; }\n"
        "        ENDCG\n"
        "    } }\n"
        "}\n");
    CompileRun run = Compile({path});
    EXPECT_EQ(Brief(run.diags),
              "io.shader:5:26 K5004 fragment input COLOR0 and vertex output TEXCOORD0 share "
              "location 0; declare the vertex outputs and fragment inputs in the same order\n"
              "  note: in shader \"Test/IO\" pass \"#1\", variant (no keywords)\n");
}

TEST(Compile, PropertiesAreCheckedAgainstShaderGlobals) {
    ScratchDir dir;
    const std::string path = dir.Write(
        "props.shader",
        Replace(Replace(PassShader("", "            float3 _Wrong;\n            float _Loose;\n"),
                        "_Tint (\"Tint\", Color) = (1, 1, 1, 1)",
                        "_Tint (\"Tint\", Color) = (1, 1, 1, 1)\n"
                        "        _Unused (\"Unused\", Float) = 0\n"
                        "        _Wrong (\"Wrong\", Color) = (1, 1, 1, 1)"),
                "return _Tint; }", "return _Tint * _Loose + _Wrong.x; }"));
    CompileRun run = Compile({path});
    ASSERT_TRUE(run.out.ok) << Brief(run.diags);
    EXPECT_EQ(Brief(run.diags),
              "props.shader:3:9 K5005 property '_Unused' has no shader variable of that name in "
              "any pass\n"
              "props.shader:4:26 K5008 property '_Wrong' is a Color but the shader does not "
              "declare it as a 4-component vector\n"
              "props.shader:1:8 K5006 shader global '_Loose' is not in Properties; materials "
              "cannot set it\n");
}

TEST(Compile, BindingsFollowTheBindingModel) {
    CompileRun run = Compile({DataPath("../materials/Unlit.shader")});
    ASSERT_TRUE(run.out.ok) << Brief(run.diags);
    pack::Pack p;
    ASSERT_TRUE(kiln::test::OpenInto(run.out.pack, p));
    const pack::VariantRec v = p.Variant(0).value();
    const pack::ModuleRec vs = p.Module(v.vertex_module).value(),
                          fs = p.Module(v.fragment_module).value();
    bool saw_per_frame = false, saw_push = false, saw_global = false, saw_tex = false;
    for (const auto& m : {vs, fs}) {
        for (uint32_t b = m.first_block; b < m.first_block + m.block_count; ++b) {
            const auto br = p.Get<pack::BlockRec>(pack::SectionTag::kBlocks, b).value();
            const std::string name(p.String(br.name));
            if (name == "UnityPerFrame")
                saw_per_frame = br.set == 0 && br.binding == 1;
            if (name == "UnityPerDraw") {
                saw_push = br.kind == uint32_t(pack::BlockKind::kPushConstant) && br.size == 128;
            }
            if (name == "$Global")
                saw_global = br.set == 1 && br.binding == 0;
        }
        for (uint32_t r = m.first_resource; r < m.first_resource + m.resource_count; ++r) {
            const auto rr = p.Get<pack::ResourceRec>(pack::SectionTag::kResources, r).value();
            if (p.String(rr.name) == "_MainTex")
                saw_tex = rr.set == 1 && rr.binding == 1;
        }
    }
    EXPECT_TRUE(saw_per_frame);
    EXPECT_TRUE(saw_push);
    EXPECT_TRUE(saw_global);
    EXPECT_TRUE(saw_tex);
}

TEST(Compile, UnitysCompileEnvironmentIsReproduced) {
    ScratchDir dir;
    const std::string shader = dir.Write("env.shader", R"(Shader "Test/Env" {
    SubShader {
        Pass {
            Tags { "LightMode" = "Meta" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_instancing
            #if !defined(UNITY_PASS_META) || !defined(SHADER_API_VULKAN) || !defined(SHADER_API_DESKTOP)
            #error "pass or API macro missing"
            #endif
            #if UNITY_VERSION != EXPECTED_VERSION || !defined(UNITY_PBS_USE_BRDF1)
            #error "version or tier macro wrong"
            #endif
            #if defined(INSTANCING_ON) && SHADER_TARGET < 35
            #error "instancing variants need shader model 3.5"
            #endif
            #if !defined(FORCED) || !defined(HLSL_SUPPORT_INCLUDED) || !defined(UNITY_SHADER_UTILITIES_INCLUDED)
            #error "implicit or forced include missing"
            #endif
            float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
            fixed4 frag() : SV_Target { return fixed4(1, 1, 1, 1); }
            ENDCG
        }
    }
})");
    const std::string forced = dir.Write("forced.cginc", "#define FORCED 1\n");
    CompileOptions o;
    o.defines = {{"EXPECTED_VERSION", "202230"}};
    o.forced_includes = {forced};
    o.strict_variants = true;  // INSTANCING_ON too, which the default profile leaves out
    CompileRun ok = Compile({shader}, o);
    EXPECT_TRUE(ok.out.ok) << Brief(ok.diags);
    EXPECT_EQ(ok.out.stats.variants, 2u);

    o.unity_version = 201940;
    o.defines = {{"EXPECTED_VERSION", "201940"}};
    EXPECT_TRUE(Compile({shader}, o).out.ok);

    o.undefines = {"UNITY_PBS_USE_BRDF1"};
    CompileRun undefined = Compile({shader}, o);
    EXPECT_FALSE(undefined.out.ok);
    EXPECT_NE(Brief(undefined.diags).find("version or tier macro wrong"), std::string::npos)
        << Brief(undefined.diags);
}

TEST(Compile, HlslProgramHasNoImplicitIncludes) {
    ScratchDir dir;
    const std::string shader = dir.Write("h.shader", R"(Shader "Test/H" {
    SubShader { Pass {
        HLSLPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #ifdef HLSL_SUPPORT_INCLUDED
        #error "HLSLPROGRAM must not include HLSLSupport.cginc"
        #endif
        float4 vert(float4 p : POSITION) : SV_POSITION { return p; }
        float4 frag() : SV_Target { return 1; }
        ENDHLSL
    } }
})");
    CompileRun run = Compile({shader});
    EXPECT_TRUE(run.out.ok) << Brief(run.diags);
}

// As in Unity, Lighting.cginc alone reaches DotClamped (through UnityGlobalIllumination ->
// UnityImageBasedLighting -> UnityStandardBRDF -> UnityDeprecated), so a tutorial shader written
// that way compiles against Kiln's templates.
TEST(Compile, LightingCgincAloneReachesDotClamped) {
    ScratchDir dir;
    const std::string shader = dir.Write("lit.shader", R"(Shader "Test/LightingOnly" {
    Properties { _Tint ("Tint", Color) = (1, 1, 1, 1) }
    SubShader { Pass {
        Tags { "LightMode" = "ForwardBase" }
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "Lighting.cginc"
        float4 _Tint;
        struct v2f { float4 pos : SV_POSITION; float3 normal : TEXCOORD0; };
        v2f vert(appdata_base v) {
            v2f o;
            o.pos = UnityObjectToClipPos(v.vertex);
            o.normal = UnityObjectToWorldNormal(v.normal);
            return o;
        }
        float4 frag(v2f i) : SV_Target {
            float3 n = normalize(i.normal);
            return _Tint * _LightColor0 * DotClamped(_WorldSpaceLightPos0.xyz, n);
        }
        ENDCG
    } }
})");
    CompileRun run = Compile({shader});
    EXPECT_TRUE(run.out.ok) << Brief(run.diags);
    EXPECT_EQ(Brief(run.diags), "");
}

}  // namespace
}  // namespace kiln::test
