#include "hlsl/file_cache.h"

namespace kiln::hlsl {

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

}  // namespace kiln::hlsl
