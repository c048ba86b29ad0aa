// kiln lint's property-keywords check (K7009, K7010: Properties and keywords that do not meet) and
// pass-state check (K7011: render state the pass's LightMode or Queue contradicts).
#include <set>

#include "checks/check_functions.h"
#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"
#include "kiln/pack/property_keywords.h"
#include "kiln/pack/render_state.h"

namespace kiln::checks {
namespace {

using driver::CompileState;
using driver::FlatPass;
using driver::PassUnit;
using driver::ShaderUnit;

std::set<std::string> DeclaredKeywords(const CompileState& st, size_t s) {
    std::set<std::string> out;
    for (const PassUnit& pu : st.passes) {
        if (pu.shader != s)
            continue;
        for (const variants::KeywordSet& set : pu.pragmas.sets)
            out.insert(set.keywords.begin(), set.keywords.end());
    }
    return out;
}

// K7009: a property switches a keyword no pass declares. K7010: a pass declares the keyword
// [Toggle] (or [ToggleOff]) on a property would switch, but the property has no such attribute.
void LintShaderPropertyKeywords(CompileState& st, size_t s) {
    const ShaderUnit& unit = st.shaders[s];
    const std::string& file = unit.file->path();
    const std::set<std::string> declared = DeclaredKeywords(st, s);
    for (const shaderlab::Property& prop : unit.ast->properties) {
        bool switches = false;
        for (const shaderlab::Attribute& a : prop.attributes) {
            const auto driven = pack::KeywordsDrivenBy(prop.name, a.name, a.raw_args);
            switches = switches || driven.kind != pack::PropertyKeywords::Kind::kNone;
            for (const std::string& k : driven.keywords) {
                if (declared.count(k))
                    continue;
                st.diags.Warning(DiagCode::kLintPropertyKeywordUndeclared, file, prop.name_range,
                                 "property '" + prop.name + "' ([" + a.name +
                                     "]) switches "
                                     "keyword '" +
                                     k +
                                     "', which no pass declares: the switch does "
                                     "nothing");
            }
        }
        if (switches)
            continue;
        for (const char* attribute : {"Toggle", "ToggleOff"}) {
            const auto would = pack::KeywordsDrivenBy(prop.name, attribute, "");
            if (!would.keywords.empty() && declared.count(would.keywords[0])) {
                st.diags.Warning(DiagCode::kLintKeywordWithoutToggle, file, prop.name_range,
                                 "a pass declares '" + would.keywords[0] + "', the keyword [" +
                                     attribute + "] on property '" + prop.name +
                                     "' would switch, but the property has no [" + attribute +
                                     "]: setting it does not switch the keyword");
            }
        }
    }
}

// Which state fields of a pass refer to a property (a material decides them: not checked).
std::set<pack::StateField> PropertyFields(const pack::Pack& pack, uint32_t pass) {
    std::set<pack::StateField> out;
    const pack::PassRec rec = pack.Pass(pass).value();
    for (uint32_t i = rec.first_state; i < rec.first_state + rec.state_count; ++i) {
        const auto s = pack.Get<pack::StateRec>(pack::SectionTag::kStates, i).value();
        if (pack::StateKind(s.kind) == pack::StateKind::kPropertyRef)
            out.insert(pack::StateField(s.field));
    }
    return out;
}

// K7011 for one pass: ForwardAdd without additive blending or writing depth, a transparent
// Queue writing depth, a Deferred pass that blends.
void LintOnePassState(CompileState& st, const PassUnit& pu, const pack::Pack& pack) {
    const ShaderUnit& unit = st.shaders[pu.shader];
    const FlatPass& fp = unit.passes[pu.flat];
    const auto shader = pack.FindShader(unit.ast->name);
    const auto pass = shader ? pack.FindPass(*shader, fp.label) : std::nullopt;
    if (!pass)
        return;
    const shaderlab::Shader& ast = *unit.ast;
    const auto defaults = [&](std::string_view name) -> std::optional<float> {
        for (const shaderlab::Property& p : ast.properties) {
            if (p.name == name && !p.default_value.empty())
                return static_cast<float>(p.default_value[0]);
        }
        return std::nullopt;
    };
    const Result<pack::PassState> state = pack::ResolvePassState(pack, *pass, defaults, {});
    if (!state)
        return;
    const std::set<pack::StateField> refs = PropertyFields(pack, *pass);
    const pack::PassState& s = state.value();
    const pack::BlendTargetState& blend = s.targets[0];
    const bool blend_by_material = refs.count(pack::StateField::kBlendSrc) ||
                                   refs.count(pack::StateField::kBlendDst) ||
                                   refs.count(pack::StateField::kBlendOff);
    const bool zwrite_by_material = refs.count(pack::StateField::kZWrite) > 0;
    const std::string& mode = fp.light_mode;
    const std::string name = "pass \"" + fp.label + "\"";
    std::vector<std::string> problems;
    if (mode == pack::kLightModeForwardAdd) {
        if (!blend_by_material && !blend.enable) {
            problems.push_back(name +
                               " (LightMode ForwardAdd) has no Blend: each light's pass "
                               "replaces what the lights before it drew; add Blend One One");
        } else if (!blend_by_material &&
                   (blend.dst != pack::BlendFactor::kOne || blend.op != pack::BlendOp::kAdd)) {
            problems.push_back(name +
                               " (LightMode ForwardAdd) blends, but not additively: the "
                               "lights do not add up; use Blend One One");
        }
        if (!zwrite_by_material && s.zwrite) {
            problems.push_back(name +
                               " (LightMode ForwardAdd) writes depth (ZWrite is On unless "
                               "set): the base pass wrote it already; add ZWrite Off");
        }
    }
    const std::optional<int> queue = pack::RenderQueue(TagValue(fp, pack::kTagQueue));
    // (ForwardAdd's own depth-write check above covers it.)
    const bool color_pass =
        mode.empty() || mode == pack::kLightModeAlways || mode == pack::kLightModeForwardBase;
    if (queue && *queue > pack::kRenderQueueTransparentAbove && color_pass && !zwrite_by_material &&
        s.zwrite) {
        problems.push_back(name + " is in the transparent queue (" + TagValue(fp, pack::kTagQueue) +
                           ") but writes depth (ZWrite is On unless set): objects behind it are "
                           "hidden instead of blended; add ZWrite Off");
    }
    if (mode == pack::kLightModeDeferred && !blend_by_material && blend.enable) {
        problems.push_back(name +
                           " (LightMode Deferred) blends: G-buffer values are data, and a "
                           "blended normal or smoothness is no surface; use Blend Off");
    }
    // A surface shader's generated pass has the state Unity's generator gives it (decal:add's
    // DEFERRED pass adds into the G-buffer by design): nothing the user wrote.
    if (fp.pass->surface)
        return;
    for (const std::string& p : problems)
        st.diags.Warning(DiagCode::kLintStateContradictsPass, unit.file->path(), fp.pass->range, p);
}

}  // namespace

void LintPropertyKeywords(Inputs& in) {
    for (size_t s = 0; s < in.st->shaders.size(); ++s) {
        if (in.st->shaders[s].ast)
            LintShaderPropertyKeywords(*in.st, s);
    }
}

void LintPassState(Inputs& in) {
    for (const PassUnit& pu : in.st->passes)
        LintOnePassState(*in.st, pu, *in.pack);
}

}  // namespace kiln::checks
