#include "driver/cache.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <xxhash.h>

namespace kiln::driver {
namespace fs = std::filesystem;

namespace {

constexpr uint32_t kEntryMagic = 0x4341434B;  // "KCAC"
// 2: a stage whose entry point does not exist is an error (version 1 cached an empty module).
constexpr uint32_t kEntryVersion = 2;

void PutU32(std::string& s, uint32_t x) {
    for (int i = 0; i < 4; ++i)
        s += static_cast<char>(x >> (8 * i));
}
uint32_t GetU32(const std::string& s, size_t at) {
    uint32_t x = 0;
    for (int i = 0; i < 4; ++i)
        x |= uint32_t(uint8_t(s[at + i])) << (8 * i);
    return x;
}

}  // namespace

std::string HashKey(const std::vector<std::string>& parts) {
    XXH3_state_t* st = XXH3_createState();
    XXH3_128bits_reset(st);
    for (const std::string& p : parts) {
        const uint64_t n = p.size();
        XXH3_128bits_update(st, &n, sizeof n);
        XXH3_128bits_update(st, p.data(), p.size());
    }
    const XXH128_hash_t h = XXH3_128bits_digest(st);
    XXH3_freeState(st);
    char buf[33];
    std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                  static_cast<unsigned long long>(h.low64));
    return buf;
}

std::string Cache::PathFor(const std::string& key) const {
    return (fs::path(dir_) / key.substr(0, 2) / (key + ".spv")).string();
}

std::optional<std::vector<uint32_t>> Cache::Load(const std::string& key) const {
    if (!enabled())
        return std::nullopt;
    std::ifstream in(PathFor(key), std::ios::binary);
    if (!in)
        return std::nullopt;
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (data.size() < 20 || GetU32(data, 0) != kEntryMagic || GetU32(data, 4) != kEntryVersion) {
        return std::nullopt;
    }
    const uint32_t words = GetU32(data, 8);
    if (data.size() != 20 + uint64_t{words} * 4 || words == 0)
        return std::nullopt;
    const uint64_t hash = uint64_t{GetU32(data, 12)} | uint64_t{GetU32(data, 16)} << 32;
    if (XXH64(data.data() + 20, data.size() - 20, 0) != hash)
        return std::nullopt;
    std::vector<uint32_t> out(words);
    for (uint32_t i = 0; i < words; ++i)
        out[i] = GetU32(data, 20 + size_t{i} * 4);
    return out;
}

bool Cache::Store(const std::string& key, const std::vector<uint32_t>& words) const {
    if (!enabled())
        return false;
    std::string data;
    PutU32(data, kEntryMagic);
    PutU32(data, kEntryVersion);
    PutU32(data, static_cast<uint32_t>(words.size()));
    std::string payload;
    for (uint32_t w : words)
        PutU32(payload, w);
    const uint64_t hash = XXH64(payload.data(), payload.size(), 0);
    PutU32(data, static_cast<uint32_t>(hash));
    PutU32(data, static_cast<uint32_t>(hash >> 32));
    data += payload;

    const fs::path path = PathFor(key);
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    static std::atomic<uint64_t> counter{0};
    const fs::path tmp =
        path.string() + ".tmp." + std::to_string(getpid()) + "." + std::to_string(counter++);
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out)
            return false;
        out.write(data.data(), static_cast<std::streamsize>(data.size()));
        if (!out) {
            fs::remove(tmp, ec);
            return false;
        }
    }
    fs::rename(tmp, path, ec);  // atomic on POSIX: readers see the old entry or the new one
    if (ec)
        fs::remove(tmp, ec);
    return !ec;
}

}  // namespace kiln::driver
