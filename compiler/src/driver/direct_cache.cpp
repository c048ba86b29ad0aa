#include "driver/direct_cache.h"

#include <filesystem>

namespace kiln::driver {
namespace fs = std::filesystem;

namespace {

constexpr const char* kManifestExt = "man";
constexpr const char* kManifestHeader = "kiln-direct 1";

std::vector<std::string> Split(const std::string& s, char sep) {
    std::vector<std::string> out;
    size_t at = 0;
    for (size_t next; (next = s.find(sep, at)) != std::string::npos; at = next + 1)
        out.push_back(s.substr(at, next - at));
    out.push_back(s.substr(at));
    return out;
}

bool Storable(const std::string& field) {
    return field.find_first_of("\t\n") == std::string::npos;
}

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

std::optional<std::string> DirectCache::ContentHash(const std::string& path) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (auto it = hashes_.find(path); it != hashes_.end())
            return it->second;
    }
    std::optional<std::string> hash;
    if (auto file = files_.Get(path))
        hash = HashKey({std::string(file->text())});
    std::lock_guard<std::mutex> lock(mu_);
    return hashes_.emplace(path, hash).first->second;
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

// Manifest: a header line, "result\t<key>", then "file\t<hash>\t<tag>" per file read (in the
// order read) and "include\t<1 local|0>\t<includer tag>\t<header>\t<resolved tag>" per #include.
std::optional<std::string> DirectCache::Lookup(const std::string& key, const std::string& shader) {
    const std::optional<std::string> manifest = cache_.LoadBytes(key, kManifestExt);
    if (!manifest)
        return std::nullopt;
    const std::vector<std::string> lines = Split(*manifest, '\n');
    if (lines.size() < 2 || lines[0] != kManifestHeader)
        return std::nullopt;
    std::optional<std::string> result;
    for (size_t i = 1; i < lines.size(); ++i) {
        const std::vector<std::string> f = Split(lines[i], '\t');
        if (f[0] == "result" && f.size() == 2 && f[1].size() == 32 && !result) {
            result = f[1];
        } else if (f[0] == "file" && f.size() == 3) {
            const std::string path = Untag(f[2], shader);
            if (path.empty() || ContentHash(path) != f[1])
                return std::nullopt;
        } else if (f[0] == "include" && f.size() == 5 && (f[1] == "0" || f[1] == "1")) {
            const std::string includer = Untag(f[2], shader);
            if (includer.empty() || ResolvedTag({f[3], f[1] == "1"}, includer, shader) != f[4])
                return std::nullopt;
        } else if (!(lines[i].empty() && i + 1 == lines.size())) {
            return std::nullopt;  // damaged
        }
    }
    return result;
}

void DirectCache::Record(const std::string& key,
                         const std::string& shader,
                         const std::string& source,
                         const std::vector<std::string>& files_read,
                         const std::string& result_key) {
    std::string manifest = std::string(kManifestHeader) + "\nresult\t" + result_key + "\n";
    std::string includes;
    auto add_includes = [&](const std::string& text, const std::string& includer) {
        const auto directives = IncludeDirectives(text);
        const std::string includer_tag = Tag(includer, shader);
        if (!directives || !Storable(includer_tag))
            return false;
        for (const IncludeDirective& d : *directives) {
            const std::string resolved = ResolvedTag(d, includer, shader);
            if (!Storable(d.header) || !Storable(resolved))
                return false;
            includes += "include\t" + std::string(d.local ? "1" : "0") + "\t" + includer_tag +
                        "\t" + d.header + "\t" + resolved + "\n";
        }
        return true;
    };
    if (!add_includes(source, shader))
        return;
    for (const std::string& path : files_read) {
        const auto file = files_.Get(path);
        const std::optional<std::string> hash = ContentHash(path);
        const std::string tag = Tag(path, shader);
        if (!file || !hash || !Storable(tag) || !add_includes(std::string(file->text()), path))
            return;
        manifest += "file\t" + *hash + "\t" + tag + "\n";
    }
    cache_.StoreBytes(key, kManifestExt, manifest + includes);
}

}  // namespace kiln::driver
