// The late phases of a compile: bindings + reflection + validation per module, and the pack
// itself (the checks over the reflection are in checks/).
#include <algorithm>
#include <set>

#include "driver/compile_state.h"
#include "driver/isolation.h"
#include "driver/parallel.h"
#include "kiln/pack/engine_names.h"
#include "kiln/pack/property_keywords.h"
#include "kiln/shaderlab/ast.h"
#include "pack/pack_builder.h"
#include "spirv/bindings.h"
#include "spirv/optimize.h"
#include "spirv/reflect.h"
#include "variants/alias_merge.h"

namespace kiln::driver {

using pack::Stage;

std::string VariantName(const CompileState& st, size_t p, pack::VariantKey key) {
    const PassUnit& pu = st.passes[p];
    const ShaderUnit& unit = st.shaders[pu.shader];
    return "shader \"" + unit.ast->name + "\" pass \"" + unit.passes[pu.flat].label +
           "\", variant " +
           pack::JoinKeywords(variants::EnabledKeywords(pu.pragmas.sets, pu.expansion.layout, key));
}

const FinalModule& FinalFor(const CompileState& st, size_t p, size_t task) {
    return st.finals[p].at(st.tasks[task].job);
}

void FinishModules(CompileState& st) {
    st.finals.assign(st.passes.size(), {});
    std::vector<std::pair<size_t, size_t>> work;  // (pass, job)
    std::vector<std::map<std::string, spirv::Binding>> tables(st.passes.size());
    for (size_t p = 0; p < st.passes.size(); ++p) {
        std::set<size_t> jobs;
        for (size_t t : st.passes[p].tasks)
            jobs.insert(st.tasks[t].job);
        std::set<spirv::DescriptorVar> used;
        for (size_t j : jobs) {
            for (const auto& d : spirv::ListDescriptorVars(st.jobs[j].words))
                used.insert(d);
        }
        std::vector<std::string> texture_props;
        for (const auto& prop : st.shaders[st.passes[p].shader].ast->properties) {
            if (shaderlab::IsTextureType(prop.type))
                texture_props.push_back(prop.name);
        }
        tables[p] = spirv::AssignBindings(used, texture_props);
        for (size_t j : jobs) {
            st.finals[p][j];  // create the slot before threads start
            work.push_back({p, j});
        }
    }
    ParallelFor(work.size(), st.options.jobs, [&](size_t i) {
        const auto [p, j] = work[i];
        FinalModule& fm = st.finals[p][j];
        fm.words = st.jobs[j].words;
        if (Status bound = spirv::ApplyBindings(fm.words, tables[p]); !bound.ok()) {
            fm.error = bound.error().message;
            fm.internal = true;
            return;
        }
        Result<spirv::Reflection> reflected = spirv::Reflect(fm.words);
        if (!reflected) {
            fm.error = reflected.error().message;
            fm.internal = true;
            return;
        }
        fm.reflection = std::move(reflected).value();
        // Stripping and spirv-val run in a worker, as every third-party step does.
        const StageTask& task = st.tasks[st.jobs[j].first_task];
        worker::Request request = StageRequest(st, task, worker::RequestKind::kFinish);
        request.words = std::move(fm.words);
        worker::Outcome o = st.exec->Run(request);
        if ((fm.failure = OutcomeDiagnostic(st, task, o)))
            return;
        if (!o.response.ok) {
            fm.internal = o.response.failed_in != worker::Component::kSpirvVal;
            fm.error = fm.internal ? o.response.messages
                                   : "generated SPIR-V fails validation: " + o.response.messages;
            return;
        }
        fm.words = std::move(o.response.words);
        fm.ok = true;
    });
    for (Job& job : st.jobs)
        std::vector<uint32_t>().swap(job.words);  // every pass's final modules hold theirs
    for (size_t p = 0; p < st.passes.size(); ++p) {
        const PassUnit& pu = st.passes[p];
        const ShaderUnit& unit = st.shaders[pu.shader];
        for (const auto& [j, fm] : st.finals[p]) {
            if (fm.ok)
                continue;
            if (fm.failure) {
                Diagnostic& d =
                    st.diags.Add(fm.failure->severity, fm.failure->code, fm.failure->file,
                                 fm.failure->range, fm.failure->message);
                d.notes = fm.failure->notes;
                continue;
            }
            const StageTask& t = st.tasks[st.jobs[j].first_task];
            st.diags.Add(fm.internal ? Severity::kInternal : Severity::kError,
                         fm.internal ? DiagCode::kInternalError : DiagCode::kSpirvInvalid,
                         unit.file->path(), unit.passes[pu.flat].program->range,
                         fm.error + " (" + VariantName(st, p, t.key) + ", " +
                             pack::StageName(t.stage) + " stage)");
        }
    }
}

namespace {

// A shader's passes in source order: each a compiled pass (its index into st.passes) or, with
// none, a GrabPass.
std::vector<std::pair<size_t, std::optional<size_t>>> PassOrder(const CompileState& st, size_t s) {
    std::vector<std::pair<size_t, std::optional<size_t>>> out;
    const std::vector<FlatPass>& flats = st.shaders[s].passes;
    size_t p = 0;
    for (size_t f = 0; f < flats.size(); ++f) {
        while (p < st.passes.size() &&
               (st.passes[p].shader < s || (st.passes[p].shader == s && st.passes[p].flat < f)))
            ++p;
        if (p < st.passes.size() && st.passes[p].shader == s && st.passes[p].flat == f)
            out.emplace_back(f, p);
        else if (flats[f].grab)
            out.emplace_back(f, std::nullopt);
    }
    return out;
}

void AddTags(pack_builder::PackBuilder& b, const FlatPass& fp, pack::PassRec& rec) {
    rec.first_tag = static_cast<uint32_t>(b.tags.size());
    for (const PassTag& t : fp.tags)
        b.tags.push_back({b.Str(t.key), b.Str(t.value)});
    rec.tag_count = static_cast<uint32_t>(fp.tags.size());
}

// A GrabPass: its name, tags and texture; no state, keyword sets or variants.
void EmitGrabPass(pack_builder::PackBuilder& b, const FlatPass& fp, uint32_t shader) {
    pack::PassRec rec;
    rec.name = b.Str(fp.grab->name);
    rec.shader = shader;
    rec.subshader = fp.subshader;
    rec.lod = static_cast<uint32_t>(std::max(0, fp.lod));
    AddTags(b, fp, rec);
    rec.first_state = static_cast<uint32_t>(b.states.size());
    rec.first_keyword_set = static_cast<uint32_t>(b.keyword_sets.size());
    rec.first_variant = static_cast<uint32_t>(b.variants.size());
    rec.flags = pack::kPassGrab;
    b.grabs.push_back({static_cast<uint32_t>(b.passes.size()), b.Str(fp.grab->texture_name), 0});
    b.passes.push_back(rec);
}

}  // namespace

std::vector<uint8_t> EmitPack(CompileState& st, CompileStats& stats) {
    pack_builder::PackBuilder b;
    for (size_t s = 0; s < st.shaders.size(); ++s) {
        const ShaderUnit& unit = st.shaders[s];
        if (!unit.emit)
            continue;  // a stripped compile leaves it out
        const shaderlab::Shader& ast = *unit.ast;
        pack::ShaderRec sr;
        sr.name = b.Str(ast.name);
        sr.fallback = b.Str(ast.fallback && !ast.fallback->off ? ast.fallback->name : "");
        sr.first_property = static_cast<uint32_t>(b.properties.size());
        for (const shaderlab::Property& prop : ast.properties) {
            pack::PropertyRec pr;
            pr.name = b.Str(prop.name);
            pr.display_name = b.Str(prop.display_name);
            pr.type = uint32_t(prop.type);
            pr.range_min = static_cast<float>(prop.range_min);
            pr.range_max = static_cast<float>(prop.range_max);
            for (size_t i = 0; i < 4 && i < prop.default_value.size(); ++i) {
                pr.default_value[i] = static_cast<float>(prop.default_value[i]);
            }
            pr.texture_default = b.Str(prop.default_texture);
            pr.first_attribute = static_cast<uint32_t>(b.attributes.size());
            for (const shaderlab::Attribute& a : prop.attributes) {
                b.attributes.push_back({b.Str(a.name), b.Str(a.raw_args)});
            }
            pr.attribute_count = static_cast<uint32_t>(prop.attributes.size());
            b.properties.push_back(pr);
        }
        sr.property_count = static_cast<uint32_t>(ast.properties.size());
        sr.first_pass = static_cast<uint32_t>(b.passes.size());
        for (const auto& [flat, compiled] : PassOrder(st, s)) {
            if (!compiled) {
                EmitGrabPass(b, unit.passes[flat], static_cast<uint32_t>(b.shaders.size()));
                continue;
            }
            const size_t p = *compiled;
            const PassUnit& pu = st.passes[p];
            const FlatPass& fp = unit.passes[pu.flat];
            pack::PassRec rec;
            rec.name = b.Str(fp.pass->name);
            rec.shader = static_cast<uint32_t>(b.shaders.size());
            rec.subshader = fp.subshader;
            rec.lod = static_cast<uint32_t>(std::max(0, fp.lod));
            AddTags(b, fp, rec);
            rec.first_state = static_cast<uint32_t>(b.states.size());
            for (const StateSetting& ss : fp.state) {
                pack::StateRec r;
                r.field = uint32_t(ss.field);
                r.target = ss.target;
                r.kind = uint32_t(ss.value.kind);
                r.number = static_cast<float>(ss.value.number);
                r.text = b.Str(ss.value.text);
                b.states.push_back(r);
            }
            rec.state_count = static_cast<uint32_t>(fp.state.size());
            rec.first_keyword_set = static_cast<uint32_t>(b.keyword_sets.size());
            for (size_t k = 0; k < pu.pragmas.sets.size(); ++k) {
                const auto& set = pu.pragmas.sets[k];
                pack::KeywordSetRec kr;
                kr.kind = uint32_t(set.kind);
                kr.flags = set.flags;
                kr.first_keyword = static_cast<uint32_t>(b.keywords.size());
                for (const std::string& kw : set.keywords)
                    b.keywords.push_back(b.Str(kw));
                kr.keyword_count = static_cast<uint32_t>(set.keywords.size());
                kr.key_shift = pu.expansion.layout[k].shift;
                kr.key_bits = pu.expansion.layout[k].bits;
                b.keyword_sets.push_back(kr);
            }
            rec.keyword_set_count = static_cast<uint32_t>(pu.pragmas.sets.size());
            if (!pu.pragmas.only_renderers.empty())
                rec.flags |= pack::kPassOnlyRenderers;
            if (!pu.pragmas.exclude_renderers.empty())
                rec.flags |= pack::kPassExcludeRenderers;
            rec.first_variant = static_cast<uint32_t>(b.variants.size());
            const uint32_t pass_index = static_cast<uint32_t>(b.passes.size());
            std::vector<pack::VariantRec> pass_variants;
            for (size_t v = 0; v < pu.expansion.keys.size(); ++v) {
                const FinalModule& vs = FinalFor(st, p, pu.TaskOf(v, 0));
                const FinalModule& fs = FinalFor(st, p, pu.TaskOf(v, 1));
                pack::VariantRec vr;
                vr.pass = pass_index;
                vr.key = pu.expansion.keys[v].bits();
                vr.vertex_module = b.AddModule(Stage::kVertex, vs.words, vs.reflection);
                vr.fragment_module = b.AddModule(Stage::kFragment, fs.words, fs.reflection);
                pack::VariantStagesRec extra;
                const std::vector<Stage> stages = pu.pragmas.Stages();
                for (size_t slot = 2; slot < stages.size(); ++slot) {
                    const FinalModule& m = FinalFor(st, p, pu.TaskOf(v, slot));
                    const uint32_t index = b.AddModule(stages[slot], m.words, m.reflection);
                    (stages[slot] == Stage::kGeometry      ? extra.geometry_module
                     : stages[slot] == Stage::kTessControl ? extra.tess_control_module
                                                           : extra.tess_eval_module) = index;
                }
                vr.stages = b.AddStages(extra);
                pass_variants.push_back(vr);
            }
            std::vector<variants::KeywordAlias> aliases;
            if (st.options.keyword_aliases) {
                aliases = variants::MergeRedundantKeywords(pu.pragmas.sets, pu.expansion.layout,
                                                           pass_variants);
            }
            for (const variants::KeywordAlias& a : aliases) {
                b.aliases.push_back(
                    {rec.first_keyword_set + static_cast<uint32_t>(a.set), a.from, a.to, 0});
                st.aliases.push_back({p, a});
            }
            stats.aliased_variants += pu.expansion.keys.size() - pass_variants.size();
            b.variants.insert(b.variants.end(), pass_variants.begin(), pass_variants.end());
            rec.variant_count = static_cast<uint32_t>(pass_variants.size());
            b.passes.push_back(rec);
        }
        sr.pass_count = static_cast<uint32_t>(b.passes.size()) - sr.first_pass;
        b.shaders.push_back(sr);
    }
    pack::MetaRec meta;
    meta.producer = b.Str(ProducerVersion());
    meta.opt_level = st.options.opt_level == OptimizationLevel::kNone   ? 0
                     : st.options.opt_level == OptimizationLevel::kSize ? 2
                                                                        : 1;
    meta.flags = (st.options.debug_info ? pack::kMetaDebugInfo : 0u) |
                 (st.options.precision == Precision::kRelaxed ? pack::kMetaRelaxedPrecision : 0u) |
                 (st.options.precision == Precision::kHalf ? pack::kMetaHalfPrecision : 0u);
    stats.modules = b.module_count();

    return b.Finish(meta);
}

}  // namespace kiln::driver
