// Files read during a compile (shaders and includes), shared by all compile threads: each file is
// read once, kept for diagnostics, and recorded for the depfile.
#ifndef KILN_HLSL_FILE_CACHE_H_
#define KILN_HLSL_FILE_CACHE_H_

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "kiln/source.h"

namespace kiln::hlsl {

class FileCache {
  public:
    // The file at `path`, or null when it does not exist or cannot be read. Thread-safe.
    std::shared_ptr<const SourceFile> Get(const std::string& path);
    // Registers a file already read elsewhere (the .shader files).
    void Put(std::shared_ptr<const SourceFile> file);
    // Every file successfully read, sorted by path.
    std::vector<std::shared_ptr<const SourceFile>> Files() const;

  private:
    mutable std::mutex mu_;
    std::map<std::string, std::shared_ptr<const SourceFile>> files_;  // null: tried, absent
};

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_FILE_CACHE_H_
