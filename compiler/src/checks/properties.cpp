// The properties check (K5005, K5006, K5008): each shader's Properties against the globals and
// resources its variants declare, over every variant of every pass.
#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "checks/check_functions.h"
#include "kiln/pack/engine_names.h"
#include "kiln/pack/property_keywords.h"
#include "spirv/bindings.h"

namespace kiln::checks {
namespace {

using driver::CompileState;
using driver::FlatPass;
using driver::ShaderUnit;

// What one shader's variants declare, by name.
struct Reflected {
    std::map<std::string, const spirv::BlockMember*> members;  // of the material block
    std::map<std::string, const spirv::Resource*> resources;
};

// False when the shader has no compiled pass.
bool Collect(const CompileState& st, size_t s, Reflected& out) {
    bool any_pass = false;
    for (size_t p = 0; p < st.passes.size(); ++p) {
        if (st.passes[p].shader != s)
            continue;
        any_pass = true;
        for (const auto& [j, fm] : st.finals[p]) {
            for (const auto& b : fm.reflection.blocks) {
                if (b.kind != pack::BlockKind::kUniform || b.set != spirv::kMaterialSet)
                    continue;
                for (const auto& m : b.members)
                    out.members.emplace(m.name, &m);
            }
            for (const auto& r : fm.reflection.resources)
                out.resources.emplace(r.name, &r);
        }
    }
    return any_pass;
}

// A property only the unbuilt shader_feature combinations use is not unused: K5005 needs every
// combination (--all-features, or a shader without shader_feature sets), and no stripping (a
// stripped compile builds what one scene needs; other variants may read it).
bool EveryFeatureBuilt(const CompileState& st, size_t s) {
    if (st.options.requests)
        return false;
    if (st.options.all_features)
        return true;
    for (const driver::PassUnit& pu : st.passes) {
        for (const auto& set : pu.pragmas.sets) {
            if (pu.shader == s && set.kind == pack::KeywordSetKind::kShaderFeature)
                return false;
        }
    }
    return true;
}

// Properties render state reads (`Cull [_Cull]`, `Blend [_SrcBlend] [_DstBlend]`) are used.
std::set<std::string> StateRefs(const ShaderUnit& unit) {
    std::set<std::string> refs;
    for (const FlatPass& fp : unit.passes) {
        for (const driver::StateSetting& setting : fp.state) {
            if (setting.value.kind == shaderlab::StateValue::Kind::kPropertyRef)
                refs.insert(setting.value.text);
        }
    }
    return refs;
}

// A [Toggle]/[ToggleOff]/[KeywordEnum] property is a keyword switch; Unity's shaders rarely read
// its value.
bool SwitchOnly(const shaderlab::Property& prop) {
    return std::any_of(prop.attributes.begin(), prop.attributes.end(), [&](const auto& a) {
        return pack::KeywordsDrivenBy(prop.name, a.name, a.raw_args).kind !=
               pack::PropertyKeywords::Kind::kNone;
    });
}

// What the shader should declare `prop` as, when what it declares does not fit; else "".
std::string WantedType(const shaderlab::Property& prop, const spirv::BlockMember* mem) {
    using PT = shaderlab::PropertyType;
    const bool texture = shaderlab::IsTextureType(prop.type);
    if (mem == nullptr)
        return texture ? "" : "a uniform value, not a texture or sampler";
    if ((prop.type == PT::kColor || prop.type == PT::kVector) &&
        (mem->vecsize != 4 || mem->columns > 1))
        return "a 4-component vector";
    if ((prop.type == PT::kFloat || prop.type == PT::kRange || prop.type == PT::kInt ||
         prop.type == PT::kInteger) &&
        (mem->vecsize != 1 || mem->columns > 1))
        return "a scalar";
    return texture ? "a texture" : "";
}

// Globals the runtime fills (kiln/pack/engine_names.h, and the texel size of a named GrabPass's
// texture) are not material properties; any other global not declared is K5006.
void CheckGlobals(CompileState& st,
                  const ShaderUnit& unit,
                  const Reflected& r,
                  const std::set<std::string>& declared) {
    std::set<std::string> grabbed;
    for (const FlatPass& fp : unit.passes) {
        if (fp.grab && !fp.grab->texture_name.empty())
            grabbed.insert(fp.grab->texture_name + "_TexelSize");
    }
    for (const auto& [name, mem] : r.members) {
        if (declared.count(name) || pack::IsEngineGlobal(name) || grabbed.count(name))
            continue;
        st.diags.Warning(
            DiagCode::kGlobalNotAProperty, unit.file->path(), unit.ast->name_range,
            "shader global '" + name + "' is not in Properties; materials cannot set it");
    }
}

void CheckShader(CompileState& st, size_t s) {
    const ShaderUnit& unit = st.shaders[s];
    Reflected r;
    if (!unit.ast || !Collect(st, s, r))
        return;
    const bool every_feature_built = EveryFeatureBuilt(st, s);
    const std::set<std::string> state_refs = StateRefs(unit);
    const std::string& file = unit.file->path();
    std::set<std::string> declared;
    for (const shaderlab::Property& prop : unit.ast->properties) {
        declared.insert(prop.name);
        if (shaderlab::IsTextureType(prop.type)) {
            for (const char* suffix : {"_ST", "_TexelSize", "_HDR"})
                declared.insert(prop.name + suffix);
        }
        const auto m = r.members.find(prop.name);
        if (m == r.members.end() && !r.resources.count(prop.name)) {
            if (every_feature_built && !SwitchOnly(prop) && !state_refs.count(prop.name)) {
                st.diags.Warning(
                    DiagCode::kPropertyUnused, file, prop.name_range,
                    "property '" + prop.name + "' has no shader variable of that name in any pass");
            }
            continue;
        }
        const std::string want = WantedType(prop, m == r.members.end() ? nullptr : m->second);
        if (!want.empty()) {
            st.diags.Warning(DiagCode::kPropertyTypeMismatch, file, prop.type_range,
                             "property '" + prop.name + "' is a " +
                                 shaderlab::PropertyTypeName(prop.type) +
                                 " but the shader does not declare it as " + want);
        }
    }
    CheckGlobals(st, unit, r, declared);
}

}  // namespace

void CheckProperties(Inputs& in) {
    for (size_t s = 0; s < in.st->shaders.size(); ++s)
        CheckShader(*in.st, s);
}

}  // namespace kiln::checks
