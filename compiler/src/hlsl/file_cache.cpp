#include "hlsl/file_cache.h"

#include <algorithm>

#include "hlsl/lean_text.h"
#include "hlsl/needless_defines.h"
#include "hlsl/pp_skeleton.h"
#include "hlsl/splice.h"

namespace kiln::hlsl {

std::string_view ServedText(const SourceFile& file) {
    std::string_view text = file.text();
    if (text.substr(0, 3) == "\xEF\xBB\xBF")
        text.remove_prefix(3);
    return text;
}

std::shared_ptr<const SourceFile> FileCache::Get(const std::string& path) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        auto it = files_.find(path);
        if (it != files_.end())
            return it->second;
    }
    std::shared_ptr<const SourceFile> file;
    if (loader_) {
        if (std::optional<std::string> bytes = loader_(path))
            file = std::make_shared<const SourceFile>(path, std::move(*bytes));
    } else if (auto read = ReadSourceFile(path); read.ok()) {  // regular files, within the limit
        file = std::make_shared<const SourceFile>(std::move(read).value());
    }
    std::lock_guard<std::mutex> lock(mu_);
    return files_.emplace(path, std::move(file)).first->second;
}

void FileCache::Put(std::shared_ptr<const SourceFile> file) {
    std::lock_guard<std::mutex> lock(mu_);
    files_[file->path()] = std::move(file);
}

std::vector<std::shared_ptr<const SourceFile>> FileCache::Files() const {
    std::lock_guard<std::mutex> lock(mu_);
    std::vector<std::shared_ptr<const SourceFile>> out;
    for (const auto& [path, file] : files_) {
        if (file)
            out.push_back(file);
    }
    return out;
}

std::shared_ptr<const PpSkeleton> FileCache::Skeleton(
    const std::shared_ptr<const SourceFile>& file) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto it = skeletons_.find(file->path());
        if (it != skeletons_.end() && it->second.first == file)
            return it->second.second;
    }
    auto skeleton = std::make_shared<const PpSkeleton>(ScanSkeleton(ServedText(*file)));
    std::lock_guard<std::mutex> lock(mu_);
    skeletons_[file->path()] = {file, skeleton};
    return skeleton;
}

std::shared_ptr<const LeanText> FileCache::Lean(const std::shared_ptr<const SourceFile>& file) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto it = leans_.find(file->path());
        if (it != leans_.end() && it->second.first == file)
            return it->second.second;
    }
    auto lean = std::make_shared<const LeanText>(MakeLeanText(ServedText(*file), *Skeleton(file)));
    std::lock_guard<std::mutex> lock(mu_);
    leans_[file->path()] = {file, lean};
    return lean;
}

std::shared_ptr<const SpliceFile> FileCache::Splice(const std::shared_ptr<const SourceFile>& file) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto it = splices_.find(file->path());
        if (it != splices_.end() && it->second.first == file)
            return it->second.second;
    }
    std::shared_ptr<const SpliceFile> splice = ScanSpliceFile(Lean(file), *Skeleton(file));
    std::lock_guard<std::mutex> lock(mu_);
    splices_[file->path()] = {file, splice};
    return splice;
}

std::shared_ptr<const SpliceChoice> FileCache::SpliceRuns(
    const std::shared_ptr<const SpliceFile>& file,
    const std::shared_ptr<const IncludedDefines>& defines,
    const SplicePatch& patch) {
    auto key = std::make_tuple(file.get(), defines.get(), patch);
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto it = splice_macros_.find(key);
        if (it != splice_macros_.end())
            return it->second.choice;
    }
    std::vector<char> macro =
        patch.empty() ? MacroWords(*file, defines->defined, defines->callable, defines->empty)
                      : SpliceRuns(file, defines)->macro;
    for (const auto& [word, kind] : patch)
        macro[word] = kind;
    auto choice = std::make_shared<const SpliceChoice>(ChooseSpliceRuns(*file, std::move(macro)));
    std::lock_guard<std::mutex> lock(mu_);
    splice_macros_[std::move(key)] = {file, defines, choice};
    return choice;
}

std::shared_ptr<const std::unordered_set<std::string_view>> FileCache::SpliceWords(
    const std::shared_ptr<const IncludedDefines>& defines,
    const std::vector<std::shared_ptr<const SpliceFile>>& files) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto it = splice_words_.find(defines.get());
        if (it != splice_words_.end())
            return it->second.words;
    }
    auto words = std::make_shared<std::unordered_set<std::string_view>>();
    for (const auto& file : files)
        words->insert(file->words.begin(), file->words.end());
    std::lock_guard<std::mutex> lock(mu_);
    splice_words_[defines.get()] = {defines, files, words};
    return words;
}

std::shared_ptr<const IncludedDefines> FileCache::Defines(
    const std::vector<std::shared_ptr<const PpSkeleton>>& files) {
    std::vector<const PpSkeleton*> key;
    for (const auto& file : files)
        key.push_back(file.get());
    std::sort(key.begin(), key.end());
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (const auto it = defines_.find(key); it != defines_.end())
            return it->second;
    }
    auto made = std::make_shared<const IncludedDefines>(MakeIncludedDefines(files));
    std::lock_guard<std::mutex> lock(mu_);
    constexpr size_t kMaxSets = 256;  // a watch session's edits make new sets
    if (defines_.size() >= kMaxSets)
        defines_.clear();
    defines_[key] = made;
    return made;
}

std::optional<std::string> FileCache::Resolved(const std::string& key) const {
    std::lock_guard<std::mutex> lock(mu_);
    const auto it = resolved_.find(key);
    if (it == resolved_.end())
        return std::nullopt;
    return it->second;
}

void FileCache::RememberResolved(const std::string& key, const std::string& path) {
    std::lock_guard<std::mutex> lock(mu_);
    resolved_.emplace(key, path);
}

}  // namespace kiln::hlsl
