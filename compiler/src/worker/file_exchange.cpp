#include "worker/file_exchange.h"

namespace kiln::worker {

std::string ContentHashes::Of(const std::shared_ptr<const SourceFile>& file) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (auto it = hashes_.find(file); it != hashes_.end())
            return it->second;
    }
    std::string hash = ContentHash(file->text());  // outside the lock: files hash in parallel
    std::lock_guard<std::mutex> lock(mu_);
    return hashes_.emplace(file, std::move(hash)).first->second;
}

std::string FileServer::Answer(const std::string& path) {
    FileAnswer a;
    a.path = path;
    if (const auto file = files_.Get(path)) {
        a.found = true;
        a.hash = hashes_.Of(file);
        std::lock_guard<std::mutex> lock(mu_);
        if (sent_.insert(a.hash).second) {
            a.with_content = true;
            a.content = file->text();
        }
    }
    return EncodeFile(a);
}

void FileServer::Reset() {
    std::lock_guard<std::mutex> lock(mu_);
    sent_.clear();
}

std::optional<std::string> RemoteFiles::Load(const std::string& path) {
    // One question and its answer at a time: an answer without content ("you have it") must not
    // overtake the answer that carries it (threads of the in-process executor ask concurrently).
    std::lock_guard<std::mutex> exchange(exchange_mu_);
    const std::optional<FileAnswer> a = ask_(path);
    std::lock_guard<std::mutex> lock(mu_);
    if (!a || a->path != path) {
        error_ = "the client's answer for '" + path + "' is missing or about another file";
        return std::nullopt;
    }
    if (!a->found)
        return std::nullopt;
    if (a->with_content)
        by_hash_.emplace(a->hash, a->content);  // DecodeFile checked the hash
    const auto it = by_hash_.find(a->hash);
    if (it == by_hash_.end()) {
        error_ = "the client named content " + a->hash + " for '" + path + "' but never sent it";
        return std::nullopt;
    }
    return it->second;
}

std::string RemoteFiles::error() const {
    std::lock_guard<std::mutex> lock(mu_);
    return error_;
}

}  // namespace kiln::worker
