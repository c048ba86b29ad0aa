// The interpolators, v2f_surf and vert_surf of a generated surface-shader pass (Unity manual,
// "Writing Surface Shaders"; the layout follows Unity's generated code: world position and
// normal, or the tangent frame with the world position in .w when the surface function writes a
// per-pixel normal; texture coordinates transformed by their _ST; lightmap and SH in the base and
// deferred passes; light, shadow and fog coordinates in the forward passes).
#include "surface/generate_parts.h"

#include <set>

#include "hlsl/tokens.h"

namespace kiln::surface {
namespace {

bool Interpolatable(const InputMember& m) {
    const int shape = hlsl::NumericShape(m.type);
    return shape >= 1 && shape <= 4;
}

// `vin_<member>` of `type`: the vertex input's member (through `swizzle`) where its struct has it
// (under the `#if` it is declared under), else `fallback`.
std::string Local(const SurfaceShader& s,
                  const std::string& member,
                  const std::string& type,
                  const std::string& swizzle,
                  const std::string& fallback) {
    const std::string decl = "    " + type + " vin_" + member + " = ";
    if (!s.vertex_input.Has(member))
        return decl + fallback + ";\n";
    auto it = s.vertex_input.conditions.find(member);
    if (it == s.vertex_input.conditions.end() || it->second.empty())
        return decl + "v." + member + swizzle + ";\n";
    return "#if " + ConditionExpression(it->second) + "\n" + decl + "v." + member + swizzle +
           ";\n#else\n" + decl + fallback + ";\n#endif\n";
}

std::string UvMember(int set) {
    return set == 0 ? "texcoord" : "texcoord" + std::to_string(set);
}

std::string UvSource(int set) {
    return "vin_" + UvMember(set);
}

// The locals the vertex program reads the vertex input through, after the vertex: function.
std::string Locals(const SurfaceShader& s, const Interpolators& in) {
    std::string o = Local(s, "vertex", "float4", "", "float4(0, 0, 0, 1)");
    o += Local(s, "normal", "float3", ".xyz", "float3(0, 0, 1)");
    if (s.tangent_space)
        o += Local(s, "tangent", "float4", "", "float4(1, 0, 0, 1)");
    std::set<int> sets = {1, 2};  // lightmaps, light coordinates, the meta pass
    for (const InputMember* m : in.uvs)
        sets.insert(m->uv_set);
    for (int set : sets)
        o += Local(s, UvMember(set), "float2", ".xy", "float2(0, 0)");
    if (in.color)
        o += Local(s, "color", "fixed4", "", "fixed4(1, 1, 1, 1)");
    return o;
}

// Fog coordinates in an Input struct (UNITY_FOG_COORDS, as the terrain's) exist only with fog on.
const char* kFogOn = "#if defined(FOG_LINEAR) || defined(FOG_EXP) || defined(FOG_EXP2)\n";

}  // namespace

bool AppliesFog(const SurfaceShader& s, PassKind kind) {
    return (kind == PassKind::kForwardBase || kind == PassKind::kForwardAdd) &&
           !s.directive.Has("nofog") && !s.directive.final_color;
}

Interpolators PlanInterpolators(const SurfaceShader& s, PassKind kind) {
    Interpolators in;
    if (kind == PassKind::kShadowCaster) {
        in.members.push_back("V2F_SHADOW_CASTER;");
        in.next = 1;  // V2F_SHADOW_CASTER takes TEXCOORD0 for point-light shadows
    } else {
        in.members.push_back("float4 pos : SV_POSITION;");
    }
    for (const InputMember& m : s.input.members) {
        if (m.kind == InputKind::kTexcoord) {
            in.uvs.push_back(&m);
            in.members.push_back("float2 " + PackName(m) + " : " + in.Next() + ";");
        } else if (m.kind == InputKind::kCustom && s.vertex_fills_input && Interpolatable(m)) {
            in.custom.push_back(&m);
            const bool fog = m.semantic == "FOG";
            in.members.push_back(std::string(fog ? kFogOn : "") + m.type + " " + PackName(m) +
                                 " : " + in.Next() + ";" + (fog ? "\n#endif" : ""));
        }
        in.screen_pos = in.screen_pos || m.kind == InputKind::kScreenPos;
        in.color = in.color || m.kind == InputKind::kColor;
        in.facing = in.facing || m.kind == InputKind::kFacing;
    }
    // Lighting needs the world position and normal; the other passes need them when the Input
    // reads them (its surface function may also read IN.worldPos in the shadow caster).
    in.world = true;
    if (s.tangent_space) {
        for (int i = 0; i < 3; ++i)
            in.members.push_back("float4 tSpace" + std::to_string(i) + " : " + in.Next() + ";");
    } else {
        in.members.push_back("float3 worldNormal : " + in.Next() + ";");
        in.members.push_back("float3 worldPos : " + in.Next() + ";");
    }
    if (in.screen_pos)
        in.members.push_back("float4 screenPos : " + in.Next() + ";");
    if (in.color)
        in.members.push_back("fixed4 color : COLOR0;");
    in.ambient = kind == PassKind::kForwardBase || kind == PassKind::kDeferred;
    if (in.ambient) {
        in.members.push_back("float4 lmap : " + in.Next() + ";");
        in.members.push_back("half3 sh : " + in.Next() + ";");
    }
    in.lighting = kind == PassKind::kForwardBase || kind == PassKind::kForwardAdd;
    if (in.lighting) {
        const int a = in.next++, b = in.next++;
        in.members.push_back("UNITY_LIGHTING_COORDS(" + std::to_string(a) + ", " +
                             std::to_string(b) + ")");
    }
    in.fog = AppliesFog(s, kind);
    if (in.fog)
        in.members.push_back("UNITY_FOG_COORDS(" + std::to_string(in.next++) + ")");
    if (s.vertex_input.instance_id)
        in.members.push_back("UNITY_VERTEX_INPUT_INSTANCE_ID");
    return in;
}

std::string V2fStruct(const Interpolators& interp) {
    std::string out = "struct v2f_surf {\n";
    for (const std::string& m : interp.members)
        out += "    " + m + "\n";
    return out + "};\n";
}

std::string VertexProgram(const SurfaceShader& s, PassKind kind, const Interpolators& in) {
    std::string o;
    // The _ST vectors TRANSFORM_TEX reads, unless the shader declares them.
    for (const InputMember* m : in.uvs) {
        const std::string st = m->texture + "_ST";
        if (!s.identifiers.count(st) && o.find("float4 " + st + ";") == std::string::npos)
            o += "float4 " + st + ";\n";
    }
    // The alphatest: cutoff, which Unity's generator declares too.
    if (s.directive.alpha_test && !s.identifiers.count(s.directive.alpha_test->text))
        o += "fixed " + s.directive.alpha_test->text + ";\n";
    o += "\nv2f_surf vert_surf(" + s.vertex_input.type + " v) {\n";
    if (s.vertex_input.instance_id)
        o += "    UNITY_SETUP_INSTANCE_ID(v);\n";
    o += "    v2f_surf o;\n    UNITY_INITIALIZE_OUTPUT(v2f_surf, o);\n";
    if (s.vertex_input.instance_id)
        o += "    UNITY_TRANSFER_INSTANCE_ID(v, o);\n";
    if (s.directive.vertex) {
        if (s.vertex_fills_input) {
            o += "    " + s.input.name + " customInputData;\n";
            o += "    UNITY_INITIALIZE_OUTPUT(" + s.input.name + ", customInputData);\n";
            o += "    " + s.directive.vertex->text + "(v, customInputData);\n";
        } else {
            o += "    " + s.directive.vertex->text + "(v);\n";
        }
    }
    o += Locals(s, in);
    const std::string vertex = "vin_vertex";
    if (kind == PassKind::kMeta) {
        o += "    o.pos = UnityMetaVertexPosition(" + vertex + ", " + UvSource(1) + ", " +
             UvSource(2) + ", unity_LightmapST, unity_DynamicLightmapST);\n";
    } else if (kind != PassKind::kShadowCaster) {
        o += "    o.pos = UnityObjectToClipPos(" + vertex + ");\n";
    }
    for (const InputMember* m : in.uvs) {
        o += "    o." + PackName(*m) + " = TRANSFORM_TEX(" + UvSource(m->uv_set) + ", " +
             m->texture + ");\n";
    }
    for (const InputMember* m : in.custom) {
        const bool fog = m->semantic == "FOG";
        o += Guarded(*m, std::string(fog ? kFogOn : "") + "    o." + PackName(*m) +
                             " = customInputData." + m->name + ";\n" + (fog ? "#endif\n" : ""));
    }
    o += "    float3 worldPos = mul(unity_ObjectToWorld, " + vertex + ").xyz;\n";
    o += "    float3 worldNormal = UnityObjectToWorldNormal(vin_normal);\n";
    if (s.tangent_space) {
        o += "    fixed3 worldTangent = UnityObjectToWorldDir(vin_tangent.xyz);\n";
        o += "    fixed tangentSign = vin_tangent.w * unity_WorldTransformParams.w;\n";
        o += "    fixed3 worldBinormal = cross(worldNormal, worldTangent) * tangentSign;\n";
        const char* axes = "xyz";
        for (int i = 0; i < 3; ++i) {
            const std::string c(1, axes[i]);
            o += "    o.tSpace" + std::to_string(i) + " = float4(worldTangent." + c +
                 ", worldBinormal." + c + ", worldNormal." + c + ", worldPos." + c + ");\n";
        }
    } else {
        o += "    o.worldNormal = worldNormal;\n    o.worldPos = worldPos;\n";
    }
    if (in.screen_pos) {
        o += kind == PassKind::kForwardBase || kind == PassKind::kForwardAdd ||
                     kind == PassKind::kDeferred
                 ? "    o.screenPos = ComputeScreenPos(o.pos);\n"
                 : "    o.screenPos = ComputeScreenPos(UnityObjectToClipPos(" + vertex + "));\n";
    }
    if (in.color)
        o += "    o.color = vin_color;\n";
    if (in.ambient) {
        o += "#ifdef DYNAMICLIGHTMAP_ON\n    o.lmap.zw = " + UvSource(2) +
             " * unity_DynamicLightmapST.xy + unity_DynamicLightmapST.zw;\n#endif\n";
        o += "#ifdef LIGHTMAP_ON\n    o.lmap.xy = " + UvSource(1) +
             " * unity_LightmapST.xy + unity_LightmapST.zw;\n#endif\n";
        o += "#ifndef LIGHTMAP_ON\n#if UNITY_SHOULD_SAMPLE_SH\n    o.sh = 0;\n";
        if (kind == PassKind::kForwardBase && !s.directive.Has("novertexlights")) {
            o += "#ifdef VERTEXLIGHT_ON\n"
                 "    o.sh += Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, "
                 "unity_4LightPosZ0, unity_LightColor[0].rgb, unity_LightColor[1].rgb, "
                 "unity_LightColor[2].rgb, unity_LightColor[3].rgb, unity_4LightAtten0, "
                 "worldPos, worldNormal);\n#endif\n";
        }
        if (!s.directive.Has("noambient"))
            o += "    o.sh = ShadeSHPerVertex(worldNormal, o.sh);\n";
        o += "#endif\n#endif\n";
    }
    if (in.lighting)
        o += "    UNITY_TRANSFER_LIGHTING(o, " + UvSource(1) + ");\n";
    if (in.fog)
        o += "    UNITY_TRANSFER_FOG(o, o.pos);\n";
    if (kind == PassKind::kShadowCaster)
        o += "    TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)\n";
    return o + "    return o;\n}\n";
}

}  // namespace kiln::surface
