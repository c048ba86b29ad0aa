#include "driver/shader_passes.h"

#include <map>

#include "hlsl/fixed_function.h"
#include "kiln/pack/engine_names.h"
#include "kiln/pack/pass_id.h"
#include "program_scan.h"

namespace kiln::driver {
namespace {

using namespace kiln::shaderlab;
using pack::StateField;

void Merge(RenderState& into, const RenderState& inner) {
    auto over = [](auto& a, const auto& b) {
        if (b)
            a = b;
    };
    over(into.cull, inner.cull);
    over(into.ztest, inner.ztest);
    over(into.zwrite, inner.zwrite);
    over(into.zclip, inner.zclip);
    over(into.alpha_to_mask, inner.alpha_to_mask);
    over(into.conservative, inner.conservative);
    over(into.offset, inner.offset);
    over(into.stencil, inner.stencil);
    if (!inner.blend.empty())
        into.blend = inner.blend;
    if (!inner.blend_op.empty())
        into.blend_op = inner.blend_op;
    if (!inner.color_mask.empty())
        into.color_mask = inner.color_mask;
}

void AddTags(std::vector<PassTag>& out, const std::vector<Tag>& tags) {
    for (const Tag& t : tags) {
        bool present = false;
        for (const PassTag& o : out)
            present = present || o.key == t.key;
        if (!present)
            out.push_back({t.key, t.value});
    }
}

std::vector<StateSetting> Lower(const RenderState& s) {
    std::vector<StateSetting> out;
    auto simple = [&](const std::optional<SimpleState>& v, StateField f) {
        if (v)
            out.push_back({f, -1, v->value});
    };
    simple(s.cull, StateField::kCull);
    simple(s.ztest, StateField::kZTest);
    simple(s.zwrite, StateField::kZWrite);
    simple(s.zclip, StateField::kZClip);
    simple(s.alpha_to_mask, StateField::kAlphaToMask);
    simple(s.conservative, StateField::kConservative);
    if (s.offset) {
        out.push_back({StateField::kOffsetFactor, -1, s.offset->factor});
        out.push_back({StateField::kOffsetUnits, -1, s.offset->units});
    }
    for (const BlendState& b : s.blend) {
        if (b.off) {
            StateValue off;
            off.text = "Off";
            out.push_back({StateField::kBlendOff, b.target, off});
            continue;
        }
        out.push_back({StateField::kBlendSrc, b.target, b.src});
        out.push_back({StateField::kBlendDst, b.target, b.dst});
        if (b.src_alpha)
            out.push_back({StateField::kBlendSrcAlpha, b.target, *b.src_alpha});
        if (b.dst_alpha)
            out.push_back({StateField::kBlendDstAlpha, b.target, *b.dst_alpha});
    }
    for (const BlendOpState& b : s.blend_op) {
        out.push_back({StateField::kBlendOp, b.target, b.op});
        if (b.op_alpha)
            out.push_back({StateField::kBlendOpAlpha, b.target, *b.op_alpha});
    }
    for (const ColorMaskState& c : s.color_mask) {
        out.push_back({StateField::kColorMask, c.target, c.mask});
    }
    if (s.stencil) {
        static const std::map<std::string, std::vector<StateField>> kStencil = {
            {"Ref", {StateField::kStencilRef}},
            {"ReadMask", {StateField::kStencilReadMask}},
            {"WriteMask", {StateField::kStencilWriteMask}},
            {"Comp", {StateField::kStencilCompFront, StateField::kStencilCompBack}},
            {"Pass", {StateField::kStencilPassFront, StateField::kStencilPassBack}},
            {"Fail", {StateField::kStencilFailFront, StateField::kStencilFailBack}},
            {"ZFail", {StateField::kStencilZFailFront, StateField::kStencilZFailBack}},
            {"CompFront", {StateField::kStencilCompFront}},
            {"PassFront", {StateField::kStencilPassFront}},
            {"FailFront", {StateField::kStencilFailFront}},
            {"ZFailFront", {StateField::kStencilZFailFront}},
            {"CompBack", {StateField::kStencilCompBack}},
            {"PassBack", {StateField::kStencilPassBack}},
            {"FailBack", {StateField::kStencilFailBack}},
            {"ZFailBack", {StateField::kStencilZFailBack}},
        };
        for (const StencilEntry& e : s.stencil->entries) {
            auto it = kStencil.find(e.key);
            if (it == kStencil.end())
                continue;
            for (StateField f : it->second)
                out.push_back({f, -1, e.value});
        }
    }
    return out;
}

struct Walker {
    const std::string& file;
    DiagnosticList& diags;
    const std::vector<Property>& properties;
    std::vector<FlatPass> out;
    std::vector<const ProgramBlock*> includes;  // outer levels
    std::vector<const std::vector<Tag>*> outer_tags;
    RenderState state;
    FixedFunction fixed;  // outer levels' fixed-function settings
    int lod = 0;
    uint32_t subshader_index = 0;

    static void AddIncludes(std::vector<const ProgramBlock*>& to,
                            const std::vector<ProgramBlock>& blocks) {
        for (const ProgramBlock& b : blocks) {
            if (IsIncludeBlock(b.kind))
                to.push_back(&b);
        }
    }

    void SubShaderLevel(const SubShader& ss) {
        const auto saved_inc = includes;
        const RenderState saved_state = state;
        const FixedFunction saved_fixed = fixed;
        AddIncludes(includes, ss.programs);
        Merge(state, ss.state);
        hlsl::MergeFixedFunction(fixed, ss.fixed);
        const int ss_lod = ss.lod.value_or(lod);
        for (const PassEntry& entry : ss.passes) {
            if (const auto* use = std::get_if<UsePass>(&entry)) {
                FlatPass fp;
                fp.use_pass = use;
                fp.subshader = subshader_index;
                out.push_back(std::move(fp));
                continue;
            }
            if (const auto* grab = std::get_if<GrabPass>(&entry)) {
                FlatPass fp;
                fp.grab = grab;
                fp.subshader = subshader_index;
                fp.lod = ss_lod;
                AddTags(fp.tags, grab->tags);
                AddTags(fp.tags, ss.tags);
                for (auto it = outer_tags.rbegin(); it != outer_tags.rend(); ++it)
                    AddTags(fp.tags, **it);
                out.push_back(std::move(fp));
                continue;
            }
            const Pass& p = std::get<Pass>(entry);
            FlatPass fp;
            fp.pass = &p;
            fp.subshader = subshader_index;
            fp.lod = p.lod.value_or(ss_lod);
            fp.blocks = includes;
            AddIncludes(fp.blocks, p.programs);
            for (const ProgramBlock& b : p.programs) {
                if (!IsIncludeBlock(b.kind) && !fp.program)
                    fp.program = &b;
            }
            if (p.surface) {  // its blocks are all it compiles, in order
                fp.blocks.clear();
                for (const ProgramBlock& b : p.programs)
                    fp.blocks.push_back(&b);
                fp.program = fp.blocks.back();
                fp.blocks.pop_back();
            }
            if (!fp.program) {
                // A fixed-function pass: Unity generates its programs, and so does Kiln (without
                // the CGINCLUDE blocks, which belong to the hand-written programs).
                FixedFunction ff = fixed;
                hlsl::MergeFixedFunction(ff, p.fixed);
                auto block = std::make_shared<ProgramBlock>();
                block->kind = ProgramKind::kCgProgram;
                block->range = p.range;
                block->body_begin = p.range.begin;
                block->text = hlsl::FixedFunctionProgram(ff, properties);
                block->pragmas = ScanPragmas(block->text, block->body_begin);
                fp.generated = block;
                fp.program = block.get();
                fp.blocks.clear();
            }
            fp.blocks.push_back(fp.program);
            AddTags(fp.tags, p.tags);
            AddTags(fp.tags, ss.tags);
            for (auto it = outer_tags.rbegin(); it != outer_tags.rend(); ++it)
                AddTags(fp.tags, **it);
            RenderState ps = state;
            Merge(ps, p.state);
            fp.state = Lower(ps);
            out.push_back(std::move(fp));
        }
        ++subshader_index;
        includes = saved_inc;
        state = saved_state;
        fixed = saved_fixed;
    }

    void Entries(const std::vector<SubShaderEntry>& entries) {
        for (const SubShaderEntry& e : entries) {
            if (const auto* ss = std::get_if<SubShader>(&e)) {
                SubShaderLevel(*ss);
                continue;
            }
            const Category& cat = *std::get<std::unique_ptr<Category>>(e);
            const auto saved_inc = includes;
            const RenderState saved_state = state;
            const FixedFunction saved_fixed = fixed;
            const int saved_lod = lod;
            AddIncludes(includes, cat.programs);
            Merge(state, cat.state);
            hlsl::MergeFixedFunction(fixed, cat.fixed);
            lod = cat.lod.value_or(lod);
            outer_tags.push_back(&cat.tags);
            Entries(cat.children);
            outer_tags.pop_back();
            includes = saved_inc;
            state = saved_state;
            fixed = saved_fixed;
            lod = saved_lod;
        }
    }
};

}  // namespace

std::vector<FlatPass> FlattenPasses(const Shader& shader,
                                    const std::string& file,
                                    DiagnosticList& diags) {
    Walker w{file, diags, shader.properties, {}, {}, {}, {}, {}, 0, 0};
    Walker::AddIncludes(w.includes, shader.programs);
    w.Entries(shader.subshaders);
    LabelPasses(w.out);
    return std::move(w.out);
}

void LabelPasses(std::vector<FlatPass>& passes) {
    // Each pass's one name (kiln/pack/pass_id.h), as the runtime computes it from the pack.
    bool several = false;
    for (const FlatPass& fp : passes)
        several = several || fp.subshader != passes.front().subshader;
    for (size_t i = 0; i < passes.size(); ++i) {
        FlatPass& fp = passes[i];
        if (fp.pass == nullptr && fp.grab == nullptr)
            continue;  // a UsePass not resolved yet
        uint32_t index = 0;
        for (size_t j = 0; j < i; ++j)
            index += passes[j].subshader == fp.subshader;
        fp.light_mode = TagValue(fp, pack::kTagLightMode);
        const std::string& name = fp.pass ? fp.pass->name : fp.grab->name;
        fp.label = pack::PassId({name, fp.light_mode, fp.subshader, index, several});
    }
}

std::string TagValue(const FlatPass& pass, const std::string& key) {
    for (const PassTag& t : pass.tags) {
        if (t.key == key)
            return t.value;
    }
    return "";
}

uint64_t VariantBudget(const FlatPass& pass,
                       uint64_t max_variants,
                       const std::string& file,
                       DiagnosticList& diags) {
    const std::string text = TagValue(pass, kTagMaxVariants);
    if (text.empty())
        return max_variants;
    uint64_t budget = 0;
    const bool digits =
        text.size() <= 18 && text.find_first_not_of("0123456789") == std::string::npos;
    if (digits)
        budget = std::stoull(text);
    if (!digits || budget == 0) {
        diags.Error(DiagCode::kBadVariantBudget, file, pass.pass->range,
                    "tag \"" + std::string(kTagMaxVariants) + "\" = \"" + text + "\" of pass \"" +
                        pass.label + "\" is not a positive number of variants");
        return max_variants;
    }
    return std::min(budget, max_variants);
}

}  // namespace kiln::driver
