// The whole pack in the compile cache: a no-change rebuild, where the direct mode knows the result
// of every stage program, takes the pack a compile of the same inputs built, without loading,
// binding, reflecting or validating any module again. The key is everything the pack is a
// function of: the versions, every option that changes what is built, each shader's file name and
// text, and the result key of every stage program in order (which stands for the includes). The
// warnings reported after expansion (by glslang, reflection, interface checks: steps a hit skips)
// are stored with the pack and reported again on a hit, as ccache replays a compiler's stderr;
// they name files, so a hit with warnings also needs the same shader paths, -I folders and
// templates. Only compiles without errors are stored; the pack read back must open (its checksums
// and structure verified) or the entry is a miss.
#include <cstdio>
#include <filesystem>
#include <string_view>

#include "driver/cache.h"
#include "driver/compile_state.h"
#include "driver/isolation.h"
#include "kiln/base/bytes.h"
#include "kiln/diagnostic.h"
#include "kiln/pack/reader.h"

namespace kiln::driver {
namespace {

std::string Number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// Every option that changes what is built. Jobs, the cache, isolation, the worker's path and its
// limits, and progress do not (a limit that is hit is an error, and errors are not stored).
std::string OptionsText(const CompileOptions& o) {
    std::string s;
    auto field = [&s](const std::string& name, const std::string& value) {
        s += name + "=" + std::to_string(value.size()) + ":" + value + ";";
    };
    for (const std::string& d : o.include_dirs)
        field("I", d);
    for (const auto& [name, value] : o.defines)
        field("D", name + "=" + value);
    for (const std::string& u : o.undefines)
        field("U", u);
    for (const std::string& f : o.forced_includes)
        field("include", f);
    field("unity", std::to_string(o.unity_version));
    field("templates", o.templates_dir.empty() ? DefaultTemplatesDir() : o.templates_dir);
    field("O", OptimizationKey(o));
    field("g", o.debug_info ? "1" : "0");
    field("precision", std::to_string(int(o.precision)));
    field("aliases", o.keyword_aliases ? "1" : "0");
    for (const auto& [shader, requests] : o.materials) {
        field("materials", shader);
        for (const MaterialRequest& m : requests) {
            for (const std::string& k : m.keywords)
                field("keyword", k);
            for (const auto& [name, value] : m.values)
                field("value", name + "=" + Number(value));
            field("end", "");
        }
    }
    if (o.keywords) {
        for (const std::string& k : *o.keywords)
            field("keywords", k);
        field("keywords-end", "");
    }
    field("all-features", o.all_features ? "1" : "0");
    field("strict-variants", o.strict_variants ? "1" : "0");
    field("max-variants", std::to_string(o.max_variants));
    if (o.requests)
        field("requests", pack::UsageFileText(*o.requests));
    return s;
}

// Where the files a warning may name were: the shader paths, -I folders and templates.
std::string Locations(const CompileState& st) {
    std::string s;
    for (const ShaderUnit& unit : st.shaders)
        s += unit.file->path() + '\n';
    for (const std::string& d : st.options.include_dirs)
        s += d + '\n';
    return s +
           (st.options.templates_dir.empty() ? DefaultTemplatesDir() : st.options.templates_dir);
}

}  // namespace

std::string PackKey(const CompileState& st) {
    std::vector<std::string> parts = {"pack", ProducerVersion(), OptionsText(st.options)};
    for (const ShaderUnit& unit : st.shaders) {
        // Its name, not its folder: nothing in a pack names a folder (-g modules, which do,
        // have result keys of their own), so the same sources elsewhere hit the same pack.
        parts.push_back(std::filesystem::path(unit.file->path()).filename().string());
        parts.push_back(std::string(unit.file->text()));
    }
    for (const StageTask& t : st.tasks) {
        if (t.result_key.empty())
            return "";  // not every program is known: nothing to look up or store
        parts.push_back(t.result_key);
    }
    return HashKey(parts);
}

// Entry payload: the module and aliased-variant counts (for --stats), the sizes of the warnings'
// JSON and of the locations text, both, then the pack.
std::optional<std::vector<uint8_t>> LoadCachedPack(const CompileState& st, CompileStats& stats) {
    const Cache cache(st.options.cache_dir);
    const std::string key = PackKey(st);
    if (key.empty())
        return std::nullopt;
    const std::optional<std::string> entry = cache.LoadBytes(key, Cache::kPackExt);
    if (!entry || entry->size() < 16)
        return std::nullopt;
    const uint64_t warnings_size = base::LoadLe32(*entry, 8);
    const uint64_t locations_size = base::LoadLe32(*entry, 12);
    if (entry->size() < 16 + warnings_size + locations_size)
        return std::nullopt;
    const std::string_view warnings = std::string_view(*entry).substr(16, warnings_size);
    const std::string_view locations =
        std::string_view(*entry).substr(16 + warnings_size, locations_size);
    DiagnosticList replay;
    if (!warnings.empty()) {
        if (locations != Locations(st))
            return std::nullopt;
        Result<DiagnosticList> parsed = ParseDiagnosticsJson(warnings);
        if (!parsed || parsed.value().has_errors())
            return std::nullopt;
        replay = std::move(parsed).value();
    }
    std::vector<uint8_t> bytes(entry->begin() + 16 + warnings_size + locations_size, entry->end());
    if (!pack::Pack::Open(bytes))
        return std::nullopt;
    st.diags.Append(replay);
    stats.modules = base::LoadLe32(*entry, 0);
    stats.aliased_variants = base::LoadLe32(*entry, 4);
    return bytes;
}

void StoreCachedPack(const CompileState& st,
                     const CompileStats& stats,
                     const std::vector<uint8_t>& pack,
                     size_t first_warning) {
    const std::string key = PackKey(st);
    if (key.empty() || st.diags.has_errors())
        return;
    DiagnosticList warnings;
    for (size_t i = first_warning; i < st.diags.all().size(); ++i) {
        const Diagnostic& d = st.diags.all()[i];
        warnings.Add(d.severity, d.code, d.file, d.range, d.message).notes = d.notes;
    }
    const std::string json = warnings.all().empty() ? "" : FormatDiagnosticsJson(warnings);
    const std::string locations = warnings.all().empty() ? "" : Locations(st);
    std::string entry;
    base::AppendLe32(entry, static_cast<uint32_t>(stats.modules));
    base::AppendLe32(entry, static_cast<uint32_t>(stats.aliased_variants));
    base::AppendLe32(entry, static_cast<uint32_t>(json.size()));
    base::AppendLe32(entry, static_cast<uint32_t>(locations.size()));
    entry += json;
    entry += locations;
    entry.append(pack.begin(), pack.end());
    Cache(st.options.cache_dir).StoreBytes(key, Cache::kPackExt, entry);
}

}  // namespace kiln::driver
