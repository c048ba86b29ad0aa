// The content-addressed compile cache: optimized (pre-binding) SPIR-V per unique stage program,
// keyed by a hash of the reduced text, stage, entry point, options and the versions of Kiln,
// glslang and SPIRV-Tools. Entries are written to a temporary file and renamed, so concurrent
// kiln processes never see a partial entry; a damaged entry (checked by length and hash) is a
// miss.
#ifndef KILN_DRIVER_CACHE_H_
#define KILN_DRIVER_CACHE_H_

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace kiln::driver {

class Cache {
  public:
    explicit Cache(std::string dir) : dir_(std::move(dir)) {}
    bool enabled() const { return !dir_.empty(); }

    std::optional<std::vector<uint32_t>> Load(const std::string& key) const;
    // Best effort: false when the entry cannot be written (the compile goes on).
    bool Store(const std::string& key, const std::vector<uint32_t>& words) const;

  private:
    std::string PathFor(const std::string& key) const;
    std::string dir_;
};

// 32 hex digits (XXH3 128-bit) of the parts, each length-prefixed.
std::string HashKey(const std::vector<std::string>& parts);

}  // namespace kiln::driver

#endif  // KILN_DRIVER_CACHE_H_
