#include "vk/pipeline_cache.h"

#include <unistd.h>
#include <xxhash.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "kiln/base/files.h"
#include "kiln/pack/records.h"

namespace kiln::vk {
namespace {

constexpr std::array<char, 4> kMagic = {'K', 'P', 'L', 'C'};
constexpr uint32_t kVersion = 1;

}  // namespace

std::vector<uint8_t> EncodePipelineCacheFile(const Context& c, std::span<const uint8_t> data) {
    pack::ByteWriter w;
    w.Put(kMagic);
    w.Put(kVersion);
    w.Put(c.properties.vendorID);
    w.Put(c.properties.deviceID);
    w.Put(c.properties.driverVersion);
    w.PutBytes({c.properties.pipelineCacheUUID, VK_UUID_SIZE});
    w.Put(uint32_t{0});
    w.Put(uint64_t{data.size()});
    w.Put(uint64_t{XXH64(data.data(), data.size(), 0)});
    w.PutBytes(data);
    return std::move(w.bytes());
}

std::string CheckPipelineCacheFile(const Context& c,
                                   std::span<const uint8_t> file,
                                   std::span<const uint8_t>& data) {
    if (file.size() < kPipelineCacheHeaderSize) {
        return "shorter than its header";
    }
    pack::ByteReader r(file.first(kPipelineCacheHeaderSize));
    std::array<char, 4> magic{};
    uint32_t version = 0, vendor = 0, device = 0, driver = 0, reserved = 0;
    uint64_t size = 0, hash = 0;
    r.Get(magic);
    r.Get(version);
    r.Get(vendor);
    r.Get(device);
    r.Get(driver);
    if (magic != kMagic) {
        return "not a kiln pipeline cache";
    }
    if (version != kVersion) {
        return "cache format version " + std::to_string(version) + ", expected " +
               std::to_string(kVersion);
    }
    if (vendor != c.properties.vendorID || device != c.properties.deviceID ||
        driver != c.properties.driverVersion ||
        std::memcmp(file.data() + 20, c.properties.pipelineCacheUUID, VK_UUID_SIZE) != 0) {
        return "written by another device or driver";
    }
    pack::ByteReader tail(file.subspan(36, 20));
    tail.Get(reserved);
    tail.Get(size);
    tail.Get(hash);
    if (size != file.size() - kPipelineCacheHeaderSize) {
        return "data size does not match the file";
    }
    data = file.subspan(kPipelineCacheHeaderSize);
    if (XXH64(data.data(), data.size(), 0) != hash) {
        return "checksum mismatch";
    }
    return {};
}

Status CreatePipelineCache(const Context& c,
                           const std::string& path,
                           VkPipelineCache& out,
                           std::string& note) {
    std::vector<uint8_t> file;
    std::span<const uint8_t> data;
    std::error_code ec;
    if (!path.empty() && std::filesystem::exists(path, ec)) {
        constexpr uint64_t kMaxPipelineCacheBytes = uint64_t{1} << 30;
        Result<std::string> read =
            base::ReadRegularFile(path, kMaxPipelineCacheBytes, base::ReadAs::kCache);
        if (read)
            file.assign(read.value().begin(), read.value().end());
        note = read ? CheckPipelineCacheFile(c, file, data) : read.error().message;
        if (!note.empty()) {
            note = "pipeline cache '" + path + "' ignored: " + note;
            data = {};
        }
    }
    VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
    info.initialDataSize = data.size();
    info.pInitialData = data.empty() ? nullptr : data.data();
    if (VkResult r = vkCreatePipelineCache(c.device, &info, nullptr, &out); r != VK_SUCCESS) {
        return VkError("cannot create a pipeline cache", r);
    }
    return {};
}

std::string PipelineCacheUnsavable(const std::string& path) {
    if (std::string kind = base::NotRegularFileKind(path); !kind.empty())
        return "'" + path + "' is " + kind;
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    const std::string folder = dir.empty() ? std::string(".") : dir.string();
    if (access(folder.c_str(), W_OK | X_OK) != 0)
        return "its folder '" + folder + "' cannot be written (" + std::strerror(errno) + ")";
    return "";
}

Status SavePipelineCache(const Context& c, VkPipelineCache cache, const std::string& path) {
    size_t size = 0;
    vkGetPipelineCacheData(c.device, cache, &size, nullptr);
    std::vector<uint8_t> data(size);
    if (VkResult r = vkGetPipelineCacheData(c.device, cache, &size, data.data()); r != VK_SUCCESS) {
        return VkError("cannot read the pipeline cache", r);
    }
    data.resize(size);
    const std::vector<uint8_t> file = EncodePipelineCacheFile(c, data);
    if (const Status written = base::WriteFileAtomically(path, file); !written.ok()) {
        return Error{DiagCode::kRenderFailed, written.error().message};
    }
    return {};
}

}  // namespace kiln::vk
