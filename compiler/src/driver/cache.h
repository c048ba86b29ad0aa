// The content-addressed compile cache's entries of their own: the direct mode's manifests
// (driver/direct_cache.h), whole packs (pack_cache.cpp), and modules as older Kilns stored them
// and as a compile stores one past its shader's file of modules (driver/module_store.h, where
// modules live now). A module's key is a hash of the reduced text's code (without #line lines,
// blank lines and indentation unless -g, so that neither the folder nor a line shift elsewhere
// changes it), stage, entry point, options and the versions of Kiln, glslang and SPIRV-Tools.
// Entries are written to a unique temporary file and renamed, so concurrent kiln processes never
// see a partial entry.
//
// The cache is never trusted: an entry carries its own key and a hash of key and payload, must be
// a regular file (not a link, FIFO or directory) of bounded size, and a module must hold a SPIR-V
// header; anything else is a miss, and the compile that follows replaces the entry. (The driver
// also runs spirv-val over every module it takes.) Temporary files left by killed compiles are
// removed once a day old.
#ifndef KILN_DRIVER_CACHE_H_
#define KILN_DRIVER_CACHE_H_

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kiln::driver {

class Cache {
  public:
    // The largest entry read (a stage of a Unity shader is a few hundred KiB), and the largest
    // whole-pack entry (a pack of 10,000 variants is about 55 MB).
    static constexpr uint64_t kMaxEntryBytes = uint64_t{64} << 20;
    static constexpr uint64_t kMaxPackEntryBytes = uint64_t{1} << 30;
    static constexpr const char* kPackExt = "kpack";  // whole packs (pack_cache.cpp)

    explicit Cache(std::string dir) : dir_(std::move(dir)) {}
    bool enabled() const { return !dir_.empty(); }

    std::optional<std::vector<uint32_t>> Load(const std::string& key) const;
    // Best effort: false when the entry cannot be written (the compile goes on).
    bool Store(const std::string& key, const std::vector<uint32_t>& words) const;
    // Any bytes under a key, in files named `<key>.<ext>` (a manifest: "man").
    std::optional<std::string> LoadBytes(const std::string& key, const std::string& ext) const;
    bool StoreBytes(const std::string& key, const std::string& ext, const std::string& bytes) const;
    static uint64_t MaxBytes(const std::string& ext);

    // Removes "*.tmp.*" files under the cache older than `age_seconds`; returns how many.
    size_t RemoveStaleTemporaries(int64_t age_seconds) const;

    std::string PathFor(const std::string& key, const std::string& ext = "spv") const;

  private:
    std::string dir_;
};

// A module's payload: its words little-endian; back to words only when it holds a SPIR-V header.
std::string PayloadOfSpirv(const std::vector<uint32_t>& words);
std::optional<std::vector<uint32_t>> SpirvOfPayload(const std::string& bytes);

// The hash an entry carries: XXH64 of its key, then its payload (a file of modules keeps one per
// module, driver/module_bundle.h).
uint64_t EntryHash(std::string_view key, std::string_view payload);

// 32 hex digits (XXH3 128-bit) of the parts, each length-prefixed.
std::string HashKey(const std::vector<std::string>& parts);

// What of a reduced stage text the compile cache keys: the text without its `#line` lines, blank
// lines (removed functions leave blank lines) and indentation, or all of it with debug info,
// whose SPIR-V holds the file names and lines.
std::string CodeOf(const std::string& reduced, bool debug_info);

// HashKey of `parts` and CodeOf(reduced, debug_info), without making CodeOf's copy.
std::string HashKeyOfCode(const std::vector<std::string>& parts,
                          const std::string& reduced,
                          bool debug_info);

}  // namespace kiln::driver

#endif  // KILN_DRIVER_CACHE_H_
