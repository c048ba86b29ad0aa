// A surface shader's lighting model: the `Lighting<Name>` functions the generated passes call
// (Unity manual, "Surface Shader lighting models"), found in the program's text (a custom model)
// or its includes (Lambert and BlinnPhong in Lighting.cginc, Standard and StandardSpecular in
// UnityPBSLighting.cginc), each classified by its documented signature. The output struct (the
// first parameter's type) is what the surface function fills (issue 39).
#ifndef KILN_SURFACE_LIGHTING_MODEL_H_
#define KILN_SURFACE_LIGHTING_MODEL_H_

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kiln::surface {

enum class LightingForm {
    kForward,            // Lighting<Name>(SurfaceOutput s, UnityGI gi)
    kForwardView,        // Lighting<Name>(SurfaceOutput s, half3 viewDir, UnityGI gi)
    kForwardLegacy,      // Lighting<Name>(SurfaceOutput s, half3 lightDir, half atten)
    kForwardLegacyView,  // Lighting<Name>(SurfaceOutput s, half3 lightDir, half3 viewDir, half
                         // atten)
    kDeferred,           // Lighting<Name>_Deferred(s, UnityGI gi, out half4 x3)
    kDeferredView,       // Lighting<Name>_Deferred(s, half3 viewDir, UnityGI gi, out half4 x3)
    kPrePass,            // Lighting<Name>_PrePass(s, half4 light): the legacy deferred path
    kGI,                 // Lighting<Name>_GI(s, UnityGIInput data, inout UnityGI gi)
};

// "forward", "forward with view direction", ...
const char* LightingFormName(LightingForm form);

struct LightingFunction {
    std::string name;  // LightingToonRamp, LightingToonRamp_Deferred, ...
    LightingForm form = LightingForm::kForward;
    std::string output_type;  // the first parameter's type: SurfaceOutput, SurfaceOutputStandard
    size_t offset = 0;        // of the name, in the text searched
};

struct LightingModel {
    std::string name;  // Lambert, ToonRamp, ...
    std::vector<LightingFunction> functions;

    const LightingFunction* Find(LightingForm form) const;
    // The forward function (any of the four forms); null when the model has none.
    const LightingFunction* Forward() const;
    // Whether the forward function takes the view direction.
    bool UsesViewDir() const;
};

// The functions of model `name` defined in `text`; a function whose parameters fit no documented
// form is left out. Empty `functions` when none is defined.
LightingModel FindLightingModel(std::string_view text, std::string_view name);

}  // namespace kiln::surface

#endif  // KILN_SURFACE_LIGHTING_MODEL_H_
