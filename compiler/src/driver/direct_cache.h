// The compile cache's direct mode (as ccache's): a stage program whose assembled source, options
// and every file its preprocessing read are unchanged is not preprocessed again. After a clean
// preprocess, a manifest under the hash of the assembled source (the direct key) records the
// compile cache's key of the result, the content hash of every file read, and where each
// `#include` of the source and of those files resolved. A lookup is a hit only when every file
// still has its hash and every `#include` resolves to the same file: a header added earlier on
// the search path, or a changed -I, is a miss.
//
// Keys and manifests name files relative to their root (the shader's folder, each -I folder, the
// templates), never by absolute path: the same sources in another folder hit the same entries.
// An `#include` whose name is a macro makes the program uncacheable in direct mode (it is still
// cached by its preprocessed text).
#ifndef KILN_DRIVER_DIRECT_CACHE_H_
#define KILN_DRIVER_DIRECT_CACHE_H_

#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "driver/cache.h"
#include "hlsl/file_cache.h"
#include "hlsl/includer.h"

namespace kiln::driver {

struct IncludeDirective {
    std::string header;
    bool local = false;  // "header", not <header>
};

// The `#include` lines of a text: nullopt when one names its file through a macro.
std::optional<std::vector<IncludeDirective>> IncludeDirectives(const std::string& text);

class DirectCache {
  public:
    DirectCache(Cache cache, hlsl::IncludePaths paths, hlsl::FileCache& files);

    // The direct key of a stage program: `parts` (versions, options, stage, entry) and the
    // assembled source, with the shader's path in its #line lines reduced to the file name.
    std::string KeyFor(const std::vector<std::string>& parts,
                       const std::string& source,
                       const std::string& shader) const;

    // The compile cache key recorded under `key`, when nothing it depends on changed; the files
    // it read are registered in the compile's FileCache (for depfiles).
    std::optional<std::string> Lookup(const std::string& key, const std::string& shader);

    // Records a clean preprocess of `source` (the main file `shader`) that read `files_read` and
    // gave the compile cache key `result_key`. Best effort.
    void Record(const std::string& key,
                const std::string& shader,
                const std::string& source,
                const std::vector<std::string>& files_read,
                const std::string& result_key);

  private:
    // "S:rel" (shader's folder), "I<n>:rel" (-I), "T:rel" (templates), else "A:path".
    std::string Tag(const std::string& path, const std::string& shader) const;
    std::string Untag(const std::string& tag, const std::string& shader);  // memoized
    std::string UntagOnce(const std::string& tag, const std::string& shader) const;
    std::optional<std::string> ContentHash(const std::string& path);
    // The tag of what `#include header` in `includer` resolves to now ("" when nothing).
    std::string ResolvedTag(const IncludeDirective& d,
                            const std::string& includer,
                            const std::string& shader);

    const Cache cache_;
    const hlsl::IncludePaths paths_;
    hlsl::FileCache& files_;  // the compile's: files really read
    hlsl::FileCache probes_;  // what resolution looks at, kept out of the depfile
    hlsl::Includer resolver_;
    std::mutex mu_;
    std::map<std::string, std::optional<std::string>> hashes_;  // path -> content hash
    // shader\0includer\0header<local> -> the tag of what it resolves to.
    std::map<std::string, std::string> resolved_;
    std::map<std::string, std::string> untagged_;  // shader\0tag -> path
};

}  // namespace kiln::driver

#endif  // KILN_DRIVER_DIRECT_CACHE_H_
