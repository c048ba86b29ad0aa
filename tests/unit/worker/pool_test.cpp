// The worker pool against real kiln-worker processes: a worker that crashes, hangs, exhausts its
// memory or exits is reported as such and replaced, the next request succeeds, and workers give
// the same answers as the in-process executor.
#include <gtest/gtest.h>

#include <csignal>
#include <thread>

#include "worker/executor.h"

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
    auto pool = MakeWorkerPool(Options());
    const Outcome o = pool->Run(SelfTest("crash"));
    EXPECT_EQ(o.status, Outcome::Status::kCrashed);
    EXPECT_EQ(o.signal, SIGSEGV);
    // Where it crashed comes from the phase board, which the self test set.
    EXPECT_EQ(o.component, Component::kSpirvOpt);
    ExpectWorks(*pool);
}

TEST(WorkerPool, AnUnexpectedExitIsACrashWithItsStatus) {
    auto pool = MakeWorkerPool(Options());
    const Outcome o = pool->Run(SelfTest("exit"));
    EXPECT_EQ(o.status, Outcome::Status::kCrashed);
    EXPECT_EQ(o.exit_code, 7);
    ExpectWorks(*pool);
}

TEST(WorkerPool, AHangIsKilledAtTheTimeLimit) {
    PoolOptions opts = Options();
    opts.timeout_seconds = 0.5;
    auto pool = MakeWorkerPool(opts);
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
    auto pool = MakeWorkerPool(Options());
    const Outcome o = pool->Run(SelfTest("allocate"));
    EXPECT_EQ(o.status, Outcome::Status::kOutOfMemory);
    ExpectWorks(*pool);
}

TEST(WorkerPool, AMissingWorkerIsUnavailableNotACrash) {
    PoolOptions opts = Options();
    opts.worker_path = "/nonexistent/kiln-worker";
    auto pool = MakeWorkerPool(opts);
    const Outcome o = pool->Run(CompileRequest());
    EXPECT_EQ(o.status, Outcome::Status::kUnavailable);
    EXPECT_NE(o.detail.find("/nonexistent/kiln-worker"), std::string::npos) << o.detail;
}

TEST(WorkerPool, WorkersAnswerAsTheInProcessExecutorDoes) {
    hlsl::FileCache files;
    auto local = MakeInProcessExecutor(files);
    auto pool = MakeWorkerPool(Options());
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
    auto pool = MakeWorkerPool(Options());
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

}  // namespace
}  // namespace kiln::worker
