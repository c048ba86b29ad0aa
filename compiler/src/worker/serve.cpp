// The worker process's side (kiln/compile_worker.h): read a request, run it on a deep stack,
// answer; exit on end-of-file, when the parent dies, or after anything that may have left the
// third-party libraries' global state damaged (an exhausted allocation, an exception). Where it
// ends abnormally it says, in a failure frame, which component it was in: also for a crash (a
// fatal signal's handler) and when the client stops it at a limit (SIGUSR1), so nothing but the
// socket is shared with the client.
#include "kiln/compile_worker.h"

#include <pthread.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "kiln/base/sanitizer.h"
#include "kiln/compile.h"
#include "worker/execute.h"
#include "worker/file_exchange.h"
#include "worker/protocol.h"

namespace kiln {
namespace {

using worker::Component;

struct Args {
    int fd = -1;
    uint64_t memory_limit = 0;
    uint64_t stack = uint64_t{256} << 20;
};

bool ParseArgs(int argc, char** argv, Args& a) {
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        char* end = nullptr;
        errno = 0;
        const unsigned long long v = std::strtoull(argv[i + 1], &end, 10);
        if (errno != 0 || end == argv[i + 1] || *end != '\0')
            return false;
        if (flag == "--fd" && v < 1024)
            a.fd = static_cast<int>(v);
        else if (flag == "--memory-limit")
            a.memory_limit = v;
        else if (flag == "--stack" && v >= (1u << 20))
            a.stack = v;
        else
            return false;
    }
    return a.fd >= 0;
}

// The next request's payload; nullopt at end-of-file, on a read error or an oversized frame.
std::optional<std::string> Receive(int fd, worker::FrameReader& reader) {
    for (;;) {
        const std::span<char> room = reader.Room();
        const ssize_t n = recv(fd, room.data(), room.size(), 0);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return std::nullopt;
        if (reader.Advance(static_cast<size_t>(n)))
            return reader.Take();
        if (reader.bad())
            return std::nullopt;
    }
}

// The worker's last words: where a request was when the worker crashed or was stopped. The
// frames are encoded before the first request, so the signal handlers only write(2) them
// (async-signal-safe) and then end the process.
constexpr size_t kComponents = size_t(Component::kKilnReduction) + 1;
struct LastWords {
    int fd = -1;
    std::atomic<uint8_t> component{0};
    std::string crashed[kComponents];  // reason "crash"
    std::string stopped[kComponents];  // reason "stopped": the client's limit
};
LastWords g_last;

void SetComponent(Component c) {
    g_last.component.store(uint8_t(c), std::memory_order_relaxed);
}

void Say(const std::string (&frames)[kComponents]) {
    const uint8_t c = g_last.component.load(std::memory_order_relaxed);
    const std::string& f = frames[c < kComponents ? c : 0];
    ssize_t n = 0;
    for (size_t at = 0; at < f.size() && n >= 0; at += size_t(n))
        n = write(g_last.fd, f.data() + at, f.size() - at);
}

void OnFatalSignal(int sig) {
    Say(g_last.crashed);
    signal(sig, SIG_DFL);  // the process ends by the signal, as the client sees it
    raise(sig);
}

void OnStop(int) {
    Say(g_last.stopped);
    std::_Exit(6);
}

void PrepareLastWords(int fd) {
    g_last.fd = fd;
    for (size_t c = 0; c < kComponents; ++c) {
        g_last.crashed[c] = worker::EncodeFailure("crash", "", Component(c));
        g_last.stopped[c] = worker::EncodeFailure("stopped", "", Component(c));
    }
    struct sigaction fatal {};
    fatal.sa_handler = OnFatalSignal;
    fatal.sa_flags = SA_ONSTACK | SA_RESETHAND;  // a stack overflow runs it on the spare stack
    sigemptyset(&fatal.sa_mask);
    for (int sig : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT})
        sigaction(sig, &fatal, nullptr);
    struct sigaction stop {};
    stop.sa_handler = OnStop;
    sigemptyset(&stop.sa_mask);
    sigaction(SIGUSR1, &stop, nullptr);
}

// A spare stack for the fatal-signal handler on the calling thread (the one requests run on),
// unless the thread has one already: AddressSanitizer gives each thread its own and unmaps it
// when the thread ends, which fails on a stack it did not map.
void UseSpareStack() {
    stack_t current{};
    if (sigaltstack(nullptr, &current) == 0 && !(current.ss_flags & SS_DISABLE))
        return;
    static std::vector<char> spare(size_t{256} << 10);
    stack_t ss{};
    ss.ss_sp = spare.data();
    ss.ss_size = spare.size();
    sigaltstack(&ss, nullptr);
}

// Requests that test the isolation itself (tests/unit/worker/pool_test.cpp): they do what a broken
// compiler does, after saying they are in SPIRV-Tools' optimizer.
[[noreturn]] void SelfTest(const std::string& what) {
    SetComponent(Component::kSpirvOpt);
    if (what == "hang") {
        for (;;)
            pause();
    }
    if (what == "allocate") {
        std::vector<std::vector<char>> hog;
        for (;;)
            hog.emplace_back(size_t{64} << 20, '\1');  // touched: resident, not just reserved
    }
    if (what == "exit")
        std::_Exit(7);
    raise(SIGSEGV);
    std::abort();
}

// The connection's first frame is the client's hello; ours answers it either way, so that a
// client of another version can say which two met. False when the two do not match.
bool Handshake(int fd, worker::FrameReader& reader) {
    const std::optional<std::string> payload = Receive(fd, reader);
    if (!payload)
        return false;
    const auto frame = worker::SplitFrame(*payload);
    std::optional<worker::Hello> theirs;
    if (frame && frame->type == worker::FrameType::kHello)
        theirs = worker::DecodeHello(frame->payload);
    const worker::Hello mine{worker::kProtocolVersion, ProducerVersion()};
    worker::SendFrame(fd, worker::EncodeHello(mine));
    return theirs && theirs->protocol == mine.protocol && theirs->producer == mine.producer;
}

int Serve(int fd) {
    worker::FrameReader reader;
    if (!Handshake(fd, reader))
        return 5;
    // Every file is the client's, asked for by its path (worker/file_exchange.h).
    worker::RemoteFiles remote([&](const std::string& path) -> std::optional<worker::FileAnswer> {
        if (!worker::SendFrame(fd, worker::EncodeNeedFile(path)))
            return std::nullopt;
        const std::optional<std::string> answer = Receive(fd, reader);
        const auto frame = answer ? worker::SplitFrame(*answer) : std::nullopt;
        if (!frame || frame->type != worker::FrameType::kFile)
            return std::nullopt;
        return worker::DecodeFile(frame->payload);
    });
    hlsl::FileCache files(remote.AsLoader());
    hlsl::PreambleCache preambles;
    for (;;) {
        const std::optional<std::string> payload = Receive(fd, reader);
        if (!payload)
            return 0;  // the parent closed its end
        const auto frame = worker::SplitFrame(*payload);
        std::optional<worker::Request> request;
        if (frame && frame->type == worker::FrameType::kRequest)
            request = worker::DecodeRequest(frame->payload);
        if (!request) {
            worker::SendFrame(fd, worker::EncodeFailure("protocol", "a malformed request"));
            return 2;
        }
        if (request->kind == worker::RequestKind::kSelfTest)
            SelfTest(request->source);
        Component now = worker::FirstComponent(request->kind);
        SetComponent(now);
        worker::ExecuteContext context{files,
                                       [&now](Component c) {
                                           SetComponent(c);
                                           now = c;
                                       },
                                       &preambles};
        try {
            const worker::Response response = worker::Execute(*request, context);
            if (const std::string broken = remote.error(); !broken.empty()) {
                worker::SendFrame(fd, worker::EncodeFailure("protocol", broken, now));
                return 2;
            }
            if (!worker::SendFrame(fd, worker::EncodeResponse(response)))
                return 0;
        } catch (const std::bad_alloc&) {
            worker::SendFrame(fd, worker::EncodeFailure("memory", "an allocation failed", now));
            return 3;
        } catch (const std::exception& e) {
            worker::SendFrame(fd, worker::EncodeFailure("exception", e.what(), now));
            return 4;
        }
    }
}

struct ThreadArgs {
    int fd;
    int rc;
};

void* ServeThread(void* p) {
    auto* a = static_cast<ThreadArgs*>(p);
    UseSpareStack();
    a->rc = Serve(a->fd);
    return nullptr;
}

void LimitResources(const Args& a) {
    const rlimit no_core{0, 0};
    setrlimit(RLIMIT_CORE, &no_core);
    // The parent kills a worker whose resident memory passes the limit; the address-space limit
    // is the backstop for an allocation too fast to be seen (not under AddressSanitizer, whose
    // shadow memory is terabytes of address space).
    if (!base::kAddressSanitizer && a.memory_limit > 0) {
        const uint64_t slack = uint64_t{1} << 30;
        const rlim_t as = static_cast<rlim_t>(a.memory_limit * 2 + a.stack + slack);
        const rlimit limit{as, as};
        setrlimit(RLIMIT_AS, &limit);
    }
}

}  // namespace

int RunCompileWorker(int argc, char** argv) {
    Args args;
    if (!ParseArgs(argc, argv, args)) {
        std::fprintf(stderr,
                     "kiln-worker: a compile worker started by kiln; usage: kiln-worker --fd N "
                     "[--memory-limit BYTES] [--stack BYTES]\n");
        return 2;
    }
    // Never outlive the compile, even when a request hangs. (PR_SET_PDEATHSIG would fire when
    // the parent's spawning thread ends, not the parent.)
    const pid_t parent = getppid();
    std::thread([parent] {
        while (getppid() == parent)
            std::this_thread::sleep_for(std::chrono::milliseconds(500));
        std::_Exit(0);
    }).detach();
    LimitResources(args);
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstacksize(&attr, static_cast<size_t>(args.stack));
    PrepareLastWords(args.fd);
    ThreadArgs targs{args.fd, 0};
    pthread_t thread;
    if (pthread_create(&thread, &attr, ServeThread, &targs) != 0) {
        std::fprintf(stderr, "kiln-worker: cannot start a thread with a %llu-byte stack\n",
                     static_cast<unsigned long long>(args.stack));
        return 2;
    }
    pthread_join(thread, nullptr);
    pthread_attr_destroy(&attr);
    return targs.rc;
}

}  // namespace kiln
