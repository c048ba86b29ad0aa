// A surface shader's Input struct (surface/input_struct.h), by the manual's conventions;
// tests/unit/surface/corpus_test.cpp reads every surface shader of the corpora.
#include "surface/input_struct.h"

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace kiln::surface {
namespace {

TEST(SurfaceInput, MembersAreReadByUnitysConventions) {
    const std::string text = R"(
        sampler2D _MainTex;
        struct Input {
            float2 uv_MainTex, uv_BumpMap;  // two declarators
            float2 uv2_Detail;
            float3 viewDir;
            /* float3 commented; */
            float4 screenPos;
            float3 worldPos;
            float3 worldRefl;
            float4 color : COLOR;
            float3 customColor;
            float facing : VFACE;
            INTERNAL_DATA
        };
        void surf(in Input IN, inout SurfaceOutput o) { o.Albedo = 1; }
    )";
    const std::optional<InputStruct> in = FindInputStruct(text, "surf");
    ASSERT_TRUE(in);
    EXPECT_EQ(in->name, "Input");
    EXPECT_TRUE(in->internal_data);
    std::vector<std::string> seen;
    for (const InputMember& m : in->members)
        seen.push_back(m.name + "=" + InputKindName(m.kind));
    EXPECT_EQ(seen,
              (std::vector<std::string>{
                  "uv_MainTex=uv_<texture>", "uv_BumpMap=uv_<texture>", "uv2_Detail=uv_<texture>",
                  "viewDir=viewDir", "screenPos=screenPos", "worldPos=worldPos",
                  "worldRefl=worldRefl", "color=COLOR", "customColor=custom", "facing=VFACE"}));
    EXPECT_EQ(in->members[0].texture, "_MainTex");
    EXPECT_EQ(in->members[2].uv_set, 1);
    EXPECT_EQ(in->members[2].texture, "_Detail");
    EXPECT_EQ(text.substr(in->members[7].offset, 5), "color");
    EXPECT_TRUE(in->Reads(InputKind::kWorldRefl));
    EXPECT_FALSE(in->Reads(InputKind::kWorldNormal));
}

TEST(SurfaceInput, TheStructIsTheSurfaceFunctionsFirstParameter) {
    const std::string text = R"(
        struct Input { float2 uv_MainTex; };
        struct Other { float3 worldNormal; };
        void vert(inout appdata_full v, out Other o) { o = (Other)0; }
        void surfAlt(Other IN, inout SurfaceOutputStandard o) {}
        void surf(Input IN, inout SurfaceOutputStandard o) { surfAlt((Other)0, o); }
    )";
    EXPECT_EQ(FindInputStruct(text, "surf")->members.front().name, "uv_MainTex");
    EXPECT_EQ(FindInputStruct(text, "surfAlt")->name, "Other");
    EXPECT_FALSE(FindInputStruct(text, "surface"));  // no such function
    EXPECT_FALSE(FindInputStruct("void surf(Missing IN, inout SurfaceOutput o) {}", "surf"));
}

}  // namespace
}  // namespace kiln::surface
