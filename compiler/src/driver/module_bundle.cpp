#include "driver/module_bundle.h"

#include <unordered_set>

#include <xxhash.h>

#include "driver/cache.h"
#include "kiln/base/bytes.h"

namespace kiln::driver {
namespace {

constexpr uint32_t kMagic = 0x444F4D4B;     // "KMOD"
constexpr uint32_t kEndMagic = 0x4B4D4F44;  // "DOMK"
constexpr uint32_t kVersion = 1;
constexpr size_t kKeyBytes = 32;

bool IsKey(std::string_view key) {
    if (key.size() != kKeyBytes)
        return false;
    for (char c : key) {
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f')))
            return false;
    }
    return true;
}

}  // namespace

std::string ModuleBundleHeader() {
    std::string out;
    base::AppendLe32(out, kMagic);
    base::AppendLe32(out, kVersion);
    return out;
}

std::string ModuleBundleTail(const std::vector<ModuleEntry>& entries, uint64_t index_at) {
    std::string index;
    index.reserve(entries.size() * kModuleIndexEntryBytes);
    for (const ModuleEntry& e : entries) {
        index += e.key;
        base::AppendLe64(index, e.offset);
        base::AppendLe32(index, e.size);
        base::AppendLe64(index, e.hash);
    }
    std::string out = index;
    base::AppendLe32(out, static_cast<uint32_t>(entries.size()));
    base::AppendLe64(out, index_at);
    base::AppendLe64(out, XXH64(index.data(), index.size(), 0));
    base::AppendLe32(out, kEndMagic);
    return out;
}

std::optional<ModuleFooter> ParseModuleFooter(std::string_view header,
                                              std::string_view footer,
                                              uint64_t file_size) {
    if (header.size() != kModuleHeaderBytes || footer.size() != kModuleFooterBytes ||
        file_size < kModuleHeaderBytes + kModuleFooterBytes ||
        base::LoadLe32(header, 0) != kMagic || base::LoadLe32(header, 4) != kVersion ||
        base::LoadLe32(footer, 20) != kEndMagic)
        return std::nullopt;
    ModuleFooter f;
    f.count = base::LoadLe32(footer, 0);
    f.index_at = base::LoadLe64(footer, 4);
    f.index_hash = base::LoadLe64(footer, 12);
    // The index ends where the footer starts (no overflow: count < 2^32, sizes < 2^64 / 64).
    const uint64_t index_end = file_size - kModuleFooterBytes;
    if (f.index_at < kModuleHeaderBytes || f.index_at > index_end ||
        index_end - f.index_at != uint64_t{f.count} * kModuleIndexEntryBytes)
        return std::nullopt;
    return f;
}

std::optional<std::vector<ModuleEntry>> ParseModuleIndex(std::string_view index,
                                                         const ModuleFooter& footer) {
    if (index.size() != uint64_t{footer.count} * kModuleIndexEntryBytes ||
        XXH64(index.data(), index.size(), 0) != footer.index_hash)
        return std::nullopt;
    std::vector<ModuleEntry> out(footer.count);
    std::unordered_set<std::string_view> keys;
    for (size_t i = 0; i < out.size(); ++i) {
        const size_t at = i * kModuleIndexEntryBytes;
        const std::string_view key = index.substr(at, kKeyBytes);
        ModuleEntry& e = out[i];
        e.offset = base::LoadLe64(index, at + 32);
        e.size = base::LoadLe32(index, at + 40);
        e.hash = base::LoadLe64(index, at + 44);
        if (!IsKey(key) || !keys.insert(key).second || e.offset < kModuleHeaderBytes ||
            e.offset > footer.index_at || e.size > footer.index_at - e.offset)
            return std::nullopt;
        e.key = std::string(key);
    }
    return out;
}

std::string BuildModuleBundle(const std::vector<std::pair<std::string, std::string>>& modules) {
    std::string out = ModuleBundleHeader();
    std::vector<ModuleEntry> entries;
    for (const auto& [key, payload] : modules) {
        entries.push_back(
            {key, out.size(), static_cast<uint32_t>(payload.size()), EntryHash(key, payload)});
        out += payload;
    }
    out += ModuleBundleTail(entries, out.size());
    return out;
}

std::optional<std::vector<std::pair<std::string, std::string>>> ReadModuleBundle(
    std::string_view bytes) {
    if (bytes.size() < kModuleHeaderBytes + kModuleFooterBytes)
        return std::nullopt;
    const std::optional<ModuleFooter> footer =
        ParseModuleFooter(bytes.substr(0, kModuleHeaderBytes),
                          bytes.substr(bytes.size() - kModuleFooterBytes), bytes.size());
    if (!footer)
        return std::nullopt;
    const std::optional<std::vector<ModuleEntry>> entries = ParseModuleIndex(
        bytes.substr(footer->index_at, bytes.size() - kModuleFooterBytes - footer->index_at),
        *footer);
    if (!entries)
        return std::nullopt;
    std::vector<std::pair<std::string, std::string>> out;
    for (const ModuleEntry& e : *entries) {
        const std::string_view payload = bytes.substr(e.offset, e.size);
        if (EntryHash(e.key, payload) == e.hash)
            out.emplace_back(e.key, std::string(payload));
    }
    return out;
}

}  // namespace kiln::driver
