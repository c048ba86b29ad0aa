// A surface shader's lighting model (surface/lighting_model.h): each documented signature of a
// custom `Lighting<Name>` function; tests/unit/surface/corpus_test.cpp finds every corpus model.
#include "surface/lighting_model.h"

#include <gtest/gtest.h>

namespace kiln::surface {
namespace {

TEST(SurfaceLighting, EveryDocumentedFormIsRecognised) {
    const std::string text = R"(
        struct ToonOutput { fixed3 Albedo; fixed3 Normal; fixed3 Emission; fixed Alpha; };
        half4 LightingToon(ToonOutput s, half3 viewDir, UnityGI gi) { return 1; }
        half4 LightingToon_Deferred(ToonOutput s, half3 viewDir, UnityGI gi, out half4 a,
                                    out half4 b, out half4 c) { a = b = c = 0; return 0; }
        void LightingToon_GI(ToonOutput s, UnityGIInput data, inout UnityGI gi) {}
        half4 LightingToon_PrePass(ToonOutput s, half4 light) { return light; }
        // A declaration and a call are not definitions:
        half4 LightingToon(ToonOutput s, UnityGI gi);
        half4 Other(ToonOutput s, UnityGI gi) { return LightingToon(s, gi); }
        // Unity 4's form, another model:
        float4 LightingStepped(SurfaceOutput s, float3 lightDir, half3 viewDir, float atten) {
            return atten;
        }
        float4 LightingCustom(SurfaceOutput s, float3 lightDir, float atten) { return atten; }
        float4 LightingWrong(SurfaceOutput s, float2 nope) { return 0; }
    )";
    const LightingModel toon = FindLightingModel(text, "Toon");
    ASSERT_EQ(toon.functions.size(), 4u);
    EXPECT_EQ(toon.Forward()->form, LightingForm::kForwardView);
    EXPECT_TRUE(toon.UsesViewDir());
    EXPECT_EQ(toon.Forward()->output_type, "ToonOutput");
    EXPECT_EQ(toon.Find(LightingForm::kDeferredView)->name, "LightingToon_Deferred");
    EXPECT_TRUE(toon.Find(LightingForm::kGI));
    EXPECT_TRUE(toon.Find(LightingForm::kPrePass));
    EXPECT_FALSE(toon.Find(LightingForm::kDeferred));

    EXPECT_EQ(FindLightingModel(text, "Stepped").Forward()->form, LightingForm::kForwardLegacyView);
    EXPECT_EQ(FindLightingModel(text, "Custom").Forward()->form, LightingForm::kForwardLegacy);
    EXPECT_FALSE(FindLightingModel(text, "Custom").UsesViewDir());
    EXPECT_FALSE(FindLightingModel(text, "Wrong").Forward()) << "no documented form";
    EXPECT_TRUE(FindLightingModel(text, "Missing").functions.empty());
    EXPECT_STREQ(LightingFormName(LightingForm::kForwardLegacy),
                 "forward (light direction and attenuation)");
}

}  // namespace
}  // namespace kiln::surface
