// `#pragma surface surfFunction lightModel [options]`: the directive of a Unity surface shader,
// read into what the pass generator needs (issue 39; Unity manual, "Surface Shader required
// directives" and "optional directives"). The lighting model is Lambert, BlinnPhong, Standard,
// StandardSpecular or NAME for a custom `LightingNAME` function; options are flags
// (`addshadow`, `nofog`, ...) and `name:value` pairs (`vertex:func`, `alpha:fade`, ...). An unknown
// option is an error naming the closest one (K4016); a missing function or model is K4009.
#ifndef KILN_SURFACE_DIRECTIVE_H_
#define KILN_SURFACE_DIRECTIVE_H_

#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "kiln/diagnostic.h"
#include "kiln/shaderlab/ast.h"

namespace kiln::surface {

// `alpha` (= `alpha:auto`: fade for the simple lighting models, premultiplied for the physically
// based ones), `alpha:blend`, `alpha:fade`, `alpha:premul`.
enum class AlphaMode { kOpaque, kAuto, kBlend, kFade, kPremul };
// `decal:add` (additive, as the terrain's AddPass), `decal:blend` (alpha-blended).
enum class DecalMode { kNone, kAdd, kBlend };

struct SurfaceDirective {
    shaderlab::PragmaArg function;  // the surface function
    shaderlab::PragmaArg lighting;  // Lambert, BlinnPhong, Standard, StandardSpecular, or NAME
    AlphaMode alpha = AlphaMode::kOpaque;
    DecalMode decal = DecalMode::kNone;
    // `name:value` options naming a function or a property.
    std::optional<shaderlab::PragmaArg> alpha_test;     // alphatest:Property (the cutoff)
    std::optional<shaderlab::PragmaArg> vertex;         // vertex:Function
    std::optional<shaderlab::PragmaArg> final_color;    // finalcolor:Function
    std::optional<shaderlab::PragmaArg> final_gbuffer;  // finalgbuffer:Function
    std::optional<shaderlab::PragmaArg> final_prepass;  // finalprepass:Function
    std::optional<shaderlab::PragmaArg> tessellate;     // tessellate:Function (or a property)
    std::optional<shaderlab::PragmaArg> tess_phong;     // tessphong:Property
    std::set<std::string> excluded_paths;               // exclude_path: forward, deferred, prepass
    std::set<std::string> flags;                        // keepalpha, addshadow, nofog, ...

    bool Has(std::string_view flag) const { return flags.count(std::string(flag)) > 0; }
    // Whether the lighting model is one of Unity's built-in ones (else `Lighting<lighting>`).
    bool BuiltinLighting() const;
    // Standard and StandardSpecular (alpha:auto picks premultiplied for them).
    bool PhysicallyBased() const;
};

// The flags Unity documents (and that its built-in shaders use).
const std::set<std::string>& SurfaceFlags();

// Reads a `#pragma surface` line; nullopt after an error (every problem of the line reported).
std::optional<SurfaceDirective> ParseSurfaceDirective(const shaderlab::Pragma& pragma,
                                                      const std::string& file,
                                                      DiagnosticList& diags);

}  // namespace kiln::surface

#endif  // KILN_SURFACE_DIRECTIVE_H_
