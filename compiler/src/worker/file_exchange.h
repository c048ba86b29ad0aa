// The files a worker reads, served through the protocol (worker/protocol.h): the worker asks for
// a file by the client's path, the client answers with its hash and, once per connection, its
// bytes. Neither side trusts a path to mean anything on the other's disk: the worker resolves
// includes as always (hlsl/includer.h), against a FileCache whose loader asks the client.
#ifndef KILN_WORKER_FILE_EXCHANGE_H_
#define KILN_WORKER_FILE_EXCHANGE_H_

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>

#include "hlsl/file_cache.h"
#include "worker/protocol.h"

namespace kiln::worker {

// The content hash of each file a compile serves, computed once however many connections ask for
// it (each worker of a pool asks for the same includes). Keeps the files it hashed. Thread-safe.
class ContentHashes {
  public:
    std::string Of(const std::shared_ptr<const SourceFile>& file);

  private:
    std::mutex mu_;
    std::map<std::shared_ptr<const SourceFile>, std::string> hashes_;
};

// The client's side of one connection: answers kNeedFile from the compile's FileCache (which
// reads each file once) with its hash from `hashes` (shared by the connections), sending each
// content once. Thread-safe.
class FileServer {
  public:
    FileServer(hlsl::FileCache& files, ContentHashes& hashes) : files_(files), hashes_(hashes) {}
    // The kFile frame that answers a kNeedFile for `path`.
    std::string Answer(const std::string& path);
    // A new connection: the peer has nothing yet.
    void Reset();

  private:
    hlsl::FileCache& files_;
    ContentHashes& hashes_;
    std::mutex mu_;
    std::set<std::string> sent_;  // hashes whose content this connection has
};

// The worker's side: a FileCache loader that asks the client (through `ask`, which sends a
// kNeedFile and returns the decoded kFile, or nullopt when the exchange broke) and keeps what it
// was sent by hash. Thread-safe.
class RemoteFiles {
  public:
    using Ask = std::function<std::optional<FileAnswer>(const std::string& path)>;
    explicit RemoteFiles(Ask ask) : ask_(std::move(ask)) {}
    // The file's bytes, nullopt when the client has no such file. An answer that does not fit the
    // question (another path, a hash whose bytes never came) is taken as no file and kept in
    // error(): the caller ends the request as broken (nothing is thrown through glslang).
    std::optional<std::string> Load(const std::string& path);
    std::string error() const;
    hlsl::FileCache::Loader AsLoader() {
        return [this](const std::string& path) { return Load(path); };
    }

  private:
    Ask ask_;
    std::mutex exchange_mu_;  // held across a question and its answer
    mutable std::mutex mu_;
    std::map<std::string, std::string> by_hash_;
    std::string error_;
};

}  // namespace kiln::worker

#endif  // KILN_WORKER_FILE_EXCHANGE_H_
