#include "hlsl/assemble.h"

#include <algorithm>
#include <cctype>
#include <string_view>

#include "kiln/base/text.h"
#include "kiln/pack/engine_names.h"

namespace kiln::hlsl {

const char* StageMacro(pack::Stage stage) {
    switch (stage) {
        case pack::Stage::kVertex:
            return "SHADER_STAGE_VERTEX";
        case pack::Stage::kFragment:
            return "SHADER_STAGE_FRAGMENT";
        case pack::Stage::kGeometry:
            return "SHADER_STAGE_GEOMETRY";
        case pack::Stage::kTessControl:
            return "SHADER_STAGE_HULL";
        case pack::Stage::kTessEval:
            return "SHADER_STAGE_DOMAIN";
    }
    return "SHADER_STAGE_VERTEX";
}

namespace {

using Macros = std::vector<std::pair<std::string, std::string>>;

bool IsCgProgram(const AssembleInput& in) {
    return !in.blocks.empty() && in.blocks.back()->kind == shaderlab::ProgramKind::kCgProgram;
}

void Define(std::string& s, std::string_view name, std::string_view value) {
    s += "#define ";
    s += name;
    if (!value.empty()) {
        s += ' ';
        s += value;
    }
    s += '\n';
}

}  // namespace

bool IsLineSafeName(const std::string& path) {
    for (char c : path) {
        if (c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20)
            return false;
    }
    return !path.empty();
}

std::string PassMacro(const std::string& light_mode) {
    // Unity's built-in pipeline defines these for the passes of those LightModes (its include
    // files rely on them: UnityStandardMeta.cginc on UNITY_PASS_META, UnityCG.cginc on
    // UNITY_PASS_SHADOWCASTER and UNITY_PASS_FORWARDADD).
    static const char* const kModes[][2] = {
        {pack::kLightModeForwardBase, "UNITY_PASS_FORWARDBASE"},
        {pack::kLightModeForwardAdd, "UNITY_PASS_FORWARDADD"},
        {pack::kLightModeDeferred, "UNITY_PASS_DEFERRED"},
        {pack::kLightModeShadowCaster, "UNITY_PASS_SHADOWCASTER"},
        {pack::kLightModeMeta, "UNITY_PASS_META"},
        {pack::kLightModePrepassBase, "UNITY_PASS_PREPASSBASE"},
        {pack::kLightModePrepassFinal, "UNITY_PASS_PREPASSFINAL"},
        {pack::kLightModeMotionVectors, "UNITY_PASS_MOTIONVECTORS"},
    };
    for (const auto& [mode, macro] : kModes) {
        if (base::EqualsIgnoreCase(light_mode, mode))
            return macro;
    }
    return "";
}

Macros PredefinedMacros(const AssembleInput& in) {
    Macros m = {
        // What Unity's shader compiler defines for the Vulkan target.
        {"SHADER_API_VULKAN", "1"},
        {"SHADER_API_DESKTOP", "1"},
        {"UNITY_VERSION", std::to_string(in.unity_version)},
        {"SHADER_TARGET", std::to_string(in.shader_target)},
        {StageMacro(in.stage), "1"},
        // Unity's graphics settings for desktop (tier 3) defaults, which its compiler passes as
        // macros: Standard shader quality High, reflection-probe box projection and blending,
        // detail normal maps, deferred reflections, light probe proxy volumes, RGBM lightmaps.
        {"UNITY_PBS_USE_BRDF1", "1"},
        {"UNITY_SPECCUBE_BOX_PROJECTION", "1"},
        {"UNITY_SPECCUBE_BLENDING", "1"},
        {"UNITY_ENABLE_DETAIL_NORMALMAP", "1"},
        {"UNITY_ENABLE_REFLECTION_BUFFERS", "1"},
        {"UNITY_LIGHT_PROBE_PROXY_VOLUME", "1"},
        {"UNITY_LIGHTMAP_RGBM_ENCODING", "1"},
        {"KILN", "1"},
    };
    if (const std::string pass = PassMacro(in.light_mode); !pass.empty())
        m.emplace_back(pass, "1");
    // --precision: HLSLSupport.cginc makes half and fixed min16float (RelaxedPrecision); with
    // half, SPIRV-Tools then computes that arithmetic in binary16.
    if (in.precision != pack::Precision::kFull)
        m.emplace_back("KILN_PRECISION_RELAXED", "1");
    if (in.precision == pack::Precision::kHalf)
        m.emplace_back("KILN_PRECISION_HALF", "1");
    // Precision-suffixed type names that Unity's HLSLcc back end understands for Vulkan (and that
    // its HLSLSupport.cginc therefore leaves undefined there); for glslang they are the plain
    // types (half is 32-bit, see docs/unity-compat.md).
    for (const char* type :
         {"sampler1D", "sampler2D", "sampler3D", "samplerCUBE", "Texture2D", "Texture2DArray",
          "Texture2DMS", "TextureCube", "TextureCubeArray", "Texture3D"}) {
        m.emplace_back(std::string(type) + "_half", type);
        m.emplace_back(std::string(type) + "_float", type);
    }
    return m;
}

std::string Prelude(const AssembleInput& in) {
    std::string s;
    s.reserve(2048);  // the predefined macros are about 1.2 KB
    s += "#line 1 \"";
    s += kPreludeName;
    s += "\"\n";
    auto undefined = [&](const std::string& name) {
        return std::find(in.undefines.begin(), in.undefines.end(), name) != in.undefines.end();
    };
    for (const auto& [name, value] : PredefinedMacros(in)) {
        if (!undefined(name))
            Define(s, name, value);
    }
    for (const auto& [name, value] : in.defines) {
        if (!undefined(name))
            Define(s, name, value.empty() ? std::string_view("1") : std::string_view(value));
    }
    for (const std::string& kw : in.keywords)
        Define(s, kw, "1");
    if (IsCgProgram(in)) {
        for (const char* file : kImplicitIncludes)
            s += "#include \"" + std::string(file) + "\"\n";
    }
    for (const std::string& file : in.forced_includes)
        s += "#include \"" + file + "\"\n";
    return s;
}

std::string AssembleSource(const AssembleInput& in) {
    std::string s = Prelude(in);
    for (const shaderlab::ProgramBlock* b : in.blocks) {
        const std::string& name =
            b->file.empty() || !IsLineSafeName(b->file) ? in.file_name : b->file;
        s += "#line " + std::to_string(b->body_begin.line) + " \"" + name + "\"\n";
        s.append(b->body_begin.column - 1, ' ');
        s += b->text;
        s += '\n';
    }
    return s;
}

}  // namespace kiln::hlsl
