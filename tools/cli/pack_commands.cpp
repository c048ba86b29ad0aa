// kiln info PACK [--json] and kiln extract PACK --shader S --pass P --stage STAGE -o x.spv.
#include <algorithm>
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "kiln/base/files.h"
#include "kiln/base/text.h"
#include "kiln/pack/engine_names.h"
#include "kiln/pack/names.h"
#include "kiln/pack/pass_id.h"
#include "kiln/pack/reader.h"
#include "kiln/pack/render_state.h"

namespace kiln::cli {

using namespace kiln::pack;

bool OpenPack(const std::string& path, MappedFile& file, Pack& pack, const GlobalOptions& global) {
    Result<MappedFile> mapped = MappedFile::Map(path);
    if (!mapped) {
        ReportError(global, mapped.error().code, path, mapped.error().message);
        return false;
    }
    file = std::move(mapped).value();
    Result<Pack> opened = Pack::Open(file.bytes());
    if (!opened) {
        ReportError(global, opened.error().code, path, opened.error().message);
        return false;
    }
    pack = std::move(opened).value();
    return true;
}

namespace {

// Pack strings are bytes from a file: every string and key of a description is escaped as
// diagnostics escape text (\xNN for control bytes and invalid UTF-8), so the JSON never throws
// and the text and JSON forms show the same.
nlohmann::json Printable(const nlohmann::json& j) {
    if (j.is_string())
        return base::EscapeForTerminal(j.get_ref<const std::string&>());
    if (j.is_array()) {
        nlohmann::json out = nlohmann::json::array();
        for (const auto& e : j)
            out.push_back(Printable(e));
        return out;
    }
    if (j.is_object()) {
        nlohmann::json out = nlohmann::json::object();
        for (const auto& [k, v] : j.items())
            out[base::EscapeForTerminal(k)] = Printable(v);
        return out;
    }
    return j;
}

nlohmann::json InfoJson(const Pack& p) {
    nlohmann::json shaders = nlohmann::json::array();
    for (uint32_t s = 0; s < p.Count(SectionTag::kShaders); ++s) {
        const ShaderRec sr = p.Shader(s).value();
        nlohmann::json props = nlohmann::json::array();
        for (uint32_t i = sr.first_property; i < sr.first_property + sr.property_count; ++i) {
            const auto pr = p.Get<PropertyRec>(SectionTag::kProperties, i).value();
            props.push_back({{"name", p.String(pr.name)},
                             {"type", pr.type},
                             {"default", pr.default_value},
                             {"texture_default", p.String(pr.texture_default)}});
        }
        nlohmann::json passes = nlohmann::json::array();
        for (uint32_t i = sr.first_pass; i < sr.first_pass + sr.pass_count; ++i) {
            const PassRec pr = p.Pass(i).value();
            nlohmann::json tags = nlohmann::json::object();
            for (uint32_t t = pr.first_tag; t < pr.first_tag + pr.tag_count; ++t) {
                const auto tag = p.Get<TagRec>(SectionTag::kTags, t).value();
                tags[std::string(p.String(tag.key))] = p.String(tag.value);
            }
            nlohmann::json state = nlohmann::json::array();
            for (uint32_t t = pr.first_state; t < pr.first_state + pr.state_count; ++t) {
                const auto st = p.Get<StateRec>(SectionTag::kStates, t).value();
                nlohmann::json e = {{"field", pack::StateFieldName(pack::StateField(st.field))},
                                    {"target", st.target}};
                if (st.kind == uint32_t(StateKind::kPropertyRef)) {
                    e["property"] = p.String(st.text);
                } else if (st.kind == uint32_t(StateKind::kNumber)) {
                    e["value"] = st.number;
                } else {
                    e["value"] = p.String(st.text);
                }
                state.push_back(e);
            }
            nlohmann::json sets = nlohmann::json::array();
            for (uint32_t k = pr.first_keyword_set; k < pr.first_keyword_set + pr.keyword_set_count;
                 ++k) {
                const KeywordSetRec kr = p.KeywordSet(k).value();
                nlohmann::json words = nlohmann::json::array();
                for (uint32_t w = 0; w < kr.keyword_count; ++w) {
                    words.push_back(p.Keyword(kr.first_keyword + w).value());
                }
                nlohmann::json aliases = nlohmann::json::object();
                for (uint32_t w = 0; w < kr.keyword_count; ++w) {
                    if (const uint32_t to = p.AliasOf(k, w); to != w) {
                        aliases[std::string(p.Keyword(kr.first_keyword + w).value())] =
                            p.Keyword(kr.first_keyword + to).value();
                    }
                }
                sets.push_back({{"kind", kr.kind == 0 ? "multi_compile" : "shader_feature"},
                                {"keywords", words},
                                {"aliases", aliases},
                                {"shift", kr.key_shift},
                                {"bits", kr.key_bits}});
            }
            nlohmann::json variants = nlohmann::json::array();
            for (uint32_t v = pr.first_variant; v < pr.first_variant + pr.variant_count; ++v) {
                const VariantRec vr = p.Variant(v).value();
                nlohmann::json variant = {{"key", vr.key},
                                          {"keywords", p.KeywordsOf(i, VariantKey(vr.key))},
                                          {"vertex_module", vr.vertex_module},
                                          {"fragment_module", vr.fragment_module}};
                if (const Result<VariantStagesRec> st = p.Stages(vr); st && vr.stages != 0) {
                    const auto put = [&](const char* name, uint32_t m) {
                        if (m != kNoModule)
                            variant[name] = m;
                    };
                    put("geometry_module", st.value().geometry_module);
                    put("hull_module", st.value().tess_control_module);
                    put("domain_module", st.value().tess_eval_module);
                }
                variants.push_back(std::move(variant));
            }
            nlohmann::json pass = {{"pass", PassLabel(p, i)},
                                   {"name", p.String(pr.name)},
                                   {"subshader", pr.subshader},
                                   {"tags", tags},
                                   {"state", state},
                                   {"keyword_sets", sets},
                                   {"variants", variants}};
            if (const std::optional<std::string_view> grab = p.GrabTexture(i))
                pass["grab"] = grab->empty() ? std::string(kTextureGrab) : std::string(*grab);
            passes.push_back(std::move(pass));
        }
        shaders.push_back({{"name", p.String(sr.name)}, {"properties", props}, {"passes", passes}});
    }
    nlohmann::json modules = nlohmann::json::array();
    for (uint32_t m = 0; m < p.Count(SectionTag::kModules); ++m) {
        const ModuleRec mr = p.Module(m).value();
        nlohmann::json blocks = nlohmann::json::array();
        for (uint32_t b = mr.first_block; b < mr.first_block + mr.block_count; ++b) {
            const auto br = p.Get<BlockRec>(SectionTag::kBlocks, b).value();
            nlohmann::json members = nlohmann::json::array();
            for (uint32_t i = br.first_member; i < br.first_member + br.member_count; ++i) {
                const auto mem = p.Get<MemberRec>(SectionTag::kMembers, i).value();
                members.push_back(
                    {{"name", p.String(mem.name)}, {"offset", mem.offset}, {"size", mem.size}});
            }
            blocks.push_back({{"name", p.String(br.name)},
                              {"kind", br.kind == 0 ? "uniform" : "push_constant"},
                              {"set", br.set},
                              {"binding", br.binding},
                              {"size", br.size},
                              {"members", members}});
        }
        nlohmann::json resources = nlohmann::json::array();
        for (uint32_t r = mr.first_resource; r < mr.first_resource + mr.resource_count; ++r) {
            const auto rr = p.Get<ResourceRec>(SectionTag::kResources, r).value();
            resources.push_back({{"name", p.String(rr.name)},
                                 {"kind", rr.kind},
                                 {"set", rr.set},
                                 {"binding", rr.binding}});
        }
        nlohmann::json io = nlohmann::json::array();
        for (uint32_t i = mr.first_interface; i < mr.first_interface + mr.interface_count; ++i) {
            const auto v = p.Get<InterfaceVarRec>(SectionTag::kInterface, i).value();
            io.push_back({{"name", p.String(v.name)},
                          {"semantic", p.String(v.semantic)},
                          {"location", v.location},
                          {"direction", v.direction == 0 ? "in" : "out"},
                          {"vecsize", v.vecsize}});
        }
        modules.push_back({{"stage", pack::StageName(pack::Stage(mr.stage))},
                           {"bytes", mr.spirv_size},
                           {"interface", io},
                           {"blocks", blocks},
                           {"resources", resources}});
    }
    const MetaRec meta = p.meta();
    return {{"format", std::to_string(kFormatMajor) + "." + std::to_string(p.format_minor())},
            {"producer", p.String(meta.producer)},
            {"variants", meta.variant_count},
            {"precision", PrecisionName(PrecisionOf(meta.flags))},
            {"modules", modules},
            {"shaders", shaders}};
}

}  // namespace

std::function<int()> AddInfoCommand(CLI::App* cmd, const GlobalOptions& global) {
    struct Options {
        std::string file;
        bool json = false;
    };
    auto o = std::make_shared<Options>();
    cmd->add_option("pack", o->file, "A .kpack file")->required();
    cmd->add_flag("--json", o->json, "Print JSON");
    return [o, &global]() {
        MappedFile file;
        Pack pack;
        if (!OpenPack(o->file, file, pack, global))
            return int(kExitInputError);
        const nlohmann::json j = Printable(InfoJson(pack));
        if (o->json) {
            std::printf("%s\n", j.dump(2).c_str());
            return int(kExitOk);
        }
        size_t spirv = 0;
        for (const auto& m : j["modules"])
            spirv += m["bytes"].get<size_t>();
        std::printf("%s: kiln pack %s, %zu bytes, by %s\n", o->file.c_str(),
                    j["format"].get<std::string>().c_str(), file.bytes().size(),
                    j["producer"].get<std::string>().c_str());
        std::printf("%u variants, %zu unique modules (%zu bytes of SPIR-V), precision %s\n",
                    j["variants"].get<unsigned>(), j["modules"].size(), spirv,
                    j["precision"].get<std::string>().c_str());
        for (const auto& s : j["shaders"]) {
            std::printf("Shader \"%s\": %zu properties\n", s["name"].get<std::string>().c_str(),
                        s["properties"].size());
            for (const auto& p : s["passes"]) {
                if (p.contains("grab")) {
                    std::printf("  pass \"%s\": GrabPass into %s\n",
                                p["pass"].get<std::string>().c_str(),
                                p["grab"].get<std::string>().c_str());
                    continue;
                }
                std::string sets;
                for (const auto& k : p["keyword_sets"]) {
                    std::string words;
                    auto shown = [](const std::string& kw) { return kw.empty() ? "_" : kw; };
                    for (const auto& w : k["keywords"]) {
                        const std::string kw = w.get<std::string>();
                        words += (words.empty() ? "" : " ") + shown(kw);
                        if (k["aliases"].contains(kw))  // BAZ=_: BAZ finds _'s variants
                            words += "=" + shown(k["aliases"][kw].get<std::string>());
                    }
                    sets += " [" + words + "]";
                }
                std::printf(
                    "  pass \"%s\"%s: %zu variants%s\n", p["pass"].get<std::string>().c_str(),
                    p["tags"].contains("LightMode")
                        ? (" (LightMode " + p["tags"]["LightMode"].get<std::string>() + ")").c_str()
                        : "",
                    p["variants"].size(), sets.c_str());
            }
        }
        return int(kExitOk);
    };
}

// The shader names of a pack, for suggestions.
std::vector<std::string> ShaderNames(const Pack& pack) {
    std::vector<std::string> names;
    for (uint32_t s = 0; s < pack.Count(SectionTag::kShaders); ++s)
        names.emplace_back(pack.String(pack.Shader(s).value().name));
    return names;
}

// A shader's pass labels, Names and LightMode tags, for suggestions.
std::vector<std::string> PassNames(const Pack& pack, uint32_t shader) {
    std::vector<std::string> names;
    const ShaderRec s = pack.Shader(shader).value();
    for (uint32_t i = s.first_pass; i < s.first_pass + s.pass_count; ++i) {
        const std::string label = PassLabel(pack, i);
        for (std::string_view n : {std::string_view(label), pack.String(pack.Pass(i).value().name),
                                   LightModeOf(pack, i)}) {
            if (!n.empty() && std::find(names.begin(), names.end(), n) == names.end())
                names.emplace_back(n);
        }
    }
    return names;
}

// The pass of a pack named by shader and pass, its keywords checked (kiln extract, kiln show).
std::optional<uint32_t> ResolvePass(const Pack& pack,
                                    const std::string& file,
                                    const VariantName& name,
                                    const GlobalOptions& global) {
    const auto shader = pack.FindShader(name.shader);
    if (!shader) {
        ReportError(global, DiagCode::kUnknownPackName, file,
                    "no shader \"" + name.shader + "\" in " +
                        (file.ends_with(".kpack") || file == "-" ? "the pack" : "'" + file + "'") +
                        pack::DidYouMean(name.shader, ShaderNames(pack)));
        return std::nullopt;
    }
    const auto pass = pack.FindPass(*shader, name.pass);
    if (!pass) {
        ReportError(global, DiagCode::kUnknownPackName, file,
                    "shader \"" + name.shader + "\" has no pass \"" + name.pass + "\"" +
                        pack::DidYouMean(name.pass, PassNames(pack, *shader)));
        return std::nullopt;
    }
    if (Status declared = pack.CheckKeywords(*pass, name.keywords); !declared.ok()) {
        ReportError(global, declared.error().code, file,
                    "shader \"" + name.shader + "\" pass \"" + name.pass +
                        "\": " + declared.error().message);
        return std::nullopt;
    }
    return pass;
}

std::optional<pack::VariantRec> ResolveVariant(const Pack& pack,
                                               const std::string& file,
                                               const VariantName& name,
                                               const GlobalOptions& global) {
    const std::optional<uint32_t> pass = ResolvePass(pack, file, name, global);
    if (!pass)
        return std::nullopt;
    const auto variant = pack.FindVariant(*pass, pack.KeyFor(*pass, name.keywords));
    if (!variant) {
        std::string kws;
        for (const auto& k : name.keywords)
            kws += " " + k;
        ReportError(global, DiagCode::kMissingVariant, file,
                    "shader \"" + name.shader + "\" pass \"" + name.pass +
                        "\" has no variant with keywords" + (kws.empty() ? " (none)" : kws) +
                        " (stripped or never built)");
        return std::nullopt;
    }
    return pack.Variant(*variant).value();
}

std::function<int()> AddExtractCommand(CLI::App* cmd, const GlobalOptions& global) {
    struct Options {
        std::string file, stage, output;
        VariantName name;
    };
    auto o = std::make_shared<Options>();
    cmd->add_option("pack", o->file, "A .kpack file (- reads standard input)")->required();
    AddVariantNameOptions(*cmd, o->name);
    AddStageOption(
        cmd->add_option("--stage", o->stage, "vert, frag, geometry, hull or domain")->required());
    cmd->add_option("-o,--output", o->output, "Output .spv (- writes standard output)")->required();
    return [o, &global]() {
        MappedFile file;
        Pack pack;
        if (!OpenPack(o->file, file, pack, global))
            return int(kExitInputError);
        const std::optional<pack::VariantRec> v = ResolveVariant(pack, o->file, o->name, global);
        if (!v)
            return int(kExitInputError);
        const std::optional<uint32_t> module =
            ModuleAt(pack, *v, StageOf(o->stage), o->file, global);
        if (!module)
            return int(kExitInputError);
        const auto bytes = pack.Spirv(pack.Module(*module).value());
        Status written = base::WriteFileAtomically(
            o->output, std::span<const uint8_t>(bytes.data(), bytes.size()), {{o->file}});
        if (!written.ok())
            return ReportError(global, DiagCode::kCannotWriteFile, o->output,
                               written.error().message);
        return int(kExitOk);
    };
}

void AddStageOption(CLI::Option* option) {
    option->check(
        CLI::IsMember({"vert", "frag", "vertex", "fragment", "geometry", "hull", "domain"}));
}

pack::Stage StageOf(const std::string& option) {
    for (uint32_t s = 0; s < pack::kStageCount; ++s) {
        const std::string name = pack::StageName(pack::Stage(s));
        if (option == name || option == name.substr(0, 4))
            return pack::Stage(s);
    }
    return pack::Stage::kFragment;
}

std::optional<uint32_t> ModuleAt(const Pack& pack,
                                 const pack::VariantRec& variant,
                                 pack::Stage stage,
                                 const std::string& file,
                                 const GlobalOptions& global) {
    std::string stages;
    for (uint32_t m : pack.ModulesOf(variant)) {
        const pack::ModuleRec rec = pack.Module(m).value();
        if (rec.stage == uint32_t(stage))
            return m;
        stages += std::string(stages.empty() ? "" : ", ") + pack::StageName(pack::Stage(rec.stage));
    }
    ReportError(global, DiagCode::kMissingVariant, file,
                std::string("the variant has no ") + pack::StageName(stage) + " stage (it has " +
                    stages + ")");
    return std::nullopt;
}

void AddVariantNameOptions(CLI::App& cmd, VariantName& name) {
    cmd.add_option("--shader", name.shader, "Shader name")->required();
    cmd.add_option("--pass", name.pass, "Pass as kiln info names it, its Name or LightMode")
        ->required();
    cmd.add_option("--keywords", name.keywords, "Enabled keywords")->delimiter(',');
}

}  // namespace kiln::cli
