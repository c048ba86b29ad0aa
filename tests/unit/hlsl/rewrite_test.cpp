#include "hlsl/rewrite.h"

#include <gtest/gtest.h>

namespace kiln::hlsl {
namespace {

TEST(Rewrite, ComponentWriteThroughAOneVectorBecomesAWholeWrite) {
    // UNITY_TRANSFER_FOG after preprocessing: o.fogCoord.x = (outpos).z with a float1 fogCoord.
    const std::string in =
        "struct v2f { float4 pos : SV_POSITION; float1 fogCoord : TEXCOORD0; };\n"
        "v2f vert(float4 p : POSITION) { v2f o; o . fogCoord . x = ( p ) . z;\n"
        "  o.fogCoord.x += 1; return o; }\n";
    const RewriteResult r = RewriteForGlslang(in);
    EXPECT_EQ(r.one_vector_swizzles, 2u);
    EXPECT_EQ(r.text,
              "struct v2f { float4 pos : SV_POSITION; float1 fogCoord : TEXCOORD0; };\n"
              "v2f vert(float4 p : POSITION) { v2f o; o . fogCoord  = ( p ) . z;\n"
              "  o.fogCoord += 1; return o; }\n");
}

TEST(Rewrite, NamesWithAnyOtherTypeAreLeftAlone) {
    // fogCoord is a float4 in a second struct: dropping .x there would change the meaning.
    const std::string in =
        "struct a { float1 fogCoord : TEXCOORD0; };\n"
        "struct b { float4 pos; float4 fogCoord : TEXCOORD1; };\n"
        "void f(inout b o) { o.fogCoord.x = 1; }\n"
        "float1 s, t; float4 u, w;\n"
        "void g() { s.x = 1; t.x = 2; w.x = 3; s.xx = 4; }\n";
    const RewriteResult r = RewriteForGlslang(in);
    EXPECT_EQ(r.text,
              "struct a { float1 fogCoord : TEXCOORD0; };\n"
              "struct b { float4 pos; float4 fogCoord : TEXCOORD1; };\n"
              "void f(inout b o) { o.fogCoord.x = 1; }\n"
              // The globals written get private copies (AWrittenGlobalGetsAPrivateCopy...).
              "float1 s, t; static float1 kiln_private_s = s; static float1 kiln_private_t = t; "
              "float4 u, w; static float4 kiln_private_w = w;\n"
              "void g() { kiln_private_s = 1; kiln_private_t = 2; kiln_private_w.x = 3; "
              "kiln_private_s.xx = 4; }\n");
}

TEST(Rewrite, MatrixSwizzlesReadAsValuesBecomeConstructors) {
    const std::string in =
        "float4x4 unity_ObjectToWorld;\n"
        "float f(float4x4 m[2]) { return dot ( unity_ObjectToWorld . _14_24_34 , 1 ) +\n"
        "  m[1]._m00_m11.y + (m[0])._11_22_33_44.w; }\n"
        "void g(inout float4x4 m) { m._14_24_34 = 0; }\n";
    const RewriteResult r = RewriteForGlslang(in);
    EXPECT_EQ(r.matrix_swizzles, 3u);
    EXPECT_EQ(r.text,
              "float4x4 unity_ObjectToWorld;\n"
              "float f(float4x4 m[2]) { return dot ( float3((unity_ObjectToWorld)._14, "
              "(unity_ObjectToWorld)._24, (unity_ObjectToWorld)._34) , 1 ) +\n"
              "  float2((m[1])._m00, (m[1])._m11).y + float4(((m[0]))._11, ((m[0]))._22, "
              "((m[0]))._33, ((m[0]))._44).w; }\n"
              "void g(inout float4x4 m) { m._14_24_34 = 0; }\n");
}

TEST(Rewrite, DirectivesStringsAndOrdinaryCodeAreUntouched) {
    const std::string in =
        "#line 3 \"x.shader\"\n"
        "float4 frag() : SV_Target { float4 c = 1; c.x = 2; return c.xy.xyyx; }\n";
    const RewriteResult r = RewriteForGlslang(in);
    EXPECT_FALSE(r.changed());
    EXPECT_EQ(r.text, in);
}

// Unity 2018's HLSLSupport.cginc makes half3x3 a min16float3x3 on Vulkan; glslang 12 has no such
// type. The name is padded, so what follows it keeps its column.
TEST(Rewrite, MinimumPrecisionMatricesBecome32BitMatrices) {
    const std::string in =
        "min16float3x3 f(min16float3 n) { return min16float3x3(n, n, n); }\n"
        "min16int2x2 i; min16uint4x4 u; min10float2x3 t; min16float3 v; float3x3 k;\n";
    const RewriteResult r = RewriteForGlslang(in);
    EXPECT_EQ(r.min_precision_matrices, 5u);
    EXPECT_EQ(r.text,
              "float3x3      f(min16float3 n) { return float3x3     (n, n, n); }\n"
              "int2x2      i; uint4x4      u; float2x3      t; min16float3 v; float3x3 k;\n");
}

// Unity 2018's UnityMetaPass.cginc writes a global; fxc keeps the write private to the
// invocation. The uniform keeps its name; a static copy takes every use, including a write
// through an inout argument; a struct member of the same name is left alone.
TEST(Rewrite, AWrittenGlobalGetsAPrivateCopyThatEveryUseReads) {
    const std::string in =
        "#line 1 \"meta.cginc\"\n"
        "float unity_Boost;\n"
        "cbuffer C { float4 _Tint; float4 _Other; };\n"
        "struct S { float unity_Boost; };\n"
        "void twice(inout float4 v) { v *= 2; }\n"
        "float4 frag(S s) : SV_Target {\n"
        "  unity_Boost = saturate(unity_Boost); twice(_Tint);\n"
        "  return _Tint * unity_Boost * s.unity_Boost * _Other; }\n";
    const RewriteResult r = RewriteForGlslang(in);
    EXPECT_EQ(r.private_globals, 2u);
    EXPECT_EQ(
        r.text,
        "#line 1 \"meta.cginc\"\n"
        "float unity_Boost; static float kiln_private_unity_Boost = unity_Boost;\n"
        "cbuffer C { float4 _Tint; float4 _Other; }; static float4 kiln_private__Tint = "
        "_Tint;\n"
        "struct S { float unity_Boost; };\n"
        "void twice(inout float4 v) { v *= 2; }\n"
        "float4 frag(S s) : SV_Target {\n"
        "  kiln_private_unity_Boost = saturate(kiln_private_unity_Boost); "
        "twice(kiln_private__Tint);\n"
        "  return kiln_private__Tint * kiln_private_unity_Boost * s.unity_Boost * _Other; }\n");
}

TEST(Rewrite, GlobalsOnlyReadAreLeftAlone) {
    const std::string in =
        "float4 _Color; static float4 k = 1; void get(out float4 c) { c = _Color; }\n"
        "float4 frag() : SV_Target { float4 c; get(c); k = 2; return c + _Color == 1; }\n";
    const RewriteResult r = RewriteForGlslang(in);
    EXPECT_EQ(r.private_globals, 0u);
    EXPECT_EQ(r.text, in);
}

// fxc passes the first component of a vector given to a scalar parameter (warning X3206).
TEST(Rewrite, AVectorArgumentToAScalarParameterPassesItsFirstComponent) {
    const std::string in =
        "#line 40 \"tut.shader\"\n"
        "float cells(inout float2 p, float n, bool m = false) { return n; }\n"
        "float g(float3 a) { return a.x; }\n"
        "float g(float2 a) { return a.y; }\n"
        "float scene(float2 position) {\n"
        "    float2 period = 6; float3 q = 1;\n"
        "    cells(position, period, true); cells(position, q.xy); cells(position, 2);\n"
        "    return g(q) + cells(position, float3(1, 2, 3)); }\n";
    const RewriteResult r = RewriteForGlslang(in);
    EXPECT_EQ(r.truncated_arguments, 3u);
    EXPECT_EQ(r.text,
              "#line 40 \"tut.shader\"\n"
              "float cells(inout float2 p, float n, bool m = false) { return n; }\n"
              "float g(float3 a) { return a.x; }\n"
              "float g(float2 a) { return a.y; }\n"
              "float scene(float2 position) {\n"
              "    float2 period = 6; float3 q = 1;\n"
              "    cells(position, (period).x, true); cells(position, (q.xy).x); "
              "cells(position, 2);\n"
              "    return g(q) + cells(position, (float3(1, 2, 3)).x); }\n");
    ASSERT_EQ(r.warnings.size(), 3u);
    EXPECT_EQ(r.warnings[0].file, "tut.shader");
    EXPECT_EQ(r.warnings[0].line, 45u);
    EXPECT_EQ(r.warnings[0].token, "period");
    EXPECT_NE(r.warnings[0].message.find("X3206"), std::string::npos);
    EXPECT_EQ(r.warnings[2].line, 46u);
}

// Two candidates of the same arity: which one fxc picks is overload resolution, left to glslang.
TEST(Rewrite, AnAmbiguousCallIsLeftToGlslang) {
    const std::string in =
        "float h(float a) { return a; }\nfloat h(int a) { return a; }\n"
        "float f() { float2 v = 1; return h(v); }\n";
    const RewriteResult r = RewriteForGlslang(in);
    EXPECT_EQ(r.truncated_arguments, 0u);
    EXPECT_EQ(r.text, in);
}

// Unity's `UNITY_VPOS_TYPE screenPos : VPOS` fragment input is the pixel position.
TEST(Rewrite, VposIsTheFragmentPosition) {
    const std::string in =
        "float4 frag(v2f i, float4 screenPos : VPOS) : SV_Target { return screenPos; }\n";
    const RewriteResult r = RewriteForGlslang(in);
    EXPECT_EQ(r.vpos_semantics, 1u);
    EXPECT_EQ(r.text,
              "float4 frag(v2f i, float4 screenPos : SV_Position) : SV_Target { return "
              "screenPos; }\n");
}

// fxc converts a switch selector to int; glslang wants an integer.
TEST(Rewrite, ASwitchSelectorIsConvertedToIntAsFxcDoes) {
    const std::string in =
        "float f(float x) { switch (x * 3) { case 0: return 1; default: return 0; } }\n"
        "int g(int k) { switch ((int)k) { case 1: return 2; } return 0; }\n";
    const RewriteResult r = RewriteForGlslang(in);
    EXPECT_EQ(r.switch_selectors, 1u);
    EXPECT_EQ(r.text,
              "float f(float x) { switch ((int)(x * 3)) { case 0: return 1; default: return 0; } "
              "}\n"
              "int g(int k) { switch ((int)k) { case 1: return 2; } return 0; }\n");
    // The selector's own rewrite and the conversion's insertion start at the same place.
    const RewriteResult both = RewriteForGlslang("void h(float4x4 M) { switch (M._11_22.x) {} }\n");
    EXPECT_EQ(both.text, "void h(float4x4 M) { switch ((int)(float2((M)._11, (M)._22).x)) {} }\n");
}

TEST(Tokens, OperatorsAreTheLongestOfHlsls) {
    const std::string text = "a<<=b>>c->d::e&&f||g++<=h!=i-=j--k<l\n# define X 1\n.5e-3 \"s\"";
    std::vector<std::string> got;
    for (const Token& t : Tokenize(text))
        got.emplace_back(t.text);
    EXPECT_EQ(got,
              (std::vector<std::string>{"a",  "<<=", "b",  ">>", "c",  "->", "d",     "::",   "e",
                                        "&&", "f",   "||", "g",  "++", "<=", "h",     "!=",   "i",
                                        "-=", "j",   "--", "k",  "<",  "l",  ".5e-3", "\"s\""}));
}

TEST(Tokens, NumericShapesOfTypeNames) {
    EXPECT_EQ(NumericShape("float"), 1);
    EXPECT_EQ(NumericShape("half1"), 1);
    EXPECT_EQ(NumericShape("min16float3"), 3);
    EXPECT_EQ(NumericShape("uint4x4"), 5);
    EXPECT_EQ(NumericShape("min12int2x3"), 5);
    EXPECT_EQ(NumericShape("float5"), 0);
    EXPECT_EQ(NumericShape("float4x"), 0);
    EXPECT_EQ(NumericShape("floats"), 0);
    EXPECT_EQ(NumericShape("sampler2D"), 0);
    EXPECT_EQ(NumericShape(""), 0);
}

}  // namespace
}  // namespace kiln::hlsl
