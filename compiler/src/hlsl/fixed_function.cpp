#include "hlsl/fixed_function.h"

#include <cstdio>
#include <map>
#include <set>

namespace kiln::hlsl {
namespace {

using shaderlab::CombineOp;
using shaderlab::Combiner;
using shaderlab::CombineSource;
using shaderlab::FixedFunction;
using shaderlab::FixedValue;
using shaderlab::Property;
using shaderlab::PropertyType;

std::string Num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    std::string s = buf;
    if (s.find_first_of(".eEn") == std::string::npos)
        s += ".0";
    return s;
}

struct State {
    const FixedFunction& ff;
    std::map<std::string, const Property*> props;
    std::set<std::string> declared;
    std::string decls;

    bool IsScalarProperty(const std::string& name) const {
        auto it = props.find(name);
        if (it == props.end())
            return false;
        const PropertyType t = it->second->type;
        return t == PropertyType::kFloat || t == PropertyType::kRange || t == PropertyType::kInt ||
               t == PropertyType::kInteger;
    }

    // A material (or global) value used as a colour (float4) or a number (float). A property is
    // declared as its Properties type says (numbers as float, the rest as float4); a global
    // that Properties does not declare, as the use needs it.
    std::string Value(const FixedValue& v, bool colour) {
        if (!v.property.empty()) {
            const std::string& p = v.property;
            const bool scalar = props.count(p) ? IsScalarProperty(p) : !colour;
            if (declared.insert(p).second)
                decls += std::string(scalar ? "float " : "float4 ") + p + ";\n";
            if (colour)
                return scalar ? "float4(" + p + ", " + p + ", " + p + ", " + p + ")" : p;
            return scalar ? p : p + ".x";
        }
        if (!colour)
            return Num(v.numbers.empty() ? 0.0 : v.numbers[0]);
        std::string s = "float4(";
        for (size_t i = 0; i < 4; ++i)
            s += (i ? ", " : "") + Num(i < v.numbers.size() ? v.numbers[i] : 1.0);
        return s + ")";
    }

    // The sampler declaration and the sampling expression of a stage's texture.
    std::string Sample(const std::string& texture, size_t stage) {
        auto it = props.find(texture);
        const PropertyType t = it == props.end() ? PropertyType::kTexture2D : it->second->type;
        const std::string uv = "i.uv" + std::to_string(stage);
        if (t == PropertyType::kCube) {
            if (declared.insert(texture).second)
                decls += "samplerCUBE " + texture + ";\n";
            return "texCUBE(" + texture + ", " + uv + ".xyz)";
        }
        if (t == PropertyType::kTexture3D) {
            if (declared.insert(texture).second)
                decls += "sampler3D " + texture + ";\n";
            return "tex3D(" + texture + ", " + uv + ".xyz)";
        }
        if (declared.insert(texture).second)
            decls += "sampler2D " + texture + ";\nfloat4 " + texture + "_ST;\n";
        return "tex2D(" + texture + ", " + uv + ".xy)";
    }

    // Which vertex texcoord set a stage reads (BindChannels "texcoord1", texcoord0), default 0.
    int TexcoordSet(size_t stage) const {
        const std::string target = "texcoord" + std::to_string(stage);
        for (const auto& [from, to] : ff.bindings) {
            if (to == target || (stage == 0 && to == "texcoord"))
                return from == "texcoord1" ? 1 : 0;
        }
        return 0;
    }
};

std::string Source(const CombineSource& s) {
    static const std::map<std::string, std::string> kNames = {
        {"previous", "prev"}, {"primary", "prim"}, {"texture", "tex"}, {"constant", "cnst"}};
    auto it = kNames.find(s.name);
    std::string v = it == kNames.end() ? "prev" : it->second;
    if (s.alpha)
        v += ".aaaa";
    return s.one_minus ? "(1.0 - " + v + ")" : v;
}

std::string Combine(const Combiner& c) {
    const auto& s = c.sources;
    auto at = [&](size_t i) { return i < s.size() ? Source(s[i]) : std::string("prev"); };
    std::string e;
    switch (c.op) {
        case CombineOp::kNone:
            e = at(0);
            break;
        case CombineOp::kMultiply:
            e = at(0) + " * " + at(1);
            break;
        case CombineOp::kAdd:
            e = at(0) + " + " + at(1);
            break;
        case CombineOp::kSubtract:
            e = at(0) + " - " + at(1);
            break;
        case CombineOp::kAddSigned:
            e = at(0) + " + " + at(1) + " - 0.5";
            break;
        case CombineOp::kLerp:  // src1 lerp (src2) src3: from src3 to src1 by src2's alpha
            e = "lerp(" + at(2) + ", " + at(0) + ", (" + at(1) + ").a)";
            break;
        case CombineOp::kMultiplyAdd:
            e = at(0) + " * " + at(1) + " + " + at(2);
            break;
        case CombineOp::kMultiplyAddSigned:
            e = at(0) + " * " + at(1) + " + " + at(2) + " - 0.5";
            break;
        case CombineOp::kMultiplySubtract:
            e = at(0) + " * " + at(1) + " - " + at(2);
            break;
    }
    return c.scale == 1 ? "(" + e + ")" : "((" + e + ") * " + std::to_string(c.scale) + ".0)";
}

std::string AlphaTestCondition(const std::string& cmp,
                               const std::string& a,
                               const std::string& ref) {
    static const std::map<std::string, std::string> kOps = {
        {"Greater", ">"}, {"GEqual", ">="},   {"Less", "<"},  {"LEqual", "<="},
        {"Equal", "=="},  {"NotEqual", "!="}, {"Always", ""}, {"Never", ""}};
    if (cmp == "Never")
        return "true";
    auto it = kOps.find(cmp);
    if (it == kOps.end() || it->second.empty())
        return "";
    return "!(" + a + " " + it->second + " " + ref + ")";
}

// Per-vertex lighting of up to eight lights in view space (Unity's "Vertex" pass lights), as the
// fixed-function pipeline computed it (UnityCG.cginc's ShadeVertexLightsFull, plus Material).
std::string LightingCode(State& st, bool specular) {
    const FixedFunction& ff = st.ff;
    const std::string vc = "v.color";
    const bool cm_diffuse = ff.color_material == "AmbientAndDiffuse";
    const bool cm_emission = ff.color_material == "Emission";
    auto colour = [&](const std::optional<FixedValue>& v, const std::string& fallback) {
        return v ? st.Value(*v, true) : fallback;
    };
    std::string s;
    s += "    float4 diffuseC = " + (cm_diffuse ? vc : colour(ff.diffuse, "float4(1, 1, 1, 1)")) +
         ";\n";
    s += "    float4 ambientC = " + (cm_diffuse ? vc : colour(ff.ambient, "float4(0, 0, 0, 1)")) +
         ";\n";
    s +=
        "    float4 emissionC = " + (cm_emission ? vc : colour(ff.emission, "float4(0, 0, 0, 0)")) +
        ";\n";
    s += "    float3 viewPos = UnityObjectToViewPos(v.vertex.xyz);\n";
    s += "    // guard: a zero normal stays zero\n";
    s += "    float3 viewN = mul((float3x3)UNITY_MATRIX_IT_MV, v.normal);\n";
    s += "    viewN *= rsqrt(max(dot(viewN, viewN), 1e-12));\n";
    s += "    float3 lit = emissionC.rgb + ambientC.rgb * glstate_lightmodel_ambient.rgb;\n";
    s += "    float3 spec = 0;\n";
    if (specular) {
        s += "    float specPower = max(" +
             (ff.shininess ? st.Value(*ff.shininess, false) : std::string("0.7")) +
             " * 128.0, 1e-4);\n";
    }
    s += "    for (int l = 0; l < 8; l++) {\n";
    s += "        float3 toLight = unity_LightPosition[l].xyz - viewPos * "
         "unity_LightPosition[l].w;\n";
    s += "        float lengthSq = dot(toLight, toLight);\n";
    s += "        // guard: a vertex at the light's position has no direction to it\n";
    s += "        toLight *= rsqrt(max(lengthSq, 1e-12));\n";
    s += "        float atten = 1.0 / (1.0 + lengthSq * unity_LightAtten[l].z);\n";
    s += "        float rho = max(0, dot(toLight, unity_SpotDirection[l].xyz));\n";
    s += "        atten *= saturate((rho - unity_LightAtten[l].x) * unity_LightAtten[l].y);\n";
    s += "        float ndotl = max(0, dot(viewN, toLight));\n";
    s += "        lit += diffuseC.rgb * unity_LightColor[l].rgb * (ndotl * atten);\n";
    if (specular) {
        s += "        float3 h = toLight - normalize(viewPos);\n";
        s += "        h *= rsqrt(max(dot(h, h), 1e-12));\n";
        s += "        // guard: pow of a zero base with the exponent bounded above 0\n";
        s += "        spec += unity_LightColor[l].rgb * (pow(max(dot(viewN, h), 1e-30), specPower) "
             "* atten * (ndotl > 0 ? 1.0 : 0.0));\n";
    }
    s += "    }\n";
    s += "    o.primary = float4(lit, diffuseC.a);\n";
    if (specular) {
        const std::string sc = colour(ff.specular, "float4(1, 1, 1, 1)");
        if (ff.separate_specular.value_or(false)) {
            s += "    o.specular = float4(spec * " + sc + ".rgb, 0);\n";
        } else {
            s += "    o.primary.rgb += spec * " + sc + ".rgb;\n";
        }
    }
    return s;
}

}  // namespace

void MergeFixedFunction(FixedFunction& outer, const FixedFunction& inner) {
    auto over = [](auto& a, const auto& b) {
        if (b)
            a = b;
    };
    over(outer.lighting, inner.lighting);
    over(outer.separate_specular, inner.separate_specular);
    over(outer.color_material, inner.color_material);
    over(outer.color, inner.color);
    over(outer.diffuse, inner.diffuse);
    over(outer.ambient, inner.ambient);
    over(outer.specular, inner.specular);
    over(outer.emission, inner.emission);
    over(outer.shininess, inner.shininess);
    over(outer.alpha_test, inner.alpha_test);
    over(outer.alpha_ref, inner.alpha_ref);
    if (!inner.stages.empty())
        outer.stages = inner.stages;
    if (!inner.bindings.empty())
        outer.bindings = inner.bindings;
    outer.any = outer.any || inner.any;
}

std::string FixedFunctionProgram(const FixedFunction& ff, const std::vector<Property>& properties) {
    State st{ff, {}, {}, {}};
    for (const Property& p : properties)
        st.props[p.name] = &p;
    const bool lit = ff.lighting.value_or(false);
    const bool specular = lit && (ff.specular.has_value() || ff.separate_specular.value_or(false));
    const bool separate = specular && ff.separate_specular.value_or(false);

    std::string vert;
    if (lit) {
        vert += LightingCode(st, specular);
    } else {
        // Unlit: the Color command, else the vertex colour (white where a mesh has none).
        vert += "    o.primary = " + (ff.color ? st.Value(*ff.color, true) : "v.color") + ";\n";
    }
    std::string frag = "    float4 prim = i.primary;\n    float4 prev = prim;\n";
    std::string v2f_uv;
    for (size_t k = 0; k < ff.stages.size(); ++k) {
        const shaderlab::TextureStage& stage = ff.stages[k];
        const std::string n = std::to_string(k);
        const std::string uv = st.TexcoordSet(k) == 1 ? "v.texcoord1" : "v.texcoord";
        v2f_uv += "    float4 uv" + n + " : TEXCOORD" + n + ";\n";
        const std::string sample = st.Sample(stage.texture, k);
        auto prop = st.props.find(stage.texture);
        const bool plain_2d =
            prop == st.props.end() || (prop->second->type != PropertyType::kCube &&
                                       prop->second->type != PropertyType::kTexture3D);
        vert += plain_2d ? "    o.uv" + n + " = float4(TRANSFORM_TEX(" + uv + ".xy, " +
                               stage.texture + "), 0, 0);\n"
                         : "    o.uv" + n + " = " + uv + ";\n";
        frag += "    {\n        float4 tex = " + sample + ";\n";
        frag += "        float4 cnst = " +
                (stage.constant_color ? st.Value(*stage.constant_color, true)
                                      : std::string("float4(0, 0, 0, 0)")) +
                ";\n";
        frag += "        float4 c = " + Combine(stage.color) + ";\n";
        if (stage.alpha)
            frag += "        c.a = " + Combine(*stage.alpha) + ".a;\n";
        frag += "        prev = saturate(c);\n    }\n";
    }
    if (separate)
        frag += "    prev.rgb = saturate(prev.rgb + i.specular.rgb);\n";
    if (ff.alpha_test && ff.alpha_ref) {
        const std::string cond =
            AlphaTestCondition(*ff.alpha_test, "prev.a", st.Value(*ff.alpha_ref, false));
        if (!cond.empty())
            frag += "    if (" + cond + ")\n        discard;\n";
    }

    std::string s = "\n// Generated by Kiln from this pass's fixed-function commands\n";
    s += "#pragma vertex " + std::string(kFixedFunctionVertex) + "\n";
    s += "#pragma fragment " + std::string(kFixedFunctionFragment) + "\n";
    s += "#include \"UnityCG.cginc\"\n";
    s += st.decls;
    s += "struct kiln_ff_appdata {\n    float4 vertex : POSITION;\n";
    if (lit)
        s += "    float3 normal : NORMAL;\n";
    s += "    float4 color : COLOR;\n    float4 texcoord : TEXCOORD0;\n";
    s += "    float4 texcoord1 : TEXCOORD1;\n};\n";
    s += "struct kiln_ff_v2f {\n    float4 pos : SV_POSITION;\n    float4 primary : COLOR0;\n";
    if (separate)
        s += "    float4 specular : COLOR1;\n";
    s += v2f_uv + "};\n";
    s += "kiln_ff_v2f " + std::string(kFixedFunctionVertex) + "(kiln_ff_appdata v) {\n";
    s += "    kiln_ff_v2f o = (kiln_ff_v2f)0;\n";
    s += "    o.pos = UnityObjectToClipPos(v.vertex.xyz);\n" + vert + "    return o;\n}\n";
    s += "float4 " + std::string(kFixedFunctionFragment) + "(kiln_ff_v2f i) : SV_Target {\n";
    s += frag + "    return prev;\n}\n";
    return s;
}

}  // namespace kiln::hlsl
