// Phase 3 of the compile driver: every stage program preprocessed and reduced to its entry point
// in the workers, unless the direct mode's manifest says what it gives and the compile cache
// holds that; then the reduced texts deduplicated into jobs. Only the first task of each job
// keeps its texts (the one CompileJob reads), so memory grows with the unique programs.
#include <atomic>
#include <map>
#include <mutex>

#include "driver/cache.h"
#include "driver/compile_state.h"
#include "driver/direct_cache.h"
#include "driver/isolation.h"
#include "driver/parallel.h"

namespace kiln::driver {
namespace {

struct State {
    CompileState& st;
    const Cache cache;
    // Result key -> the SPIR-V the cache holds for a direct hit (nullopt: not usable).
    std::map<std::string, std::optional<std::vector<uint32_t>>> found;
    // Result key -> the task that keeps its texts (the smallest index).
    std::mutex mu;
    std::map<std::string, size_t> keeper;
};

// The options that change a module: part of every key.
std::vector<std::string> KeyParts(const CompileState& st, const StageTask& t) {
    const CompileOptions& o = st.options;
    return {ProducerVersion(),
            "O" + std::to_string(int(o.opt_level)) + (o.debug_info ? "g" : "") +
                (o.precision == Precision::kRelaxed ? "r"
                 : o.precision == Precision::kHalf  ? "h"
                                                    : ""),
            t.stage == pack::Stage::kVertex ? "vert" : "frag", EntryOf(st, t)};
}

const std::string& ShaderOf(const CompileState& st, const StageTask& t) {
    return st.shaders[st.passes[t.pass].shader].file->path();
}

// The entries the direct hits name, each loaded and validated once.
void LoadFound(State& s) {
    CompileState& st = s.st;
    std::vector<std::string> keys;
    for (const StageTask& t : st.tasks) {
        if (!t.result_key.empty() && s.found.emplace(t.result_key, std::nullopt).second)
            keys.push_back(t.result_key);
    }
    std::vector<std::optional<std::vector<uint32_t>>> words(keys.size());
    ParallelFor(keys.size(), st.options.jobs,
                [&](size_t k) { words[k] = LoadCached(st, s.cache, keys[k]); });
    for (size_t k = 0; k < keys.size(); ++k)
        s.found[keys[k]] = std::move(words[k]);
}

// Keeps the texts of the first task of each result key only.
void KeepTextsOfFirst(State& s, size_t i) {
    StageTask& t = s.st.tasks[i];
    std::lock_guard<std::mutex> lock(s.mu);
    auto [it, fresh] = s.keeper.emplace(t.result_key, i);
    size_t drop = i;
    if (!fresh && i < it->second) {
        drop = it->second;
        it->second = i;
    } else if (fresh) {
        return;
    }
    StageTask& d = s.st.tasks[drop];
    std::string().swap(d.source);
    std::string().swap(d.reduced);
    std::string().swap(d.rewritten);
}

void Preprocess(State& s, size_t i) {
    CompileState& st = s.st;
    StageTask& t = st.tasks[i];
    if (!t.result_key.empty()) {
        if (const auto it = s.found.find(t.result_key); it != s.found.end() && it->second) {
            t.preprocess_ok = t.direct = true;
            std::string().swap(t.source);
            return;
        }
        t.result_key.clear();  // its entry is gone or damaged: preprocess as if unknown
    }
    worker::Request request = StageRequest(st, t, worker::RequestKind::kPreprocess);
    request.source = t.source;
    worker::Outcome o = st.exec->Run(request);
    if ((t.failure = OutcomeDiagnostic(st, t, o)))
        return;
    for (const std::string& f : o.response.files_read)
        st.files.Get(f);  // for diagnostics and the depfile (a no-op in-process)
    t.preprocess_ok = o.response.ok;
    t.preprocess_log = std::move(o.response.info_log);
    t.reduced = std::move(o.response.text);
    t.rewritten = std::move(o.response.rewritten);
    t.functions_if_entry_missing = std::move(o.response.functions);
    if (!t.preprocess_ok)
        return;
    std::vector<std::string> parts = KeyParts(st, t);
    parts.push_back(CodeOf(t.reduced, st.options.debug_info));
    t.result_key = HashKey(parts);
    // A preprocess with messages is done again each time, so that they are shown each time.
    if (st.direct && t.preprocess_log.empty()) {
        st.direct->Record(st.direct_keys[i], ShaderOf(st, t), t.source, o.response.files_read,
                          t.result_key);
    }
    KeepTextsOfFirst(s, i);
}

Job NewJob(const CompileState& st, const StageTask& t, size_t i) {
    Job job;
    job.stage = t.stage;
    job.entry = EntryOf(st, t);
    job.first_task = i;
    return job;
}

// Tasks with the same result key share a job; a failing preprocess is a job of its own.
void Dedup(CompileState& st, const State* s, CompileStats& stats) {
    std::map<std::string, size_t> by_key;
    for (size_t i = 0; i < st.tasks.size(); ++i) {
        StageTask& t = st.tasks[i];
        stats.direct_hits += t.direct;
        if (!t.preprocess_ok) {
            // Each failing preprocess is its own job so its messages are reported per variant.
            Job job = NewJob(st, t, i);
            if (t.failure)
                job.diags.push_back(*t.failure);
            else
                AppendGlslangLog(st, t.preprocess_log, job.diags, &t.source);
            t.job = st.jobs.size();
            st.jobs.push_back(std::move(job));
            continue;
        }
        auto [it, fresh] = by_key.emplace(t.result_key, st.jobs.size());
        if (fresh) {
            Job job = NewJob(st, t, i);
            job.cache_key = t.result_key;
            if (s == nullptr) {
                job.ok = job.from_cache = true;  // a pack from the cache: no words needed
            } else if (const auto f = s->found.find(t.result_key);
                       f != s->found.end() && f->second) {
                job.words = *f->second;  // loaded and validated by LoadFound
                job.ok = job.from_cache = true;
            }
            st.jobs.push_back(std::move(job));
        }
        t.job = it->second;
    }
}

}  // namespace

bool LookUpDirect(CompileState& st) {
    const CompileOptions& o = st.options;
    if (o.cache_dir.empty())
        return false;
    st.direct = std::make_shared<DirectCache>(Cache(o.cache_dir), IncludePathsFor(o), st.files);
    st.direct_keys.resize(st.tasks.size());
    std::atomic<size_t> hits{0};
    ParallelFor(st.tasks.size(), o.jobs, [&](size_t i) {
        StageTask& t = st.tasks[i];
        st.direct_keys[i] = st.direct->KeyFor(KeyParts(st, t), t.source, ShaderOf(st, t));
        if (auto result = st.direct->Lookup(st.direct_keys[i], ShaderOf(st, t))) {
            t.result_key = *result;
            ++hits;
        }
    });
    return hits == st.tasks.size();
}

void DedupKnown(CompileState& st, CompileStats& stats) {
    for (StageTask& t : st.tasks)
        t.preprocess_ok = t.direct = true;
    Dedup(st, nullptr, stats);
}

void PreprocessAndDedup(CompileState& st, CompileStats& stats) {
    State s{st, Cache(st.options.cache_dir), {}, {}, {}};
    if (st.direct)
        LoadFound(s);
    ParallelFor(
        st.tasks.size(), st.options.jobs, [&](size_t i) { Preprocess(s, i); },
        [&](size_t done) { Progress(st.options, "preprocessing", done, st.tasks.size()); });
    Dedup(st, &s, stats);
}

}  // namespace kiln::driver
