#include "kiln/base/files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <utility>

namespace kiln::base {
namespace fs = std::filesystem;

namespace {

// The most standard input Kiln keeps, whatever the caller's limit (a pack or a shader).
constexpr uint64_t kMaxStandardInputBytes = uint64_t{4} << 30;

std::string Errno(const std::string& what) {
    return what + ": " + std::strerror(errno);
}

std::string KindOf(mode_t mode) {
    if (S_ISDIR(mode))
        return "a directory";
    if (S_ISFIFO(mode))
        return "a FIFO";
    if (S_ISCHR(mode))
        return "a character device";
    if (S_ISBLK(mode))
        return "a block device";
    if (S_ISSOCK(mode))
        return "a socket";
    return S_ISREG(mode) ? "" : "not a regular file";
}

class Fd {
  public:
    explicit Fd(int fd) : fd_(fd) {}
    ~Fd() {
        if (fd_ >= 0)
            close(fd_);
    }
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    int get() const { return fd_; }
    int release() { return std::exchange(fd_, -1); }

  private:
    int fd_;
};

// The file an output path names: a symbolic link's target (followed to the end), else the path.
Result<std::string> OutputTarget(const std::string& path) {
    std::string target = path;
    for (int hops = 0; hops < 40; ++hops) {
        struct stat st {};
        if (lstat(target.c_str(), &st) != 0)
            return target;  // does not exist (yet): it will be created
        if (!S_ISLNK(st.st_mode))
            return target;
        std::error_code ec;
        const fs::path link = fs::read_symlink(target, ec);
        if (ec)
            return Error{DiagCode::kCannotWriteFile,
                         "cannot read the symbolic link '" + target + "': " + ec.message()};
        target = (link.is_absolute() ? link : fs::path(target).parent_path() / link).string();
    }
    return Error{DiagCode::kCannotWriteFile, "'" + path + "' is a loop of symbolic links"};
}

// Standard input, read to its end (or past `max_bytes`) the first time it is asked for.
Result<std::string> ReadStandardInput(uint64_t max_bytes) {
    static std::mutex mu;
    static std::optional<std::string> text;
    static std::string error;
    std::lock_guard<std::mutex> lock(mu);
    if (!text && error.empty()) {
        std::string out;
        char buffer[65536];
        for (;;) {
            const ssize_t n = read(STDIN_FILENO, buffer, sizeof buffer);
            if (n < 0 && errno == EINTR)
                continue;
            if (n < 0) {
                error = Errno("cannot read standard input");
                break;
            }
            if (n == 0)
                break;
            out.append(buffer, static_cast<size_t>(n));
            if (out.size() > kMaxStandardInputBytes) {
                error = "standard input is larger than the limit of " +
                        std::to_string(kMaxStandardInputBytes) + " bytes";
                break;
            }
        }
        if (error.empty())
            text = std::move(out);
    }
    if (!error.empty())
        return Error{DiagCode::kCannotReadFile, error};
    if (text->size() > max_bytes) {
        return Error{DiagCode::kCannotReadFile, "standard input is larger than the limit of " +
                                                    std::to_string(max_bytes) + " bytes"};
    }
    return *text;
}

}  // namespace

std::string NotRegularFileKind(const std::string& path) {
    struct stat st {};
    if (stat(path.c_str(), &st) != 0)
        return "";
    return KindOf(st.st_mode);
}

namespace {

struct InputGuard {
    std::mutex mu;
    bool on = false;
    std::map<std::pair<dev_t, ino_t>, std::string> files;  // read so far, with a name for each
};

InputGuard& Guard() {
    static InputGuard guard;
    return guard;
}

void Remember(const struct stat& st, const std::string& path) {
    InputGuard& g = Guard();
    std::lock_guard<std::mutex> lock(g.mu);
    if (g.on)
        g.files.emplace(std::pair{st.st_dev, st.st_ino}, path);
}

// The name of a file read under the guard that `st` is; "" for none.
std::string ReadName(const struct stat& st) {
    InputGuard& g = Guard();
    std::lock_guard<std::mutex> lock(g.mu);
    const auto it = g.files.find({st.st_dev, st.st_ino});
    return it == g.files.end() ? std::string() : it->second;
}

}  // namespace

void GuardInputFiles() {
    InputGuard& g = Guard();
    std::lock_guard<std::mutex> lock(g.mu);
    g.on = true;
}

void ForgetInputFiles() {
    InputGuard& g = Guard();
    std::lock_guard<std::mutex> lock(g.mu);
    g.files.clear();
}

void NoteInputFile(const std::string& path) {
    struct stat st {};
    if (path != kStandardStream && stat(path.c_str(), &st) == 0)
        Remember(st, path);
}

Result<std::string> ReadRegularFile(const std::string& path, uint64_t max_bytes, ReadAs as) {
    if (path == kStandardStream)
        return ReadStandardInput(max_bytes);
    // O_NONBLOCK: opening a FIFO for reading must not wait for a writer.
    Fd fd(open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY));
    if (fd.get() < 0)
        return Error{DiagCode::kCannotReadFile, Errno("cannot open '" + path + "'")};
    struct stat st {};
    if (fstat(fd.get(), &st) != 0)
        return Error{DiagCode::kCannotReadFile, Errno("cannot read '" + path + "'")};
    if (!S_ISREG(st.st_mode))
        return Error{DiagCode::kCannotReadFile,
                     "'" + path + "' is " + KindOf(st.st_mode) + ", not a regular file"};
    if (as == ReadAs::kInput)
        Remember(st, path);
    if (static_cast<uint64_t>(st.st_size) > max_bytes) {
        return Error{DiagCode::kCannotReadFile, "'" + path + "' is larger than the limit of " +
                                                    std::to_string(max_bytes) + " bytes"};
    }
    std::string out;
    out.resize(static_cast<size_t>(st.st_size));
    size_t at = 0;
    // The size is re-checked while reading: a file that grows is still read only to the limit.
    for (;;) {
        if (at == out.size()) {
            if (out.size() >= max_bytes + 1)
                break;
            out.resize(std::min<uint64_t>(max_bytes + 1, out.size() + 65536));
        }
        const ssize_t n = read(fd.get(), out.data() + at, out.size() - at);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            return Error{DiagCode::kCannotReadFile, Errno("cannot read '" + path + "'")};
        if (n == 0)
            break;
        at += static_cast<size_t>(n);
    }
    if (at > max_bytes) {
        return Error{DiagCode::kCannotReadFile, "'" + path + "' is larger than the limit of " +
                                                    std::to_string(max_bytes) + " bytes"};
    }
    out.resize(at);
    return out;
}

namespace {

Result<std::string> CheckOutput(const std::string& path,
                                const std::vector<std::string>& inputs,
                                bool check_read_files) {
    if (path == kStandardStream)
        return path;
    Result<std::string> resolved = OutputTarget(path);
    if (!resolved)
        return resolved;
    struct stat existing {};
    if (stat(resolved.value().c_str(), &existing) != 0)
        return resolved;  // to be created
    if (!S_ISREG(existing.st_mode)) {
        return Error{DiagCode::kCannotWriteFile, "the output '" + path + "' is " +
                                                     KindOf(existing.st_mode) +
                                                     "; kiln writes only regular files"};
    }
    for (const std::string& input : inputs) {
        struct stat in {};
        if (stat(input.c_str(), &in) == 0 && in.st_dev == existing.st_dev &&
            in.st_ino == existing.st_ino) {
            return Error{DiagCode::kCannotWriteFile, "the output '" + path + "' is the input '" +
                                                         input + "'; refusing to overwrite it"};
        }
    }
    if (std::string read = check_read_files ? ReadName(existing) : ""; !read.empty()) {
        return Error{DiagCode::kCannotWriteFile, "the output '" + path + "' is '" + read +
                                                     "', which this command reads; refusing to "
                                                     "overwrite it"};
    }
    return resolved;
}

}  // namespace

Result<std::string> CheckOutputPath(const std::string& path,
                                    const std::vector<std::string>& inputs) {
    return CheckOutput(path, inputs, true);
}

namespace {

// The output path itself, for an output that replaces a symbolic link instead of following it:
// absent, a regular file or a link (a directory, FIFO or device is refused).
Result<std::string> CheckLinkOutput(const std::string& path) {
    struct stat st {};
    if (lstat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode) || S_ISLNK(st.st_mode))
        return path;
    return Error{DiagCode::kCannotWriteFile, "the output '" + path + "' is " + KindOf(st.st_mode) +
                                                 "; kiln writes only regular files"};
}

}  // namespace

Status CheckDistinctOutputs(const std::vector<std::pair<std::string, std::string>>& outputs) {
    auto same = [](const std::string& a, const std::string& b) {
        struct stat sa {
        }, sb{};
        if (stat(a.c_str(), &sa) == 0 && stat(b.c_str(), &sb) == 0)
            return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
        std::error_code ea, eb;
        const fs::path ca = fs::weakly_canonical(a, ea), cb = fs::weakly_canonical(b, eb);
        return !ea && !eb && ca == cb;
    };
    for (size_t i = 0; i < outputs.size(); ++i) {
        const auto& [flag_a, a] = outputs[i];
        if (a.empty() || a == kStandardStream)
            continue;
        for (size_t j = i + 1; j < outputs.size(); ++j) {
            const auto& [flag_b, b] = outputs[j];
            if (b.empty() || b == kStandardStream || !same(a, b))
                continue;
            return Error{DiagCode::kCannotWriteFile, flag_a + " '" + a + "' and " + flag_b + " '" +
                                                         b +
                                                         "' are one file; give each output "
                                                         "its own"};
        }
    }
    return {};
}

std::string TempName(const std::string& target) {
    static std::atomic<uint64_t> counter{0};
    static const uint64_t seed = std::random_device{}();
    return target + ".tmp." + std::to_string(getpid()) + "." +
           std::to_string(seed ^ (counter++ * 0x9e3779b97f4a7c15ull));
}

bool WriteAll(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t n = write(fd, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        bytes.remove_prefix(static_cast<size_t>(n));
    }
    return true;
}

Status WriteFileAtomically(const std::string& path,
                           std::span<const uint8_t> bytes,
                           const WriteOptions& options) {
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (path == kStandardStream) {
        if (!WriteAll(STDOUT_FILENO, text))
            return Error{DiagCode::kCannotWriteFile, Errno("cannot write standard output")};
        return {};
    }
    Result<std::string> checked =
        options.follow_symlinks ? CheckOutput(path, options.inputs, true) : CheckLinkOutput(path);
    if (!checked)
        return checked.error();
    const std::string& target = checked.value();
    struct stat existing {};
    const bool exists = (options.follow_symlinks ? stat(target.c_str(), &existing)
                                                 : lstat(target.c_str(), &existing)) == 0 &&
                        S_ISREG(existing.st_mode);
    std::string temp;
    int raw = -1;
    for (int attempt = 0; attempt < 100 && raw < 0; ++attempt) {
        temp = TempName(target);
        raw = open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (raw < 0 && errno != EEXIST)
            return Error{DiagCode::kCannotWriteFile,
                         Errno("cannot create a file beside '" + path + "'")};
    }
    if (raw < 0)
        return Error{DiagCode::kCannotWriteFile,
                     "cannot create a temporary file beside '" + path + "'"};
    Fd fd(raw);
    if (exists)
        fchmod(fd.get(), existing.st_mode & 07777);
    if (!WriteAll(fd.get(), text) || (options.durable && fsync(fd.get()) != 0)) {
        const std::string why = Errno("cannot write '" + path + "'");
        unlink(temp.c_str());
        return Error{DiagCode::kCannotWriteFile, why};
    }
    if (close(fd.release()) != 0) {
        const std::string why = Errno("cannot write '" + path + "'");
        unlink(temp.c_str());
        return Error{DiagCode::kCannotWriteFile, why};
    }
    if (rename(temp.c_str(), target.c_str()) != 0) {
        const std::string why = Errno("cannot move the output into place at '" + path + "'");
        unlink(temp.c_str());
        return Error{DiagCode::kCannotWriteFile, why};
    }
    if (!options.durable)
        return {};
    // The rename itself is durable once the directory is.
    std::string dir = fs::path(target).parent_path().string();
    Fd dfd(open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (dfd.get() >= 0)
        fsync(dfd.get());
    return {};
}

Status WriteFileAtomically(const std::string& path,
                           std::string_view text,
                           const WriteOptions& options) {
    return WriteFileAtomically(
        path, std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(text.data()), text.size()),
        options);
}

}  // namespace kiln::base
