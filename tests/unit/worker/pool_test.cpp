// The worker pool against real kiln-worker processes: a worker that crashes, hangs, exhausts its
// memory or exits is reported as such and replaced, the next request succeeds, and workers give
// the same answers as the in-process executor.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include "worker/executor.h"
#include "worker/file_exchange.h"

namespace kiln::worker {
namespace {

PoolOptions Options() {
    PoolOptions o;
    o.worker_path = FindWorker("");
    o.workers = 2;
    o.timeout_seconds = 20;
    o.memory_limit_bytes = uint64_t{256} << 20;
    return o;
}

// The compile's files as a compile has them: read from this machine's disk.
hlsl::FileCache& DiskFiles() {
    static hlsl::FileCache files;
    return files;
}

Request SelfTest(const char* what) {
    Request r;
    r.kind = RequestKind::kSelfTest;
    r.source = what;
    return r;
}

Request CompileRequest() {
    Request r;
    r.kind = RequestKind::kCompile;
    r.stage = pack::Stage::kFragment;
    r.name = "pool_test.hlsl";
    r.entry = "frag";
    r.source = "float4 _Color;\nfloat4 frag() : SV_Target { return _Color * 2; }\n";
    return r;
}

void ExpectWorks(Executor& e) {
    const Outcome o = e.Run(CompileRequest());
    ASSERT_EQ(o.status, Outcome::Status::kOk) << o.detail;
    EXPECT_TRUE(o.response.ok) << o.response.info_log << o.response.messages;
    EXPECT_GT(o.response.words.size(), 5u);
}

TEST(WorkerPool, TheWorkerIsFound) {
    EXPECT_FALSE(FindWorker("").empty()) << "kiln-worker should be beside the test binary";
    EXPECT_EQ(FindWorker("/nonexistent/kiln-worker"), "");
}

TEST(WorkerPool, ACrashIsReportedWithItsSignalAndTheWorkerIsReplaced) {
    auto pool = MakeWorkerPool(Options(), DiskFiles());
    const Outcome o = pool->Run(SelfTest("crash"));
    EXPECT_EQ(o.status, Outcome::Status::kCrashed);
    EXPECT_EQ(o.signal, SIGSEGV);
    // Where it crashed comes from the worker's last words (its fatal-signal handler's failure
    // frame), the component the self test said it was in; nothing but the socket is shared.
    EXPECT_EQ(o.component, Component::kSpirvOpt);
    ExpectWorks(*pool);
}

TEST(WorkerPool, AnUnexpectedExitIsACrashWithItsStatus) {
    auto pool = MakeWorkerPool(Options(), DiskFiles());
    const Outcome o = pool->Run(SelfTest("exit"));
    EXPECT_EQ(o.status, Outcome::Status::kCrashed);
    EXPECT_EQ(o.exit_code, 7);
    ExpectWorks(*pool);
}

TEST(WorkerPool, AHangIsKilledAtTheTimeLimit) {
    PoolOptions opts = Options();
    opts.timeout_seconds = 0.5;
    auto pool = MakeWorkerPool(opts, DiskFiles());
    const auto start = std::chrono::steady_clock::now();
    const Outcome o = pool->Run(SelfTest("hang"));
    const double took =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(o.status, Outcome::Status::kTimedOut);
    EXPECT_EQ(o.component, Component::kSpirvOpt);
    EXPECT_GE(took, 0.5);
    EXPECT_LT(took, 10.0);
    ExpectWorks(*pool);
}

TEST(WorkerPool, RunawayMemoryIsStoppedAtTheLimit) {
    auto pool = MakeWorkerPool(Options(), DiskFiles());
    const Outcome o = pool->Run(SelfTest("allocate"));
    EXPECT_EQ(o.status, Outcome::Status::kOutOfMemory);
    EXPECT_EQ(o.component, Component::kSpirvOpt);  // said when stopped at the limit
    ExpectWorks(*pool);
}

TEST(WorkerPool, AMissingWorkerIsUnavailableNotACrash) {
    PoolOptions opts = Options();
    opts.worker_path = "/nonexistent/kiln-worker";
    auto pool = MakeWorkerPool(opts, DiskFiles());
    const Outcome o = pool->Run(CompileRequest());
    EXPECT_EQ(o.status, Outcome::Status::kUnavailable);
    EXPECT_NE(o.detail.find("/nonexistent/kiln-worker"), std::string::npos) << o.detail;
}

TEST(WorkerPool, WorkersAnswerAsTheInProcessExecutorDoes) {
    hlsl::FileCache files;
    auto local = MakeInProcessExecutor(files);
    auto pool = MakeWorkerPool(Options(), DiskFiles());
    for (const Request& r : {CompileRequest(), [] {
                                 Request p = CompileRequest();
                                 p.kind = RequestKind::kPreprocess;
                                 p.source = "#define X 3\nfloat f() { return X; }\n";
                                 return p;
                             }()}) {
        const Outcome a = local->Run(r), b = pool->Run(r);
        ASSERT_EQ(b.status, Outcome::Status::kOk) << b.detail;
        EXPECT_EQ(a.response.ok, b.response.ok);
        EXPECT_EQ(a.response.words, b.response.words);
        EXPECT_EQ(a.response.text, b.response.text);
        EXPECT_EQ(a.response.info_log, b.response.info_log);
    }
    // A self test never runs in-process.
    EXPECT_FALSE(local->Run(SelfTest("crash")).response.ok);
}

TEST(WorkerPool, ConcurrentRequestsShareTheWorkers) {
    auto pool = MakeWorkerPool(Options(), DiskFiles());
    std::vector<std::thread> threads;
    std::atomic<int> ok{0};
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&] {
            for (int i = 0; i < 5; ++i) {
                const Outcome o = pool->Run(CompileRequest());
                ok += o.status == Outcome::Status::kOk && o.response.ok ? 1 : 0;
            }
        });
    }
    for (auto& t : threads)
        t.join();
    EXPECT_EQ(ok.load(), 20);
}

// A worker started in an empty directory compiles a program whose files exist only on the
// client's side, under paths that mean nothing on this machine: every include comes through the
// protocol (worker/file_exchange.h), none from the worker's disk.
TEST(WorkerPool, AWorkerInAnEmptyDirectoryCompilesFilesOnlyTheClientHas) {
    const std::string root = "/nonexistent-kiln-client";
    ASSERT_FALSE(std::filesystem::exists(root));
    const std::map<std::string, std::string> client = {
        {root + "/Assets/Shaders/Common.cginc",
         "#include \"Lib/Tint.cginc\"\nfloat4 Shade(float4 c) { return Tint(c) * 2; }\n"},
        {root + "/Packages/Lib/Tint.cginc", "float4 Tint(float4 c) { return c.bgra; }\n"},
    };
    std::map<std::string, int> asked;
    hlsl::FileCache files([&](const std::string& path) -> std::optional<std::string> {
        ++asked[path];
        const auto it = client.find(path);
        return it == client.end() ? std::nullopt : std::optional<std::string>(it->second);
    });
    PoolOptions o = Options();
    o.workers = 1;
    o.working_dir =
        std::filesystem::temp_directory_path() / ("kiln_empty_" + std::to_string(getpid()));
    std::filesystem::create_directories(o.working_dir);
    auto pool = MakeWorkerPool(o, files);
    Request r = CompileRequest();
    r.kind = RequestKind::kPreprocess;
    r.name = root + "/Assets/Shaders/Rock.shader";
    r.include_dirs = {root + "/Packages"};
    r.source =
        "#include \"Common.cginc\"\nfloat4 _Color;\n"
        "float4 frag() : SV_Target { return Shade(_Color); }\n";
    const Outcome pre = pool->Run(r);
    ASSERT_EQ(pre.status, Outcome::Status::kOk) << pre.detail;
    ASSERT_TRUE(pre.response.ok) << pre.response.info_log;
    EXPECT_NE(pre.response.text.find("bgra"), std::string::npos) << pre.response.text;
    EXPECT_EQ(pre.response.files_read,
              (std::vector<std::string>{root + "/Assets/Shaders/Common.cginc",
                                        root + "/Packages/Lib/Tint.cginc"}));
    // The preprocessed program compiles in the same worker.
    Request c = CompileRequest();
    c.source = pre.response.text;
    const Outcome compiled = pool->Run(c);
    ASSERT_EQ(compiled.status, Outcome::Status::kOk) << compiled.detail;
    EXPECT_TRUE(compiled.response.ok) << compiled.response.info_log;
    EXPECT_GT(compiled.response.words.size(), 5u);
    // The client read each file once (its FileCache), the worker looked where includes resolve.
    EXPECT_EQ(asked[root + "/Packages/Lib/Tint.cginc"], 1);
    EXPECT_EQ(asked[root + "/Assets/Shaders/Lib/Tint.cginc"], 1);  // tried first, not there
    EXPECT_TRUE(std::filesystem::is_empty(o.working_dir));
    std::filesystem::remove_all(o.working_dir);
}

// A worker that answers the hello as another version (here a stand-in speaking the protocol's
// hello as protocol 1 of "kiln 0.1.0") is refused with both versions named.
TEST(WorkerPool, AWorkerOfAnotherVersionIsRefused) {
    const std::string dir =
        std::filesystem::temp_directory_path() / ("kiln_old_worker_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const std::string path = dir + "/kiln-worker";
    {
        // Wire format (worker/protocol.h): u32 length, u32 frame type, then fields of u8 tag,
        // u32 size, bytes; the hello's tags are 29 (protocol, u32) and 30 (producer).
        std::ofstream py(path);
        py << R"(#!/usr/bin/env python3
import os, struct, sys
fd = int(sys.argv[sys.argv.index("--fd") + 1])
def read(n):
    b = b""
    while len(b) < n:
        c = os.read(fd, n - len(b))
        if not c:
            sys.exit(0)
        b += c
    return b
read(struct.unpack("<I", read(4))[0])
field = lambda tag, data: bytes([tag]) + struct.pack("<I", len(data)) + data
body = struct.pack("<I", 0x4b524831) + field(29, struct.pack("<I", 1)) + field(30, b"kiln 0.1.0")
os.write(fd, struct.pack("<I", len(body)) + body)
os.read(fd, 1)
)";
    }
    chmod(path.c_str(), 0755);
    PoolOptions o = Options();
    o.worker_path = path;
    auto pool = MakeWorkerPool(o, DiskFiles());
    const Outcome out = pool->Run(CompileRequest());
    EXPECT_EQ(out.status, Outcome::Status::kUnavailable);
    EXPECT_NE(out.detail.find("the compile worker '" + path +
                              "' is 'kiln 0.1.0' (protocol 1), not this kiln's 'kiln "),
              std::string::npos)
        << out.detail;
    EXPECT_NE(out.detail.find("use the kiln-worker installed with this kiln"), std::string::npos);
    std::filesystem::remove_all(dir);
}

// Threads ask for files at once (the in-process executor's do). Files with the same content are
// sent once, so an answer that says "you have it" must never overtake, on its way to the store,
// the answer that carries the bytes: here the carrying answer is slowed down on purpose.
TEST(FileExchange, AnAnswerWithoutBytesNeverOvertakesTheOneWithThem) {
    hlsl::FileCache client([](const std::string& path) -> std::optional<std::string> {
        return path.rfind("/client/", 0) == 0 ? std::optional<std::string>("float4 Same;\n")
                                              : std::nullopt;
    });
    ContentHashes hashes;
    FileServer server(client, hashes);
    RemoteFiles remote([&](const std::string& path) -> std::optional<FileAnswer> {
        const std::string frame = server.Answer(path);
        const auto f = SplitWholeFrame(frame);
        std::optional<FileAnswer> a = f ? DecodeFile(f->payload) : std::nullopt;
        if (a && a->with_content)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        return a;
    });
    std::atomic<int> ready{0}, missing{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&, t] {
            ++ready;
            while (ready.load() < 4) {
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5 * t));  // the first carries
            if (remote.Load("/client/copy" + std::to_string(t) + ".cginc") != "float4 Same;\n")
                ++missing;
        });
    }
    for (std::thread& th : threads)
        th.join();
    EXPECT_EQ(missing.load(), 0);
    EXPECT_EQ(remote.error(), "");
}

// Each connection (a worker) is sent a file's bytes once; a second connection is sent them again.
// The hash is the compile's, shared by the connections, and names the bytes.
TEST(FileExchange, EachConnectionGetsTheBytesOnceUnderOneSharedHash) {
    hlsl::FileCache client([](const std::string&) -> std::optional<std::string> {
        return std::optional<std::string>("float4 Shared;\n");
    });
    ContentHashes hashes;
    FileServer first(client, hashes), second(client, hashes);
    auto answer = [](FileServer& server) {
        const std::string frame = server.Answer("/client/a.cginc");
        const auto f = SplitWholeFrame(frame);
        return f ? DecodeFile(f->payload) : std::nullopt;
    };
    const std::optional<FileAnswer> a1 = answer(first), a2 = answer(first), b1 = answer(second);
    ASSERT_TRUE(a1 && a2 && b1);
    EXPECT_TRUE(a1->with_content);
    EXPECT_EQ(a1->content, "float4 Shared;\n");
    EXPECT_FALSE(a2->with_content);  // this connection has it
    EXPECT_TRUE(b1->with_content);   // that one does not yet
    EXPECT_EQ(a1->hash, a2->hash);
    EXPECT_EQ(a1->hash, b1->hash);
    EXPECT_EQ(a1->hash, hashes.Of(client.Get("/client/a.cginc")));
    first.Reset();  // a new worker on the first connection's slot
    EXPECT_TRUE(answer(first)->with_content);
}

}  // namespace
}  // namespace kiln::worker
