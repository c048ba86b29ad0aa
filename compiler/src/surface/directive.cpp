#include "surface/directive.h"

#include <algorithm>
#include <array>
#include <vector>

#include "kiln/pack/names.h"

namespace kiln::surface {
namespace {

using shaderlab::PragmaArg;

// `name:value` options, in the manual's order.
constexpr std::array<std::string_view, 10> kValued = {
    "alpha",        "alphatest",    "decal",        "vertex",     "finalcolor",
    "finalgbuffer", "finalprepass", "exclude_path", "tessellate", "tessphong"};

struct State {
    const std::string& file;
    DiagnosticList& diags;
    SurfaceDirective out;
    bool ok = true;

    void Fail(DiagCode code, SourceRange range, std::string message) {
        diags.Error(code, file, range, std::move(message));
        ok = false;
    }

    std::vector<std::string> Names() const {
        std::vector<std::string> names(SurfaceFlags().begin(), SurfaceFlags().end());
        for (std::string_view v : kValued)
            names.push_back(std::string(v) + ":");
        return names;
    }

    // `value` of `name:value` as an argument of its own (its range past the colon).
    static PragmaArg ValueOf(const PragmaArg& arg, size_t colon) {
        PragmaArg v{arg.text.substr(colon + 1), arg.range};
        v.range.begin.column += static_cast<uint32_t>(colon + 1);
        v.range.begin.offset += static_cast<uint32_t>(colon + 1);
        return v;
    }

    void Choice(const PragmaArg& arg,
                const PragmaArg& value,
                std::initializer_list<std::string_view> choices) {
        std::vector<std::string> names(choices.begin(), choices.end());
        Fail(
            DiagCode::kMisspelledPragma, value.range, "'" + arg.text + "': expected " + [&] {
                std::string s;
                for (size_t i = 0; i < names.size(); ++i)
                    s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
                return s;
            }() + pack::DidYouMean(value.text, names));
    }

    void Valued(const PragmaArg& arg, const std::string& name, const PragmaArg& value) {
        if (value.text.empty()) {
            Fail(DiagCode::kPragmaMissingArgument, arg.range,
                 "surface option '" + name + ":' needs a value after the colon");
            return;
        }
        if (name == "alpha") {
            const std::string& v = value.text;
            out.alpha = v == "auto"     ? AlphaMode::kAuto
                        : v == "blend"  ? AlphaMode::kBlend
                        : v == "fade"   ? AlphaMode::kFade
                        : v == "premul" ? AlphaMode::kPremul
                                        : AlphaMode::kOpaque;
            if (out.alpha == AlphaMode::kOpaque)
                Choice(arg, value, {"auto", "blend", "fade", "premul"});
        } else if (name == "decal") {
            out.decal = value.text == "add"     ? DecalMode::kAdd
                        : value.text == "blend" ? DecalMode::kBlend
                                                : DecalMode::kNone;
            if (out.decal == DecalMode::kNone)
                Choice(arg, value, {"add", "blend"});
        } else if (name == "exclude_path") {
            if (value.text != "forward" && value.text != "deferred" && value.text != "prepass")
                Choice(arg, value, {"forward", "deferred", "prepass"});
            out.excluded_paths.insert(value.text);
        } else {
            std::optional<PragmaArg>& slot = name == "alphatest"      ? out.alpha_test
                                             : name == "vertex"       ? out.vertex
                                             : name == "finalcolor"   ? out.final_color
                                             : name == "finalgbuffer" ? out.final_gbuffer
                                             : name == "finalprepass" ? out.final_prepass
                                             : name == "tessellate"   ? out.tessellate
                                                                      : out.tess_phong;
            slot = value;
        }
    }

    void Option(const PragmaArg& arg) {
        const size_t colon = arg.text.find(':');
        const std::string name = arg.text.substr(0, colon);
        if (colon != std::string::npos &&
            std::find(kValued.begin(), kValued.end(), name) != kValued.end()) {
            Valued(arg, name, ValueOf(arg, colon));
            return;
        }
        if (colon == std::string::npos && name == "alpha") {
            out.alpha = AlphaMode::kAuto;
            return;
        }
        if (colon == std::string::npos && SurfaceFlags().count(name)) {
            out.flags.insert(name);
            return;
        }
        Fail(DiagCode::kMisspelledPragma, arg.range,
             "unknown surface shader option '" + arg.text + "'" +
                 pack::DidYouMean(colon == std::string::npos ? arg.text : name + ":", Names()));
    }
};

}  // namespace

bool SurfaceDirective::BuiltinLighting() const {
    return lighting.text == "Lambert" || lighting.text == "BlinnPhong" || PhysicallyBased();
}

bool SurfaceDirective::PhysicallyBased() const {
    return lighting.text == "Standard" || lighting.text == "StandardSpecular";
}

const std::set<std::string>& SurfaceFlags() {
    static const std::set<std::string> flags = {
        "keepalpha",   "addshadow",       "fullforwardshadows",
        "noshadow",    "noambient",       "novertexlights",
        "nolightmap",  "nodynlightmap",   "nodirlightmap",
        "nofog",       "nometa",          "noforwardadd",
        "nolppv",      "noshadowmask",    "noinstancing",
        "halfasview",  "interpolateview", "approxview",
        "dualforward", "softvegetation",  "dithercrossfade"};
    return flags;
}

std::optional<SurfaceDirective> ParseSurfaceDirective(const shaderlab::Pragma& pragma,
                                                      const std::string& file,
                                                      DiagnosticList& diags) {
    State st{file, diags, {}};
    if (pragma.args.size() < 2) {
        st.Fail(DiagCode::kPragmaMissingArgument, pragma.range,
                std::string("'#pragma surface' needs ") +
                    (pragma.args.empty() ? "a surface function and a lighting model"
                                         : "a lighting model after the surface function") +
                    " (#pragma surface surf Lambert)");
        return std::nullopt;
    }
    st.out.function = pragma.args[0];
    st.out.lighting = pragma.args[1];
    for (size_t i = 2; i < pragma.args.size(); ++i)
        st.Option(pragma.args[i]);
    if (!st.ok)
        return std::nullopt;
    return std::move(st.out);
}

}  // namespace kiln::surface
