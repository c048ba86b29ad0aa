#include "driver/module_store.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>

#include "kiln/base/files.h"
#include "kiln/compile.h"

namespace kiln::driver {
namespace fs = std::filesystem;

namespace {

// Earlier compiles' modules kept beside this compile's: up to twice as many, at least this many
// (the direct mode's manifest keeps as many entries), and never past kMaxBundleBytes in all.
constexpr size_t kMinKeptModules = 4096;
constexpr uint64_t kMaxBundleBytes = uint64_t{512} << 20;

bool ReadAt(int fd, char* out, size_t n, uint64_t at) {
    while (n > 0) {
        const ssize_t got = pread(fd, out, n, static_cast<off_t>(at));
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            return false;
        out += got;
        n -= static_cast<size_t>(got);
        at += static_cast<uint64_t>(got);
    }
    return true;
}

std::optional<std::string> ReadBytes(int fd, size_t n, uint64_t at) {
    std::string out(n, '\0');
    if (!ReadAt(fd, out.data(), n, at))
        return std::nullopt;
    return out;
}

// The old file's entries; b.old stays empty when there is none or it is damaged.
void ReadIndex(int fd, uint64_t size, std::vector<ModuleEntry>& out) {
    const std::optional<std::string> header = ReadBytes(fd, kModuleHeaderBytes, 0);
    const std::optional<std::string> footer =
        size >= kModuleFooterBytes ? ReadBytes(fd, kModuleFooterBytes, size - kModuleFooterBytes)
                                   : std::nullopt;
    if (!header || !footer)
        return;
    const std::optional<ModuleFooter> f = ParseModuleFooter(*header, *footer, size);
    if (!f)
        return;
    const std::optional<std::string> index =
        ReadBytes(fd, size - kModuleFooterBytes - f->index_at, f->index_at);
    if (!index)
        return;
    if (std::optional<std::vector<ModuleEntry>> entries = ParseModuleIndex(*index, *f))
        out = std::move(*entries);
}

}  // namespace

ModuleStore::~ModuleStore() {
    for (auto& [name, b] : bundles_) {
        if (b.old_fd >= 0)
            close(b.old_fd);
        if (b.new_fd >= 0) {
            close(b.new_fd);
            unlink(b.temp.c_str());
        }
    }
}

std::string ModuleStore::PathFor(const std::string& shader) const {
    const std::string name = fs::path(shader).filename().string();
    return cache_.PathFor(HashKey({"kiln-module-bundle", ProducerVersion(), name}), kExt);
}

ModuleStore::Bundle& ModuleStore::BundleOf(const std::string& shader) {
    auto [it, fresh] = bundles_.try_emplace(fs::path(shader).filename().string());
    Bundle& b = it->second;
    if (!fresh)
        return b;
    b.path = PathFor(shader);
    // A regular file of bounded size only: not a link, a FIFO (no hang) or a directory.
    struct stat st {};
    if (lstat(b.path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
        return b;
    const int fd = open(b.path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return b;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) ||
        static_cast<uint64_t>(st.st_size) > Cache::kMaxPackEntryBytes) {
        close(fd);
        return b;
    }
    b.old_fd = fd;
    ReadIndex(fd, static_cast<uint64_t>(st.st_size), b.old);
    b.used_old.assign(b.old.size(), 0);
    for (size_t i = 0; i < b.old.size(); ++i)
        b.old_by_key.emplace(b.old[i].key, i);
    return b;
}

std::optional<std::string> ModuleStore::ReadOld(const Bundle& b, size_t i) {
    const ModuleEntry& e = b.old[i];
    std::optional<std::string> payload = ReadBytes(b.old_fd, e.size, e.offset);
    if (!payload || EntryHash(e.key, *payload) != e.hash)
        return std::nullopt;
    return payload;
}

std::optional<std::vector<uint32_t>> ModuleStore::Load(const std::string& key,
                                                       const std::string& shader) {
    if (!cache_.enabled())
        return std::nullopt;
    {
        std::lock_guard<std::mutex> lock(mu_);
        Bundle& own = BundleOf(shader);
        if (const auto it = own.old_by_key.find(key); it != own.old_by_key.end()) {
            if (std::optional<std::string> payload = ReadOld(own, it->second)) {
                own.used_old[it->second] = 1;
                return SpirvOfPayload(*payload);
            }
        }
        if (!opened_all_) {
            opened_all_ = true;
            for (const std::string& other : shaders_)
                BundleOf(other);
        }
        for (const auto& [name, b] : bundles_) {
            if (&b == &own)
                continue;
            if (const auto it = b.old_by_key.find(key); it != b.old_by_key.end()) {
                if (std::optional<std::string> payload = ReadOld(b, it->second))
                    return SpirvOfPayload(*payload);
            }
        }
    }
    return cache_.Load(key);  // an older Kiln's entry of its own
}

bool ModuleStore::Append(Bundle& b, const std::string& key, std::string_view payload) {
    if (b.fresh_keys.count(key))
        return true;
    if (b.failed || b.size + payload.size() > kMaxBundleBytes)
        return false;
    if (b.new_fd < 0) {
        std::error_code ec;
        fs::create_directories(fs::path(b.path).parent_path(), ec);
        for (int attempt = 0; attempt < 100 && b.new_fd < 0; ++attempt) {
            b.temp = base::TempName(b.path);
            b.new_fd = open(b.temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            if (b.new_fd < 0 && errno != EEXIST)
                break;
        }
        const std::string header = ModuleBundleHeader();
        if (b.new_fd < 0 || !base::WriteAll(b.new_fd, header)) {
            b.failed = true;
            return false;
        }
        b.size = header.size();
    }
    if (!base::WriteAll(b.new_fd, payload)) {
        b.failed = true;
        return false;
    }
    b.fresh_keys.insert(key);
    b.fresh.push_back(
        {key, b.size, static_cast<uint32_t>(payload.size()), EntryHash(key, payload)});
    b.size += payload.size();
    return true;
}

void ModuleStore::Store(const std::string& key,
                        const std::vector<uint32_t>& words,
                        const std::string& shader) {
    if (!cache_.enabled())
        return;
    const std::string payload = PayloadOfSpirv(words);
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (Append(BundleOf(shader), key, payload))
            return;
    }
    cache_.Store(key, words);  // past the file's bound, or it cannot be written: its own entry
}

void ModuleStore::Write(Bundle& b) {
    // The old file's modules this compile took come first, then the others, in their order;
    // entries of edited sources fall off the end.
    const size_t bound = std::max(2 * b.fresh.size(), kMinKeptModules);
    for (int pass = 0; pass < 2; ++pass) {
        for (size_t i = 0; i < b.old.size() && b.fresh.size() < bound && !b.failed; ++i) {
            if (b.used_old[i] != (pass == 0 ? 1 : 0) || b.fresh_keys.count(b.old[i].key) ||
                b.size + b.old[i].size > kMaxBundleBytes)
                continue;
            if (std::optional<std::string> payload = ReadOld(b, i))
                Append(b, b.old[i].key, *payload);
        }
    }
    const std::string tail = ModuleBundleTail(b.fresh, b.size);
    const bool written = !b.failed && base::WriteAll(b.new_fd, tail);
    close(b.new_fd);
    b.new_fd = -1;
    // A damaged entry that is not a regular file (a directory, a FIFO, a link) goes first.
    struct stat st {};
    std::error_code ec;
    if (written && lstat(b.path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        fs::remove_all(b.path, ec);
    if (!written || rename(b.temp.c_str(), b.path.c_str()) != 0)
        unlink(b.temp.c_str());
}

void ModuleStore::Flush() {
    std::lock_guard<std::mutex> lock(mu_);
    for (auto& [name, b] : bundles_) {
        if (b.new_fd >= 0)
            Write(b);
    }
}

}  // namespace kiln::driver
