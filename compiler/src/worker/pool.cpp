// The worker pool (executor.h): spawning, one request at a time per process over a Unix socket,
// time and memory limits enforced from this side, restart after any failure.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <thread>
#include <vector>

#include "kiln/compile.h"
#include "worker/execute.h"
#include "worker/executor.h"
#include "worker/file_exchange.h"

extern char** environ;

namespace kiln::worker {
namespace {

using Clock = std::chrono::steady_clock;
constexpr int kTickMs = 20;  // how often a running request's memory is looked at
constexpr int kWorkerFd = 3;
// How long a worker stopped at a limit (SIGUSR1) has to say where it was before it is killed.
constexpr int kLastWordsMs = 500;

// The same protocol without a process: requests, responses and files pass as encoded frames, so
// --in-process checks the encoding and the file exchange the workers use.
class InProcessExecutor : public Executor {
  public:
    explicit InProcessExecutor(hlsl::FileCache& files)
        : server_(files, hashes_),
          remote_([this](const std::string& path) -> std::optional<FileAnswer> {
              const std::string frame = server_.Answer(path);
              const auto f = SplitWholeFrame(frame);
              return f && f->type == FrameType::kFile ? DecodeFile(f->payload) : std::nullopt;
          }),
          worker_files_(remote_.AsLoader()) {}

    Outcome Run(const Request& request) override {
        Outcome o;
        const std::optional<Request> sent = Decode<Request>(EncodeRequest(request));
        if (!sent) {
            o.status = Outcome::Status::kBroken;
            o.detail = "a request that does not survive its encoding";
            return o;
        }
        ExecuteContext context{worker_files_, {}, &preambles_};
        const std::optional<Response> answer =
            Decode<Response>(EncodeResponse(Execute(*sent, context)));
        if (const std::string broken = remote_.error(); !broken.empty() || !answer) {
            o.status = Outcome::Status::kBroken;
            o.detail = broken.empty() ? "a response that does not survive its encoding" : broken;
            return o;
        }
        o.response = std::move(*answer);
        return o;
    }

  private:
    template <typename T>
    static std::optional<T> Decode(const std::string& frame) {
        const auto f = SplitWholeFrame(frame);
        if (!f)
            return std::nullopt;
        if constexpr (std::is_same_v<T, Request>)
            return DecodeRequest(f->payload);
        else
            return DecodeResponse(f->payload);
    }

    ContentHashes hashes_;
    FileServer server_;
    RemoteFiles remote_;
    hlsl::FileCache worker_files_;
    hlsl::PreambleCache preambles_;
};

// Resident memory of a process, in bytes (0 when it cannot be read).
uint64_t ResidentBytes(pid_t pid) {
    char path[64];
    std::snprintf(path, sizeof path, "/proc/%d/statm", static_cast<int>(pid));
    FILE* f = std::fopen(path, "r");
    if (f == nullptr)
        return 0;
    unsigned long long size = 0, resident = 0;
    const int n = std::fscanf(f, "%llu %llu", &size, &resident);
    std::fclose(f);
    if (n != 2)
        return 0;
    return resident * static_cast<uint64_t>(sysconf(_SC_PAGESIZE));
}

struct Worker {
    pid_t pid = -1;
    int fd = -1;
    FrameReader reader;
    std::unique_ptr<FileServer> files;  // what this connection was sent
};

// What one look at a worker's socket found.
enum class Arrival {
    kFrame,      // a whole frame
    kNone,       // nothing whole yet
    kGone,       // the connection closed or failed: the worker is gone
    kOversized,  // a frame announced over the size limit: not the protocol
};

// Waits up to `ms` for `w`'s socket to be readable, then reads what has arrived without
// blocking, never past the end of one frame (which goes to `payload`).
Arrival Receive(Worker& w, int ms, std::string& payload) {
    pollfd p{w.fd, POLLIN, 0};
    const int ready = poll(&p, 1, ms);
    if (ready < 0)
        return errno == EINTR ? Arrival::kNone : Arrival::kGone;
    while (ready > 0) {
        const std::span<char> room = w.reader.Room();
        const ssize_t n = recv(w.fd, room.data(), room.size(), MSG_DONTWAIT);
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
            return Arrival::kNone;
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return Arrival::kGone;
        if (w.reader.Advance(static_cast<size_t>(n))) {
            payload = w.reader.Take();
            return Arrival::kFrame;
        }
        if (w.reader.bad())
            return Arrival::kOversized;
    }
    return Arrival::kNone;
}

// The next frame from `w` within `ms` milliseconds; nullopt when none came whole.
std::optional<std::string> ReceiveWithin(Worker& w, int ms) {
    const auto give_up = Clock::now() + std::chrono::milliseconds(ms);
    std::string payload;
    while (Clock::now() < give_up) {
        const Arrival a = Receive(w, kTickMs, payload);
        if (a == Arrival::kFrame)
            return payload;
        if (a != Arrival::kNone)
            return std::nullopt;
    }
    return std::nullopt;
}

// The outcome a worker's failure frame reports (`f` null: malformed). A crash's last words come
// before the worker dies by its signal.
Outcome::Status FailureStatus(const std::optional<Failure>& f) {
    return !f                      ? Outcome::Status::kBroken
           : f->reason == "crash"  ? Outcome::Status::kCrashed
           : f->reason == "memory" ? Outcome::Status::kOutOfMemory
                                   : Outcome::Status::kBroken;
}

class WorkerPool : public Executor {
  public:
    WorkerPool(PoolOptions options, hlsl::FileCache& files)
        : options_(std::move(options)),
          workers_(std::max(1u, options_.workers)),
          busy_(workers_.size(), false) {
        for (Worker& w : workers_)
            w.files = std::make_unique<FileServer>(files, hashes_);
    }

    ~WorkerPool() override {
        for (Worker& w : workers_)
            Stop(w, /*kill_now=*/false);
    }

    Outcome Run(const Request& request) override {
        size_t slot = 0;
        {
            std::unique_lock<std::mutex> lock(mu_);
            cv_.wait(lock, [&] {
                for (slot = 0; slot < busy_.size(); ++slot) {
                    if (!busy_[slot])
                        return true;
                }
                return false;
            });
            busy_[slot] = true;
        }
        Outcome o = RunOn(workers_[slot], request);
        {
            std::lock_guard<std::mutex> lock(mu_);
            busy_[slot] = false;
        }
        cv_.notify_one();
        return o;
    }

  private:
    Status Spawn(Worker& w) const;
    Status Handshake(Worker& w) const;
    Outcome RunOn(Worker& w, const Request& request) const;
    // Ends a worker; fills `o` with how it ended when given.
    void Stop(Worker& w, bool kill_now, Outcome* o = nullptr) const;

    PoolOptions options_;
    ContentHashes hashes_;  // before workers_: their servers use it
    std::vector<Worker> workers_;
    std::mutex mu_;
    std::condition_variable cv_;
    std::vector<bool> busy_;
};

Status WorkerPool::Spawn(Worker& w) const {
    int sv[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0) {
        return Error{DiagCode::kWorkerUnavailable,
                     std::string("socketpair: ") + std::strerror(errno)};
    }
    // The child's end moves to fd 3 there; keep it away from that here so that dup2 clears
    // CLOEXEC.
    const int child_end = fcntl(sv[1], F_DUPFD_CLOEXEC, 10);
    close(sv[1]);
    if (child_end < 0) {
        Error error{DiagCode::kWorkerUnavailable, std::string("fcntl: ") + std::strerror(errno)};
        close(sv[0]);
        return error;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, child_end, kWorkerFd);
    if (!options_.working_dir.empty())
        posix_spawn_file_actions_addchdir_np(&actions, options_.working_dir.c_str());
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t none, defaults;
    sigemptyset(&none);
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGPIPE);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
    const std::string fd = std::to_string(kWorkerFd);
    const std::string memory = std::to_string(options_.memory_limit_bytes);
    const std::string stack = std::to_string(options_.stack_bytes);
    std::vector<const char*> argv = {options_.worker_path.c_str(),
                                     "--fd",
                                     fd.c_str(),
                                     "--memory-limit",
                                     memory.c_str(),
                                     "--stack",
                                     stack.c_str(),
                                     nullptr};
    pid_t pid = -1;
    const int rc = posix_spawn(&pid, options_.worker_path.c_str(), &actions, &attr,
                               const_cast<char* const*>(argv.data()), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    close(child_end);
    if (rc != 0) {
        close(sv[0]);
        return Error{DiagCode::kWorkerUnavailable,
                     "cannot start '" + options_.worker_path + "': " + std::strerror(rc)};
    }
    w.pid = pid;
    w.fd = sv[0];
    w.reader = FrameReader();
    // Preprocessed Unity shaders are a few hundred KiB: let a response pass in few system calls.
    const int buffer_bytes = 4 << 20;
    setsockopt(w.fd, SOL_SOCKET, SO_RCVBUF, &buffer_bytes, sizeof buffer_bytes);
    setsockopt(w.fd, SOL_SOCKET, SO_SNDBUF, &buffer_bytes, sizeof buffer_bytes);
    w.files->Reset();
    if (Status shook = Handshake(w); !shook.ok()) {
        Stop(w, /*kill_now=*/true);
        return shook;
    }
    return {};
}

// Hellos both ways (worker/protocol.h): a worker of another protocol or producer version is
// refused, since its SPIR-V is not what this kiln's cache keys name.
Status WorkerPool::Handshake(Worker& w) const {
    const Hello mine{kProtocolVersion, ProducerVersion()};
    std::optional<Hello> theirs;
    if (SendFrame(w.fd, EncodeHello(mine))) {
        const std::optional<std::string> payload = ReceiveWithin(w, 30000);
        const auto frame = payload ? SplitFrame(*payload) : std::nullopt;
        if (frame && frame->type == FrameType::kHello)
            theirs = DecodeHello(frame->payload);
    }
    if (!theirs) {
        return Error{
            DiagCode::kWorkerUnavailable,
            "'" + options_.worker_path +
                "' did not answer the compile-worker protocol's hello; is it kiln-worker?"};
    }
    if (theirs->protocol != mine.protocol || theirs->producer != mine.producer) {
        return Error{DiagCode::kWorkerUnavailable,
                     "the compile worker '" + options_.worker_path + "' is '" + theirs->producer +
                         "' (protocol " + std::to_string(theirs->protocol) +
                         "), not this kiln's '" + mine.producer + "' (protocol " +
                         std::to_string(mine.protocol) +
                         "); use the kiln-worker installed with this kiln"};
    }
    return {};
}

void WorkerPool::Stop(Worker& w, bool kill_now, Outcome* o) const {
    if (w.pid < 0)
        return;
    if (kill_now)
        kill(w.pid, SIGKILL);
    if (w.fd >= 0)
        close(w.fd);  // a live worker reads end-of-file and exits
    w.fd = -1;
    int status = 0;
    // A worker that closed its socket is exiting; give it two seconds before killing it.
    const auto give_up = Clock::now() + std::chrono::seconds(2);
    pid_t r = 0;
    while ((r = waitpid(w.pid, &status, WNOHANG)) == 0 && Clock::now() < give_up)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (r == 0) {
        kill(w.pid, SIGKILL);
        r = waitpid(w.pid, &status, 0);
    }
    if (o != nullptr && r == w.pid) {
        if (WIFSIGNALED(status))
            o->signal = WTERMSIG(status);
        else if (WIFEXITED(status))
            o->exit_code = WEXITSTATUS(status);
    }
    w.pid = -1;
    w.reader = FrameReader();
}

Outcome WorkerPool::RunOn(Worker& w, const Request& request) const {
    Outcome o;
    if (w.pid < 0) {
        if (Status spawned = Spawn(w); !spawned.ok()) {
            o.status = Outcome::Status::kUnavailable;
            o.detail = spawned.error().message;
            return o;
        }
    }
    // Where the request was: the component it starts in until the worker says otherwise (its
    // failure frame, also for a crash or a stop at a limit).
    o.component = FirstComponent(request.kind);
    const auto fail = [&](Outcome::Status status, bool kill_now) {
        o.status = status;
        Stop(w, kill_now, &o);
        return o;
    };
    // A limit: the worker is asked to stop (SIGUSR1), says where it was, and is killed.
    const auto stop_at_limit = [&](Outcome::Status status) {
        kill(w.pid, SIGUSR1);
        for (auto give_up = Clock::now() + std::chrono::milliseconds(kLastWordsMs);
             Clock::now() < give_up;) {
            const std::optional<std::string> payload = ReceiveWithin(w, kLastWordsMs);
            const auto frame = payload ? SplitFrame(*payload) : std::nullopt;
            if (!frame)
                break;
            if (frame->type != FrameType::kFailure)
                continue;  // an answer that crossed the stop
            if (const auto f = DecodeFailure(frame->payload); f && f->reason == "stopped")
                o.component = f->component;
            break;
        }
        return fail(status, true);
    };
    if (!SendFrame(w.fd, EncodeRequest(request)))
        return fail(Outcome::Status::kCrashed, false);
    const auto start = Clock::now();
    const auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(options_.timeout_seconds));
    auto next_memory_check = start;
    for (;;) {
        std::string payload;
        switch (Receive(w, kTickMs, payload)) {
            case Arrival::kGone:
                return fail(Outcome::Status::kCrashed, false);
            case Arrival::kOversized:
                o.detail = "a frame over the size limit";
                return fail(Outcome::Status::kBroken, true);
            case Arrival::kNone:
                break;
            case Arrival::kFrame: {
                const std::optional<Frame> frame = SplitFrame(payload);
                if (!frame) {
                    o.detail = "an unknown frame";
                    return fail(Outcome::Status::kBroken, true);
                }
                if (frame->type == FrameType::kNeedFile) {
                    const std::optional<std::string> path = DecodeNeedFile(frame->payload);
                    if (!path) {
                        o.detail = "a malformed file request";
                        return fail(Outcome::Status::kBroken, true);
                    }
                    if (!SendFrame(w.fd, w.files->Answer(*path)))
                        return fail(Outcome::Status::kCrashed, false);
                    continue;  // the request goes on
                }
                if (frame->type == FrameType::kFailure) {
                    const auto f = DecodeFailure(frame->payload);
                    o.detail = f ? f->detail : "";
                    if (f && f->component != Component::kNone)
                        o.component = f->component;
                    return fail(FailureStatus(f), false);
                }
                std::optional<Response> resp;
                if (frame->type == FrameType::kResponse)
                    resp = DecodeResponse(frame->payload);
                if (!resp) {
                    o.detail = "a malformed response";
                    return fail(Outcome::Status::kBroken, true);
                }
                o.response = std::move(*resp);
                return o;
            }
        }
        const auto now = Clock::now();
        if (now >= deadline)
            return stop_at_limit(Outcome::Status::kTimedOut);
        if (now >= next_memory_check) {
            if (ResidentBytes(w.pid) > options_.memory_limit_bytes)
                return stop_at_limit(Outcome::Status::kOutOfMemory);
            next_memory_check = now + std::chrono::milliseconds(kTickMs);
        }
    }
}

bool IsExecutable(const std::string& path) {
    std::error_code ec;
    return !path.empty() && std::filesystem::is_regular_file(path, ec) &&
           access(path.c_str(), X_OK) == 0;
}

}  // namespace

std::unique_ptr<Executor> MakeInProcessExecutor(hlsl::FileCache& files) {
    return std::make_unique<InProcessExecutor>(files);
}

std::unique_ptr<Executor> MakeWorkerPool(const PoolOptions& options, hlsl::FileCache& files) {
    return std::make_unique<WorkerPool>(options, files);
}

std::string FindWorker(const std::string& explicit_path) {
    if (!explicit_path.empty())
        return IsExecutable(explicit_path) ? explicit_path : "";
    if (const char* env = std::getenv("KILN_WORKER"); env != nullptr && *env != '\0')
        return IsExecutable(env) ? env : "";
    std::error_code ec;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const std::string beside = (self.parent_path() / "kiln-worker").string();
        if (IsExecutable(beside))
            return beside;
    }
    return "";
}

}  // namespace kiln::worker
