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
              "float1 s, t; float4 u, w;\n"
              "void g() { s = 1; t = 2; w.x = 3; s.xx = 4; }\n");
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

}  // namespace
}  // namespace kiln::hlsl
