// The compile cache's modules of one shader file name, in one file (driver/module_store.h): a
// cold compile writes one file per shader instead of one per unique stage program.
//
//   "KMOD" u32, version u32                        (8 bytes)
//   payloads, back to back
//   index: per entry, key (32 ASCII hex digits), offset u64, size u32,
//          hash u64 (EntryHash: XXH64 of key then payload)    (52 bytes each)
//   footer: count u32, index offset u64, XXH64 of the index u64, "DOMK" u32   (24 bytes)
//
// Little-endian. The footer is read first, then the index; a payload only when its key is asked
// for, and it is used only when its hash holds. Anything that does not add up (an index that does
// not end where the footer starts, a payload outside the payload area, a key that is not 32 lower
// hex digits, a key twice) makes the whole file unreadable: a miss for all its entries.
#ifndef KILN_DRIVER_MODULE_BUNDLE_H_
#define KILN_DRIVER_MODULE_BUNDLE_H_

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace kiln::driver {

struct ModuleEntry {
    std::string key;
    uint64_t offset = 0;
    uint32_t size = 0;
    uint64_t hash = 0;
};

constexpr size_t kModuleHeaderBytes = 8;
constexpr size_t kModuleIndexEntryBytes = 52;
constexpr size_t kModuleFooterBytes = 24;

struct ModuleFooter {
    uint32_t count = 0;
    uint64_t index_at = 0;
    uint64_t index_hash = 0;
};

std::string ModuleBundleHeader();
// The index and footer of `entries`, whose payloads end at `index_at`.
std::string ModuleBundleTail(const std::vector<ModuleEntry>& entries, uint64_t index_at);

// The footer of a file of `file_size` bytes whose last kModuleFooterBytes are `footer`, and the
// header (its first kModuleHeaderBytes); nullopt when they do not fit that size.
std::optional<ModuleFooter> ParseModuleFooter(std::string_view header,
                                              std::string_view footer,
                                              uint64_t file_size);
// The entries of `index` (the footer's index bytes), each inside the payload area.
std::optional<std::vector<ModuleEntry>> ParseModuleIndex(std::string_view index,
                                                         const ModuleFooter& footer);

// A whole bundle in memory, for tests and the fuzzer: (key, payload) in order.
std::string BuildModuleBundle(const std::vector<std::pair<std::string, std::string>>& modules);
// Its entries' (key, payload) whose hashes hold; nullopt when the file is unreadable.
std::optional<std::vector<std::pair<std::string, std::string>>> ReadModuleBundle(
    std::string_view bytes);

}  // namespace kiln::driver

#endif  // KILN_DRIVER_MODULE_BUNDLE_H_
