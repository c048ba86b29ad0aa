// The compile cache's direct mode (as ccache's): a stage program whose assembled source, options
// and every file its preprocessing read are unchanged is not preprocessed again. After a clean
// preprocess, the manifest of the shader's file name records, under the hash of the assembled
// source (the direct key), the compile cache's key of the result, the content hash of every file
// read, and where each `#include` of the source and of those files resolved
// (driver/direct_bundle.h). A lookup is a hit only when every file
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
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "driver/cache.h"
#include "driver/direct_bundle.h"
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

    // The compile cache key recorded under `key` in the manifest of `shader`'s file name, when
    // nothing it depends on changed; the files it read are registered in the compile's FileCache
    // (for depfiles).
    std::optional<std::string> Lookup(const std::string& key, const std::string& shader);

    // Notes a clean preprocess of `source` (the main file `shader`) that read `files_read` and
    // gave the compile cache key `result_key`, for Flush to write. Best effort.
    void Record(const std::string& key,
                const std::string& shader,
                const std::string& source,
                const std::vector<std::string>& files_read,
                const std::string& result_key);

    // Writes the manifest of each shader file name that has new records: this compile's programs
    // (recorded or hit), then earlier entries whose files still hold, up to a bound. One cache
    // entry per shader file name, not one per stage program. Best effort.
    void Flush();

  private:
    struct Stored {
        std::string direct, result;
        uint32_t set = 0;  // into sets_
    };
    // One shader file name's manifest: what earlier compiles stored, and this compile's.
    struct Bundle {
        std::string shader;       // the first shader path this compile used it with
        std::vector<Stored> old;  // as read, newest first
        std::unordered_map<std::string, size_t> old_by_key;
        std::vector<Stored> fresh;  // this compile's: hits and records
        std::unordered_set<std::string> fresh_keys;
        bool dirty = false;  // has records
    };
    // What one file read contributes to a set: its file line and its includes' lines.
    struct FileDeps {
        uint32_t file = 0;
        std::vector<uint32_t> includes;
    };

    // "S:rel" (shader's folder), "I<n>:rel" (-I), "T:rel" (templates), else "A:path".
    std::string Tag(const std::string& path, const std::string& shader) const;
    std::string Untag(const std::string& tag, const std::string& shader);  // memoized
    std::string UntagOnce(const std::string& tag, const std::string& shader) const;
    // `quiet`: read through probes_, so that the file stays out of the depfile.
    std::optional<std::string> ContentHash(const std::string& path, bool quiet = false);
    // The tag of what `#include header` in `includer` resolves to now ("" when nothing).
    std::string ResolvedTag(const IncludeDirective& d,
                            const std::string& includer,
                            const std::string& shader);

    std::string BundleKey(const std::string& shader) const;
    // The bundle of `shader`'s file name, read from the cache on first use. bundles_mu_ held.
    Bundle& BundleOf(const std::string& shader);
    // Interned lines and sets. bundles_mu_ held.
    uint32_t InternFile(const std::string& line);
    uint32_t InternInclude(const std::string& line);
    uint32_t InternSet(DirectBundle::Set set);
    // The include lines of `text` (the file `includer`): nullopt when one is not storable.
    std::optional<std::vector<std::string>> IncludeLines(const std::string& text,
                                                         const std::string& includer,
                                                         const std::string& shader);
    std::optional<FileDeps> DepsOf(const std::string& path, const std::string& shader);
    // Whether every file and #include of set `set` is as recorded, for `shader` (memoized);
    // `quiet` for an entry this compile does not use.
    bool SetHolds(uint32_t set, const std::string& shader, bool quiet = false);
    bool LineHolds(bool file, const std::string& line, const std::string& shader, bool quiet);
    // The manifest of `entries`, its lines numbered in order of first use.
    std::string Serialize(const std::vector<Stored>& entries);

    const Cache cache_;
    const hlsl::IncludePaths paths_;
    hlsl::FileCache& files_;  // the compile's: files really read
    hlsl::FileCache probes_;  // what resolution looks at, kept out of the depfile
    hlsl::Includer resolver_;
    std::mutex mu_;
    std::map<std::string, std::optional<std::string>> hashes_;        // path -> content hash
    std::map<std::string, std::optional<std::string>> quiet_hashes_;  // read through probes_
    // shader\0includer\0header<local> -> the tag of what it resolves to.
    std::map<std::string, std::string> resolved_;
    std::map<std::string, std::string> untagged_;  // shader\0tag -> path

    std::mutex bundles_mu_;  // guards everything below; never held while mu_ is taken
    std::map<std::string, Bundle> bundles_;  // by bundle key
    std::vector<std::string> file_lines_, include_lines_;
    std::unordered_map<std::string, uint32_t> file_ids_, include_ids_;
    std::vector<DirectBundle::Set> sets_;
    std::map<DirectBundle::Set, uint32_t> set_ids_;
    std::map<std::string, std::vector<int8_t>> set_holds_;  // shader -> per set: 0 unknown, 1, 2
    std::map<std::string, std::optional<FileDeps>> deps_;   // shader\0path -> its deps
};

}  // namespace kiln::driver

#endif  // KILN_DRIVER_DIRECT_CACHE_H_
