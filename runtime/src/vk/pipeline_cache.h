// A VkPipelineCache persisted to disk behind a header of Kiln's own, so stale or foreign bytes
// never reach the driver:
//   offset size
//   0      4    magic "KPLC"
//   4      4    format version (1)
//   8      4    vendorID       12 4 deviceID      16 4 driverVersion
//   20     16   pipelineCacheUUID
//   36     4    reserved (0)
//   40     8    data size in bytes
//   48     8    XXH64 of the data
//   56     ...  the driver's cache data
// All little-endian. A file that fails any check is ignored (and reported); saving writes a
// temporary file and renames it over the old one.
#ifndef KILN_RUNTIME_VK_PIPELINE_CACHE_H_
#define KILN_RUNTIME_VK_PIPELINE_CACHE_H_

#include <span>
#include <string>
#include <vector>

#include "vk/context.h"

namespace kiln::vk {

inline constexpr uint32_t kPipelineCacheHeaderSize = 56;

// Empty when the bytes are a valid cache for this device; otherwise why they are not.
std::string CheckPipelineCacheFile(const Context& c,
                                   std::span<const uint8_t> file,
                                   std::span<const uint8_t>& data);

// Creates the cache, seeded from `path` when that file is valid. `note` says why a present
// file was not used.
Status CreatePipelineCache(const Context& c,
                           const std::string& path,
                           VkPipelineCache& out,
                           std::string& note);
Status SavePipelineCache(const Context& c, VkPipelineCache cache, const std::string& path);
// Why the cache at `path` could not be saved when the renderer ends (its folder is missing or not
// writable, the path is a folder or device); "" when it can be. Said up front as a warning
// (K0024): the save itself happens in a destructor, which has no one to tell.
std::string PipelineCacheUnsavable(const std::string& path);
std::vector<uint8_t> EncodePipelineCacheFile(const Context& c, std::span<const uint8_t> data);

}  // namespace kiln::vk

#endif  // KILN_RUNTIME_VK_PIPELINE_CACHE_H_
