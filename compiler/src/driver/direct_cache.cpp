#include "driver/direct_cache.h"

#include <algorithm>
#include <filesystem>

#include "kiln/compile.h"

namespace kiln::driver {
namespace fs = std::filesystem;

namespace {

constexpr const char* kManifestExt = "man";
// The fewest entries a manifest keeps (of this compile and earlier ones) before it drops old ones.
constexpr size_t kMinBundleEntries = 4096;

// `path` relative to `root` when it lies under it.
std::optional<std::string> Under(const std::string& path, const std::string& root) {
    if (root.empty())
        return std::nullopt;
    const fs::path rel =
        fs::path(path).lexically_normal().lexically_relative(fs::path(root).lexically_normal());
    if (rel.empty() || *rel.begin() == ".." || rel.is_absolute())
        return std::nullopt;
    return rel.string();
}

}  // namespace

std::optional<std::vector<IncludeDirective>> IncludeDirectives(const std::string& text) {
    std::vector<IncludeDirective> out;
    for (size_t at = 0; at < text.size();) {
        size_t end = text.find('\n', at);
        if (end == std::string::npos)
            end = text.size();
        size_t i = text.find_first_not_of(" \t", at);
        if (i < end && text[i] == '#') {
            i = text.find_first_not_of(" \t", i + 1);
            if (i < end && text.compare(i, 7, "include") == 0) {
                i = text.find_first_not_of(" \t", i + 7);
                const char open = i < end ? text[i] : '\0';
                const char close = open == '"' ? '"' : '>';
                const size_t stop = open == '"' || open == '<' ? text.find(close, i + 1) : end;
                if (stop >= end)
                    return std::nullopt;  // a macro, or no closing quote: not resolvable here
                out.push_back({text.substr(i + 1, stop - i - 1), open == '"'});
            }
        }
        at = end + 1;
    }
    return out;
}

DirectCache::DirectCache(Cache cache, hlsl::IncludePaths paths, hlsl::FileCache& files)
    : cache_(std::move(cache)),
      paths_(std::move(paths)),
      files_(files),
      resolver_(paths_, probes_) {}

std::string DirectCache::KeyFor(const std::vector<std::string>& parts,
                                const std::string& source,
                                const std::string& shader) const {
    std::vector<std::string> all = parts;
    all.push_back(std::to_string(paths_.dirs.size()));
    const std::string quoted = "\"" + shader + "\"";
    const std::string name = "\"" + fs::path(shader).filename().string() + "\"";
    std::string text;
    text.reserve(source.size());
    size_t at = 0;
    for (size_t hit; (hit = source.find(quoted, at)) != std::string::npos; at = hit + quoted.size())
        text.append(source, at, hit - at).append(name);
    text.append(source, at);
    all.push_back(std::move(text));
    return HashKey(all);
}

std::string DirectCache::Tag(const std::string& path, const std::string& shader) const {
    if (path.empty())
        return "";
    if (auto rel = Under(path, paths_.templates_dir))
        return "T:" + *rel;
    for (size_t i = 0; i < paths_.dirs.size(); ++i) {
        if (auto rel = Under(path, paths_.dirs[i]))
            return "I" + std::to_string(i) + ":" + *rel;
    }
    if (auto rel = Under(path, fs::path(shader).parent_path().string()))
        return "S:" + *rel;
    return "A:" + path;
}

std::string DirectCache::UntagOnce(const std::string& tag, const std::string& shader) const {
    const size_t colon = tag.find(':');
    if (colon == std::string::npos)
        return "";
    const std::string root = tag.substr(0, colon), rel = tag.substr(colon + 1);
    auto join = [&](const fs::path& dir) { return (dir / rel).lexically_normal().string(); };
    if (root == "T")
        return join(paths_.templates_dir);
    if (root == "S")
        return join(fs::path(shader).parent_path());
    if (root == "A")
        return rel;
    if (root.size() > 1 && root[0] == 'I') {
        const std::string n = root.substr(1);
        if (n.size() < 6 && n.find_first_not_of("0123456789") == std::string::npos &&
            std::stoul(n) < paths_.dirs.size()) {
            return join(paths_.dirs[std::stoul(n)]);
        }
    }
    return "";
}

std::string DirectCache::Untag(const std::string& tag, const std::string& shader) {
    std::string memo = shader;
    memo.append(1, '\0').append(tag);
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (auto it = untagged_.find(memo); it != untagged_.end())
            return it->second;
    }
    std::string path = UntagOnce(tag, shader);
    std::lock_guard<std::mutex> lock(mu_);
    return untagged_.emplace(std::move(memo), std::move(path)).first->second;
}

std::optional<std::string> DirectCache::ContentHash(const std::string& path, bool quiet) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (auto it = hashes_.find(path); it != hashes_.end())
            return it->second;
        if (auto it = quiet_hashes_.find(path); quiet && it != quiet_hashes_.end())
            return it->second;
    }
    std::optional<std::string> hash;
    if (auto file = (quiet ? probes_ : files_).Get(path))
        hash = HashKey({std::string(file->text())});
    std::lock_guard<std::mutex> lock(mu_);
    return (quiet ? quiet_hashes_ : hashes_).emplace(path, hash).first->second;
}

std::string DirectCache::ResolvedTag(const IncludeDirective& d,
                                     const std::string& includer,
                                     const std::string& shader) {
    std::string memo = shader;
    memo.append(1, '\0').append(includer).append(1, '\0').append(d.header);
    memo += d.local ? '\1' : '\2';
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (auto it = resolved_.find(memo); it != resolved_.end())
            return it->second;
    }
    std::string tag = Tag(resolver_.Resolve(d.header, includer, d.local), shader);
    std::lock_guard<std::mutex> lock(mu_);
    return resolved_.emplace(std::move(memo), std::move(tag)).first->second;
}

std::string DirectCache::BundleKey(const std::string& shader) const {
    return HashKey({"kiln-direct-bundle", ProducerVersion(), fs::path(shader).filename().string(),
                    std::to_string(paths_.dirs.size())});
}

DirectCache::Bundle& DirectCache::BundleOf(const std::string& shader) {
    auto [it, fresh] = bundles_.try_emplace(BundleKey(shader));
    Bundle& b = it->second;
    if (!fresh)
        return b;
    b.shader = shader;
    const std::optional<std::string> text = cache_.LoadBytes(it->first, kManifestExt);
    std::optional<DirectBundle> read = text ? ParseDirectBundle(*text) : std::nullopt;
    if (!read)
        return b;  // none yet, or damaged: rewritten by the next Flush with records
    std::vector<uint32_t> files, includes, sets;
    for (const std::string& line : read->files)
        files.push_back(InternFile(line));
    for (const std::string& line : read->includes)
        includes.push_back(InternInclude(line));
    for (const DirectBundle::Set& set : read->sets) {
        DirectBundle::Set ours;
        for (uint32_t f : set.files)
            ours.files.push_back(files[f]);
        for (uint32_t i : set.includes)
            ours.includes.push_back(includes[i]);
        sets.push_back(InternSet(std::move(ours)));
    }
    for (DirectBundle::Entry& e : read->entries) {
        if (b.old_by_key.emplace(e.direct, b.old.size()).second)
            b.old.push_back({std::move(e.direct), std::move(e.result), sets[e.set]});
    }
    return b;
}

uint32_t DirectCache::InternFile(const std::string& line) {
    auto [it, fresh] = file_ids_.emplace(line, file_lines_.size());
    if (fresh)
        file_lines_.push_back(line);
    return it->second;
}

uint32_t DirectCache::InternInclude(const std::string& line) {
    auto [it, fresh] = include_ids_.emplace(line, include_lines_.size());
    if (fresh)
        include_lines_.push_back(line);
    return it->second;
}

uint32_t DirectCache::InternSet(DirectBundle::Set set) {
    auto [it, fresh] = set_ids_.emplace(set, sets_.size());
    if (fresh)
        sets_.push_back(std::move(set));
    return it->second;
}

bool DirectCache::LineHolds(bool file,
                            const std::string& line,
                            const std::string& shader,
                            bool quiet) {
    const std::vector<std::string_view> f = SplitDirectFields(line);
    if (file) {
        const std::string path = f.size() == 2 ? Untag(std::string(f[1]), shader) : "";
        return !path.empty() && ContentHash(path, quiet) == f[0];
    }
    if (f.size() != 4)
        return false;
    const std::string includer = Untag(std::string(f[1]), shader);
    return !includer.empty() &&
           ResolvedTag({std::string(f[2]), f[0] == "1"}, includer, shader) == f[3];
}

bool DirectCache::SetHolds(uint32_t set, const std::string& shader, bool quiet) {
    std::vector<std::string> files, includes;
    {
        std::lock_guard<std::mutex> lock(bundles_mu_);
        std::vector<int8_t>& memo = set_holds_[shader];
        memo.resize(sets_.size());
        if (memo[set] != 0)
            return memo[set] == 1;
        for (uint32_t f : sets_[set].files)
            files.push_back(file_lines_[f]);
        for (uint32_t i : sets_[set].includes)
            includes.push_back(include_lines_[i]);
    }
    bool holds = true;
    for (size_t k = 0; holds && k < files.size(); ++k)
        holds = LineHolds(true, files[k], shader, quiet);
    for (size_t k = 0; holds && k < includes.size(); ++k)
        holds = LineHolds(false, includes[k], shader, quiet);
    std::lock_guard<std::mutex> lock(bundles_mu_);
    std::vector<int8_t>& memo = set_holds_[shader];
    memo.resize(sets_.size());
    memo[set] = holds ? 1 : 2;
    return holds;
}

std::optional<std::string> DirectCache::Lookup(const std::string& key, const std::string& shader) {
    Stored found;
    {
        std::lock_guard<std::mutex> lock(bundles_mu_);
        Bundle& b = BundleOf(shader);
        const auto it = b.old_by_key.find(key);
        if (it == b.old_by_key.end())
            return std::nullopt;
        found = b.old[it->second];
    }
    if (!SetHolds(found.set, shader))
        return std::nullopt;
    std::lock_guard<std::mutex> lock(bundles_mu_);
    Bundle& b = BundleOf(shader);
    if (b.fresh_keys.insert(key).second)
        b.fresh.push_back(found);
    return found.result;
}

std::optional<std::vector<std::string>> DirectCache::IncludeLines(const std::string& text,
                                                                  const std::string& includer,
                                                                  const std::string& shader) {
    const auto directives = IncludeDirectives(text);
    const std::string includer_tag = Tag(includer, shader);
    if (!directives || !DirectStorable(includer_tag))
        return std::nullopt;
    std::vector<std::string> out;
    for (const IncludeDirective& d : *directives) {
        const std::string resolved = ResolvedTag(d, includer, shader);
        if (!DirectStorable(d.header) || d.header.empty() || !DirectStorable(resolved))
            return std::nullopt;
        out.push_back(std::string(d.local ? "1" : "0") + "\t" + includer_tag + "\t" + d.header +
                      "\t" + resolved);
    }
    return out;
}

std::optional<DirectCache::FileDeps> DirectCache::DepsOf(const std::string& path,
                                                         const std::string& shader) {
    std::string memo = shader;
    memo.append(1, '\0').append(path);
    {
        std::lock_guard<std::mutex> lock(bundles_mu_);
        if (auto it = deps_.find(memo); it != deps_.end())
            return it->second;
    }
    const auto file = files_.Get(path);
    const std::optional<std::string> hash = ContentHash(path);
    const std::string tag = Tag(path, shader);
    std::optional<std::vector<std::string>> includes;
    if (file && hash && DirectStorable(tag))
        includes = IncludeLines(std::string(file->text()), path, shader);
    std::lock_guard<std::mutex> lock(bundles_mu_);
    std::optional<FileDeps> deps;
    if (includes) {
        deps.emplace();
        deps->file = InternFile(*hash + "\t" + tag);
        for (const std::string& line : *includes)
            deps->includes.push_back(InternInclude(line));
    }
    return deps_.emplace(std::move(memo), std::move(deps)).first->second;
}

void DirectCache::Record(const std::string& key,
                         const std::string& shader,
                         const std::string& source,
                         const std::vector<std::string>& files_read,
                         const std::string& result_key) {
    const std::optional<std::vector<std::string>> own = IncludeLines(source, shader, shader);
    if (!own)
        return;
    std::vector<FileDeps> deps;
    for (const std::string& path : files_read) {
        std::optional<FileDeps> d = DepsOf(path, shader);
        if (!d)
            return;
        deps.push_back(std::move(*d));
    }
    std::lock_guard<std::mutex> lock(bundles_mu_);
    DirectBundle::Set set;
    for (const std::string& line : *own)
        set.includes.push_back(InternInclude(line));
    for (const FileDeps& d : deps) {
        set.files.push_back(d.file);
        set.includes.insert(set.includes.end(), d.includes.begin(), d.includes.end());
    }
    Bundle& b = BundleOf(shader);
    b.dirty = true;
    if (b.fresh_keys.insert(key).second)
        b.fresh.push_back({key, result_key, InternSet(std::move(set))});
}

void DirectCache::Flush() {
    std::map<std::string, Bundle> bundles;
    {
        std::lock_guard<std::mutex> lock(bundles_mu_);
        bundles.swap(bundles_);
    }
    for (auto& [key, b] : bundles) {
        if (!b.dirty)
            continue;
        std::vector<Stored> entries = std::move(b.fresh);
        std::sort(entries.begin(), entries.end(),
                  [](const Stored& x, const Stored& y) { return x.direct < y.direct; });
        // Earlier compiles' entries that still hold follow (another keyword subset, other
        // options), up to twice this compile's: entries of edited sources fall off the end.
        const size_t bound = std::max<size_t>(2 * entries.size(), kMinBundleEntries);
        for (Stored& e : b.old) {
            if (entries.size() >= bound)
                break;
            if (!b.fresh_keys.count(e.direct) && SetHolds(e.set, b.shader, true))
                entries.push_back(std::move(e));
        }
        cache_.StoreBytes(key, kManifestExt, Serialize(entries));
    }
}

std::string DirectCache::Serialize(const std::vector<Stored>& entries) {
    std::lock_guard<std::mutex> lock(bundles_mu_);
    DirectBundle out;
    std::unordered_map<uint32_t, uint32_t> files, includes, sets;  // ours -> the manifest's
    // The manifest's number of our line `id`, listing the line on its first use.
    auto number = [](std::unordered_map<uint32_t, uint32_t>& numbers, uint32_t id,
                     const std::vector<std::string>& ours, std::vector<std::string>& listed) {
        const auto [it, fresh] = numbers.emplace(id, static_cast<uint32_t>(listed.size()));
        if (fresh)
            listed.push_back(ours[id]);
        return it->second;
    };
    for (const Stored& e : entries) {
        auto [s, fresh] = sets.emplace(e.set, static_cast<uint32_t>(out.sets.size()));
        if (fresh) {
            DirectBundle::Set set;
            for (uint32_t f : sets_[e.set].files)
                set.files.push_back(number(files, f, file_lines_, out.files));
            for (uint32_t i : sets_[e.set].includes)
                set.includes.push_back(number(includes, i, include_lines_, out.includes));
            out.sets.push_back(std::move(set));
        }
        out.entries.push_back({e.direct, e.result, s->second});
    }
    return SerializeDirectBundle(out);
}

}  // namespace kiln::driver
