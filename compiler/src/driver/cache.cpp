#include "driver/cache.h"

#include <sys/stat.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <string_view>

#include <xxhash.h>

#include "kiln/base/bytes.h"
#include "kiln/base/files.h"

namespace kiln::driver {
namespace fs = std::filesystem;

namespace {

constexpr uint32_t kEntryMagic = 0x4341434B;  // "KCAC"
// 2: a stage whose entry point does not exist is an error (version 1 cached an empty module).
// 3: the entry carries its key; the hash covers key and payload.
// 4: --precision half keeps image coordinates and levels in 32 bits (KeepImageOperandsFloat):
//    the same inputs compile to other modules. Bump it whenever that happens, so that entries
//    of an older kiln are misses.
// 5: entries hold bytes (a byte count, not a word count): SPIR-V or a direct-mode manifest; keys
//    are of the code without #line lines.
constexpr uint32_t kEntryVersion = 5;
constexpr uint32_t kSpirvMagic = 0x07230203;
constexpr int64_t kStaleTemporarySeconds = 24 * 60 * 60;

std::string HexOf(const XXH128_hash_t& h) {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string out(32, '0');
    for (int i = 0; i < 16; ++i) {
        out[size_t(15 - i)] = kDigits[(h.high64 >> (4 * i)) & 0xf];
        out[size_t(31 - i)] = kDigits[(h.low64 >> (4 * i)) & 0xf];
    }
    return out;
}

}  // namespace

uint64_t EntryHash(std::string_view key, std::string_view payload) {
    XXH64_state_t* h = XXH64_createState();
    XXH64_reset(h, 0);
    XXH64_update(h, key.data(), key.size());
    XXH64_update(h, payload.data(), payload.size());
    const uint64_t out = XXH64_digest(h);
    XXH64_freeState(h);
    return out;
}

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
    return HexOf(h);
}

namespace {

// Calls `piece` with each piece of CodeOf(reduced, false), in order: each line that is neither
// blank nor a #line line, without its indentation (which glslang's output varies with the lines
// around) and trailing spaces, then its line break.
template <class Piece>
void ForEachCodePiece(const std::string& reduced, Piece piece) {
    const char* s = reduced.data();
    const size_t n = reduced.size();
    size_t at = 0;
    while (at < n) {
        // Blank lines and indentation: one tight loop over them (most of a reduced text's lines
        // are the blank lines removed functions leave), eight line breaks at a time.
        constexpr uint64_t kEightBreaks = 0x0a0a0a0a0a0a0a0aull;
        uint64_t eight = 0;
        while (at + 8 <= n && (std::memcpy(&eight, s + at, 8), eight == kEightBreaks))
            at += 8;
        if (at == n)
            break;
        const char c = s[at];
        if (c == '\n' || c == ' ' || c == '\t' || c == '\r') {
            ++at;
            continue;
        }
        const void* nl = std::memchr(s + at, '\n', n - at);
        const size_t end = nl ? static_cast<size_t>(static_cast<const char*>(nl) - s) : n;
        if (reduced.compare(at, 5, "#line") != 0) {
            size_t last = end;
            while (last > at && (s[last - 1] == ' ' || s[last - 1] == '\t' || s[last - 1] == '\r'))
                --last;
            piece(std::string_view(s + at, last - at));
            piece(std::string_view("\n"));
        }
        at = end + 1;
    }
}

}  // namespace

std::string CodeOf(const std::string& reduced, bool debug_info) {
    if (debug_info)
        return reduced;
    std::string out;
    out.reserve(reduced.size());
    ForEachCodePiece(reduced, [&out](std::string_view p) { out += p; });
    return out;
}

// HashKey of the parts and CodeOf, with the code made in a buffer each thread keeps (one XXH3
// update over it, no allocation once the buffer has grown).
std::string HashKeyOfCode(const std::vector<std::string>& parts,
                          const std::string& reduced,
                          bool debug_info) {
    thread_local std::string code;
    code.clear();
    if (debug_info)
        code = reduced;
    else
        ForEachCodePiece(reduced, [](std::string_view p) { code += p; });
    XXH3_state_t* st = XXH3_createState();
    XXH3_128bits_reset(st);
    auto add = [st](std::string_view p) {
        const uint64_t size = p.size();
        XXH3_128bits_update(st, &size, sizeof size);
        XXH3_128bits_update(st, p.data(), p.size());
    };
    for (const std::string& p : parts)
        add(p);
    add(code);
    const XXH128_hash_t h = XXH3_128bits_digest(st);
    XXH3_freeState(st);
    if (code.capacity() > (size_t{16} << 20))
        std::string().swap(code);  // a rare huge program does not stay in memory
    return HexOf(h);
}

std::string Cache::PathFor(const std::string& key, const std::string& ext) const {
    return (fs::path(dir_) / key.substr(0, 2) / (key + "." + ext)).string();
}

// The largest entry of a kind.
uint64_t Cache::MaxBytes(const std::string& ext) {
    return ext == kPackExt ? kMaxPackEntryBytes : kMaxEntryBytes;
}

// Entry: magic, version, key length, key, payload length, XXH64 of (key + payload) as two u32s,
// then the payload.
std::optional<std::string> Cache::LoadBytes(const std::string& key, const std::string& ext) const {
    if (!enabled())
        return std::nullopt;
    const std::string path = PathFor(key, ext);
    struct stat st {};
    if (lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
        return std::nullopt;  // absent, or damaged: a link, a FIFO, a directory
    Result<std::string> read = base::ReadRegularFile(path, MaxBytes(ext), base::ReadAs::kCache);
    if (!read)
        return std::nullopt;
    std::string data = std::move(read).value();
    if (data.size() < 12 || base::LoadLe32(data, 0) != kEntryMagic ||
        base::LoadLe32(data, 4) != kEntryVersion)
        return std::nullopt;
    const uint32_t key_size = base::LoadLe32(data, 8);
    if (key_size != key.size() || data.size() < 24 + uint64_t{key_size} ||
        data.compare(12, key_size, key) != 0) {
        return std::nullopt;  // another entry's bytes under this name
    }
    const size_t at = 12 + key_size;
    const uint32_t bytes = base::LoadLe32(data, at);
    const size_t payload = at + 12;
    if (data.size() != payload + uint64_t{bytes})
        return std::nullopt;
    const uint64_t hash =
        uint64_t{base::LoadLe32(data, at + 4)} | uint64_t{base::LoadLe32(data, at + 8)} << 32;
    if (EntryHash(key, std::string_view(data).substr(payload)) != hash)
        return std::nullopt;
    return data.substr(payload);
}

std::optional<std::vector<uint32_t>> SpirvOfPayload(const std::string& bytes) {
    if (bytes.size() % 4 != 0 || bytes.size() < 20 || base::LoadLe32(bytes, 0) != kSpirvMagic)
        return std::nullopt;
    std::vector<uint32_t> out(bytes.size() / 4);
    for (size_t i = 0; i < out.size(); ++i)
        out[i] = base::LoadLe32(bytes, i * 4);
    return out;
}

std::string PayloadOfSpirv(const std::vector<uint32_t>& words) {
    std::string payload;
    payload.reserve(words.size() * 4);
    for (uint32_t w : words)
        base::AppendLe32(payload, w);
    return payload;
}

std::optional<std::vector<uint32_t>> Cache::Load(const std::string& key) const {
    const std::optional<std::string> bytes = LoadBytes(key, "spv");
    return bytes ? SpirvOfPayload(*bytes) : std::nullopt;
}

bool Cache::Store(const std::string& key, const std::vector<uint32_t>& words) const {
    return StoreBytes(key, "spv", PayloadOfSpirv(words));
}

bool Cache::StoreBytes(const std::string& key,
                       const std::string& ext,
                       const std::string& payload) const {
    if (!enabled() || payload.size() > MaxBytes(ext) / 2)
        return false;
    static std::once_flag cleaned;
    std::call_once(cleaned, [this] { RemoveStaleTemporaries(kStaleTemporarySeconds); });
    const uint64_t hash = EntryHash(key, payload);
    std::string data;
    base::AppendLe32(data, kEntryMagic);
    base::AppendLe32(data, kEntryVersion);
    base::AppendLe32(data, static_cast<uint32_t>(key.size()));
    data += key;
    base::AppendLe32(data, static_cast<uint32_t>(payload.size()));
    base::AppendLe32(data, static_cast<uint32_t>(hash));
    base::AppendLe32(data, static_cast<uint32_t>(hash >> 32));
    data += payload;

    const fs::path path = PathFor(key, ext);
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    // A damaged entry that is not a regular file (a directory, a FIFO, a link, which the writer
    // would follow) is removed first: the cache repairs itself.
    struct stat st {};
    if (lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        fs::remove_all(path, ec);
    base::WriteOptions options;
    options.durable = false;  // a torn entry fails its hash and is rebuilt
    return base::WriteFileAtomically(path.string(), data, options).ok();
}

size_t Cache::RemoveStaleTemporaries(int64_t age_seconds) const {
    if (!enabled())
        return 0;
    size_t removed = 0;
    std::error_code ec;
    const auto now = fs::file_time_type::clock::now();
    for (fs::recursive_directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
        if (it.depth() > 1) {
            it.disable_recursion_pending();
            continue;
        }
        const std::string name = it->path().filename().string();
        if (name.find(".tmp.") == std::string::npos || !it->is_regular_file(ec))
            continue;
        const auto age =
            std::chrono::duration_cast<std::chrono::seconds>(now - it->last_write_time(ec));
        if (!ec && age.count() > age_seconds && fs::remove(it->path(), ec))
            ++removed;
    }
    return removed;
}

}  // namespace kiln::driver
