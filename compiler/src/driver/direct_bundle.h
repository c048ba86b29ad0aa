// The text of the direct mode's manifest (driver/direct_cache.h): one cache entry per shader file
// name, holding every stage program of it that a compile preprocessed cleanly, so that a cold
// compile writes one manifest per shader instead of one per stage program.
//
//   kiln-direct 2
//   file\t<content hash>\t<tag>                                  (numbered from 0 in order)
//   include\t<1 local|0>\t<includer tag>\t<header>\t<resolved tag>   (numbered from 0)
//   set\t<file numbers, comma-separated>\t<include numbers>       (numbered from 0)
//   entry\t<direct key>\t<result key>\t<set number>
//
// A set is what one stage program depends on: every file its preprocessing read and every
// `#include` of its source and of those files, with what each resolved to. Lines come in the order
// above, and every number must name an earlier line of its kind, written without leading zeros:
// each manifest has one text. Anything else makes the whole manifest unreadable (a miss).
#ifndef KILN_DRIVER_DIRECT_BUNDLE_H_
#define KILN_DRIVER_DIRECT_BUNDLE_H_

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kiln::driver {

struct DirectBundle {
    struct Set {
        std::vector<uint32_t> files, includes;
        auto operator<=>(const Set&) const = default;
    };
    struct Entry {
        std::string direct, result;  // 32 hex digits each
        uint32_t set = 0;
    };
    std::vector<std::string> files;     // "<hash>\t<tag>"
    std::vector<std::string> includes;  // "<1|0>\t<includer tag>\t<header>\t<resolved tag>"
    std::vector<Set> sets;
    std::vector<Entry> entries;
};

// nullopt when `text` is not a well-formed manifest.
std::optional<DirectBundle> ParseDirectBundle(std::string_view text);
std::string SerializeDirectBundle(const DirectBundle& bundle);

// A manifest line's fields (split at tabs).
std::vector<std::string_view> SplitDirectFields(std::string_view line);

// True when `field` can be stored in a manifest line (no tab, no line break).
bool DirectStorable(std::string_view field);

}  // namespace kiln::driver

#endif  // KILN_DRIVER_DIRECT_BUNDLE_H_
