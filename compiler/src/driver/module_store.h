// The compile cache's modules (optimized, pre-binding SPIR-V per unique stage program), one file
// per shader file name (driver/module_bundle.h), as the direct mode keeps one manifest per shader:
// a cold compile of 1,024 programs writes a file per shader, not 1,024, and creating a file is
// what a cache write costs most (0.1-0.3 ms of system time each on ext4, more after a cache was
// deleted).
//
// A compile's new modules go to a temporary file as they are compiled (nothing waits in memory);
// Flush adds the modules of the earlier file this compile took, then others of it up to a bound,
// and renames the file over the old one. A compile that stores nothing rewrites nothing.
// Concurrent compiles of one shader each write their own file and the last rename wins: the other
// compile's new modules are compiled again next time, never wrong.
//
// Entries are never trusted: the file must be a regular file of bounded size whose index adds up,
// an entry's hash must hold, its payload must start as SPIR-V, and the driver runs spirv-val over
// every module it takes (LoadCached). A damaged file is a miss for its entries, and the next
// compile that stores one replaces it. Modules of older Kilns, one file per key (Cache::Load),
// are still read.
#ifndef KILN_DRIVER_MODULE_STORE_H_
#define KILN_DRIVER_MODULE_STORE_H_

#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "driver/cache.h"
#include "driver/module_bundle.h"

namespace kiln::driver {

class ModuleStore {
  public:
    static constexpr const char* kExt = "kmod";

    // `shaders`: the shader files of this compile, whose module files a lookup searches.
    explicit ModuleStore(Cache cache, std::vector<std::string> shaders = {})
        : cache_(std::move(cache)), shaders_(std::move(shaders)) {}
    ~ModuleStore();  // closes the files; removes a temporary file Flush did not rename
    ModuleStore(const ModuleStore&) = delete;
    ModuleStore& operator=(const ModuleStore&) = delete;

    // The module stored under `key`: in the file of `shader`'s file name, in the file of another
    // shader of this compile, or in the key's own entry. A program that several shaders share is
    // stored in the file of whichever compiled it first, which depends on timing, so every
    // shader's file is searched, not only those this compile happened to read already.
    std::optional<std::vector<uint32_t>> Load(const std::string& key, const std::string& shader);
    // Adds a module to the file of `shader`'s file name (past its bound of 512 MiB, an entry of its
    // own). Best effort.
    void Store(const std::string& key,
               const std::vector<uint32_t>& words,
               const std::string& shader);
    // Writes the file of each shader file name that has new modules. Best effort.
    void Flush();

    // The file of `shader`'s file name in the cache (for tests).
    std::string PathFor(const std::string& shader) const;

  private:
    struct Bundle {
        std::string path;
        int old_fd = -1;               // the file as earlier compiles left it
        std::vector<ModuleEntry> old;  // its entries
        std::unordered_map<std::string, size_t> old_by_key;
        std::vector<char> used_old;  // per old entry: taken by this compile
        int new_fd = -1;             // this compile's temporary file
        std::string temp;
        uint64_t size = 0;  // bytes written to it
        std::vector<ModuleEntry> fresh;
        std::unordered_set<std::string> fresh_keys;
        bool failed = false;  // a write failed: nothing is renamed
    };

    // The bundle of `shader`'s file name, its old file's index read on first use. mu_ held.
    Bundle& BundleOf(const std::string& shader);
    // Old entry `i`'s payload when its hash holds.
    static std::optional<std::string> ReadOld(const Bundle& b, size_t i);
    // Appends a module to b's temporary file (created on first use); false when it is not there
    // (past the bound, or a write failed).
    bool Append(Bundle& b, const std::string& key, std::string_view payload);
    void Write(Bundle& b);  // the index, the footer and the rename

    const Cache cache_;
    const std::vector<std::string> shaders_;
    bool opened_all_ = false;                // every file of shaders_ read (mu_)
    std::mutex mu_;                          // guards bundles_ and every Bundle
    std::map<std::string, Bundle> bundles_;  // by the shader's file name
};

}  // namespace kiln::driver

#endif  // KILN_DRIVER_MODULE_STORE_H_
