// Phase 3 of the compile driver: every stage program preprocessed and reduced to its entry point
// in the workers, unless the direct mode's manifest says what it gives and the compile cache
// holds that, or another stage program with the same assembled text was preprocessed already;
// then the reduced texts deduplicated into jobs. Only the first task of each job keeps its texts
// (the one CompileJob reads). When streaming, a new program is compiled by the thread that
// preprocessed it and its texts are dropped at once, so they never wait for a phase to end.
#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "driver/cache.h"
#include "driver/compile_state.h"
#include "driver/direct_cache.h"
#include "driver/isolation.h"
#include "driver/parallel.h"

namespace kiln::driver {
namespace {

// A program compiled as soon as it was preprocessed (streaming), and the task it came from.
struct Early {
    bool done = false;
    size_t task = 0;
    Job job;
};

struct State {
    CompileState& st;
    const bool stream;  // compile each new program as soon as it is preprocessed
    // Result key -> the SPIR-V the cache holds for a direct hit (nullopt: not usable).
    std::map<std::string, std::optional<std::vector<uint32_t>>> found;
    std::mutex mu;  // guards the maps below and the texts of the keepers
    // Result key -> the task that keeps its texts (the smallest index).
    std::map<std::string, size_t> keeper;
    // Result key -> its streamed compile.
    std::map<std::string, Early> early;
};

// True when a streamed compile of `key` ended without a message: no task keeps its texts.
// Called with s.mu held.
bool CompiledClean(const State& s, const std::string& key) {
    const auto e = s.early.find(key);
    return e != s.early.end() && e->second.done && e->second.job.diags.empty();
}

Job NewJob(const CompileState& st, const StageTask& t, size_t i) {
    Job job;
    job.stage = t.stage;
    job.entry = EntryOf(st, t);
    job.first_task = i;
    return job;
}

// Drops a task's texts.
void DropTexts(StageTask& t) {
    std::string().swap(t.reduced);
    std::string().swap(t.rewritten);
}

// What the reduction keeps (hlsl/reduce.h) decides a module's ids: a key holds its rules'
// version, so that the direct mode's entries of a build with other rules (which map a source to
// that build's reduced text and module) are not taken. 2: declarations nothing reaches go.
constexpr std::string_view kReductionRules = "reduction 2";

// The options that change a module: part of every key.
std::vector<std::string> KeyParts(const CompileState& st, const StageTask& t) {
    const CompileOptions& o = st.options;
    return {ProducerVersion() + "; " + std::string(kReductionRules),
            OptimizationKey(o) + (o.debug_info ? "g" : "") +
                (o.precision == Precision::kRelaxed ? "r"
                 : o.precision == Precision::kHalf  ? "h"
                                                    : ""),
            pack::StageName(t.stage), EntryOf(st, t)};
}

// The entries the direct hits name, each loaded and validated once.
void LoadFound(State& s) {
    CompileState& st = s.st;
    std::vector<std::string> keys;
    std::vector<const std::string*> shaders;
    for (const StageTask& t : st.tasks) {
        if (!t.result_key.empty() && s.found.emplace(t.result_key, std::nullopt).second) {
            keys.push_back(t.result_key);
            shaders.push_back(&ShaderOf(st, t));
        }
    }
    std::vector<std::optional<std::vector<uint32_t>>> words(keys.size());
    ParallelFor(keys.size(), st.options.jobs,
                [&](size_t k) { words[k] = LoadCached(st, keys[k], *shaders[k]); });
    for (size_t k = 0; k < keys.size(); ++k)
        s.found[keys[k]] = std::move(words[k]);
}

// Keeps the texts of the first task of each result key only, and none once a streamed compile
// of the key gave no message.
void KeepTextsOfFirst(State& s, size_t i) {
    StageTask& t = s.st.tasks[i];
    std::lock_guard<std::mutex> lock(s.mu);
    auto [it, fresh] = s.keeper.emplace(t.result_key, i);
    if (!fresh) {
        size_t drop = i;
        if (i < it->second) {
            drop = it->second;
            it->second = i;
        }
        DropTexts(s.st.tasks[drop]);
    }
    if (CompiledClean(s, t.result_key))
        DropTexts(s.st.tasks[it->second]);
}

// Streaming: compiles task i's program when no other task of its key has (or the direct mode's
// entry holds it). Task i's texts are its own thread's until KeepTextsOfFirst registers it.
void CompileEarly(State& s, size_t i) {
    CompileState& st = s.st;
    const StageTask& t = st.tasks[i];
    if (!s.stream)
        return;
    {
        std::lock_guard<std::mutex> lock(s.mu);
        if (const auto f = s.found.find(t.result_key); f != s.found.end() && f->second)
            return;
        if (!s.early.emplace(t.result_key, Early{}).second)
            return;
    }
    Job job = NewJob(st, t, i);
    job.cache_key = t.result_key;
    CompileOrLoad(st, job);
    std::lock_guard<std::mutex> lock(s.mu);
    Early& e = s.early[t.result_key];
    e.done = true;
    e.task = i;
    e.job = std::move(job);
    if (!CompiledClean(s, t.result_key))
        return;
    if (const auto k = s.keeper.find(t.result_key); k != s.keeper.end()) {
        DropTexts(st.tasks[k->second]);  // another task of the key, registered meanwhile
    }
}

// Takes a preprocessed and reduced text as task i's: its result key, its manifest, its texts.
// `source` is its assembled source when the caller has it (else assembled for the manifest).
void Accept(State& s,
            size_t i,
            const std::string* source,
            std::string reduced,
            std::string rewritten,
            std::vector<std::string> functions,
            const std::string& log,
            const std::vector<std::string>& files_read) {
    CompileState& st = s.st;
    StageTask& t = st.tasks[i];
    t.preprocess_ok = true;
    t.preprocess_log = log;
    t.reduced = std::move(reduced);
    t.rewritten = std::move(rewritten);
    t.functions_if_entry_missing = std::move(functions);
    t.result_key = HashKeyOfCode(KeyParts(st, t), t.reduced, st.options.debug_info);
    // A preprocess with messages is done again each time, so that they are shown each time.
    if (st.direct && t.preprocess_log.empty())
        st.direct->Record(st.direct_keys[i], ShaderOf(st, t), source ? *source : SourceOf(st, t),
                          files_read, t.result_key);
    CompileEarly(s, i);
    KeepTextsOfFirst(s, i);
}

// The keywords a pass's variants may define, for the worker to share the include prefix none of
// them changes (hlsl/preamble.h); none for a pass of one variant, which has nothing to share, or
// of more keywords than kMaxSharedKeywords (every request carries them, and the plan's proof
// looks for each in the files read).
constexpr size_t kMaxSharedKeywords = 256;

std::vector<std::string> PassKeywords(const PassUnit& pu) {
    std::vector<std::string> out;
    if (pu.expansion.keys.size() < 2)
        return out;
    std::unordered_set<std::string_view> seen;
    for (const variants::KeywordSet& set : pu.pragmas.sets) {
        for (const std::string& k : set.keywords) {
            if (!k.empty() && seen.insert(k).second)
                out.push_back(k);
            if (out.size() > kMaxSharedKeywords)
                return {};
        }
    }
    return out;
}

// Preprocesses task i; `partner` (when not npos) is its variant's fragment task, whose text
// differs only in the stage's #define: the worker reduces the one preprocessed text to both entry
// points when nothing read tests the stage. Returns true when the partner was filled.
bool Preprocess(State& s, size_t i, size_t partner = std::string::npos) {
    CompileState& st = s.st;
    StageTask& t = st.tasks[i];
    if (!t.result_key.empty()) {
        if (const auto it = s.found.find(t.result_key); it != s.found.end() && it->second) {
            t.preprocess_ok = t.direct = true;
            return false;
        }
        t.result_key.clear();  // its entry is gone or damaged: preprocess as if unknown
    }
    worker::Request request = StageRequest(st, t, worker::RequestKind::kPreprocess);
    request.source = SourceOf(st, t);
    request.pinned = PassKeywords(st.passes[t.pass]);
    if (partner != std::string::npos)
        request.second_entry = EntryOf(st, st.tasks[partner]);
    worker::Outcome o = st.exec->Run(request);
    if ((t.failure = OutcomeDiagnostic(st, t, o)))
        return false;
    worker::Response& r = o.response;
    for (const std::string& f : r.files_read)
        st.files.Get(f);  // for diagnostics and the depfile (a no-op in-process)
    if (!r.ok) {
        t.preprocess_log = std::move(r.info_log);
        t.functions_if_entry_missing = std::move(r.functions);
        return false;
    }
    const bool paired = partner != std::string::npos && r.second_ok;
    if (paired) {
        Accept(s, partner, nullptr, std::move(r.second_text), r.rewritten,
               std::move(r.second_functions), r.info_log, r.files_read);
    }
    Accept(s, i, &request.source, std::move(r.text), std::move(r.rewritten), std::move(r.functions),
           r.info_log, r.files_read);
    return paired;
}

// A task's source hashed twice from one assembly: whole (with the shader, stage and entry point:
// tasks of equal keys preprocess the same), and without its stage's #define, so that a vertex
// and a fragment task whose texts differ only there have equal `unstaged` keys.
struct SourceKeys {
    std::string whole, unstaged;
};

SourceKeys KeysOfSource(const CompileState& st, const StageTask& t) {
    static const std::string kVertex = "#define SHADER_STAGE_VERTEX 1\n";
    static const std::string kFragment = "#define SHADER_STAGE_FRAGMENT 1\n";
    const std::string source = SourceOf(st, t);
    SourceKeys out;
    out.whole = HashKey({ShaderOf(st, t), pack::StageName(t.stage), EntryOf(st, t), source});
    const std::string* define = t.stage == pack::Stage::kVertex     ? &kVertex
                                : t.stage == pack::Stage::kFragment ? &kFragment
                                                                    : nullptr;
    const size_t at = define ? source.find(*define) : std::string::npos;
    if (at != std::string::npos)
        out.unstaged = HashKey({source.substr(0, at), source.substr(at + define->size())});
    return out;
}

// For each task, the first task whose preprocess gives the same result: the same shader file,
// stage, entry point and assembled text (a keyword of a fragment-only set leaves the vertex
// stage's text unchanged, so its variants share one preprocess).
std::vector<size_t> Leaders(const std::vector<SourceKeys>& keys) {
    std::vector<size_t> leader(keys.size());
    std::unordered_map<std::string, size_t> first;
    for (size_t i = 0; i < keys.size(); ++i)
        leader[i] = first.emplace(keys[i].whole, i).first->second;
    return leader;
}

// The streamed compile of key `key` as the job of its first task `first` (when there is one it
// can be: compiled from that task, or with no message that a task's positions would change).
void TakeEarly(State& s, const std::string& key, size_t first, Job& job, CompileStats& stats) {
    const auto e = s.early.find(key);
    if (e == s.early.end() || !e->second.done ||
        (e->second.task != first && !e->second.job.diags.empty()))
        return;
    Job& early = e->second.job;
    job.words = std::move(early.words);
    job.ok = early.ok;
    job.from_cache = early.from_cache;
    job.done = true;
    for (Diagnostic& d : early.diags)
        job.diags.push_back(std::move(d));
    ++(early.from_cache ? stats.cache_hits : stats.glslang_compiles);
}

// A task's preprocessor and rewrite messages (X3206) into a job's diagnostics.
void AppendPreprocessLog(CompileState& st, const StageTask& t, Job& job) {
    if (t.preprocess_log.empty())
        return;
    const std::string source = SourceOf(st, t);  // its identifiers feed suggestions
    AppendGlslangLog(st, t.preprocess_log, job.diags, &source);
}

// Tasks with the same result key share a job; a failing preprocess is a job of its own.
void Dedup(CompileState& st, State* s, CompileStats& stats) {
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
                AppendPreprocessLog(st, t, job);
            t.job = st.jobs.size();
            st.jobs.push_back(std::move(job));
            continue;
        }
        auto [it, fresh] = by_key.emplace(t.result_key, st.jobs.size());
        if (fresh) {
            Job job = NewJob(st, t, i);
            job.cache_key = t.result_key;
            // The preprocessor's and the rewrite's warnings (X3206); tasks sharing the job have
            // the same text, so the same warnings.
            AppendPreprocessLog(st, t, job);
            if (s == nullptr) {
                job.ok = job.from_cache = true;  // a pack from the cache: no words needed
            } else if (const auto f = s->found.find(t.result_key);
                       f != s->found.end() && f->second) {
                job.words = *f->second;  // loaded and validated by LoadFound
                job.ok = job.from_cache = true;
            } else {
                TakeEarly(*s, t.result_key, i, job, stats);
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
        st.direct_keys[i] = st.direct->KeyFor(KeyParts(st, t), SourceOf(st, t), ShaderOf(st, t));
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

void PreprocessAndDedup(CompileState& st, CompileStats& stats, bool compile) {
    State s{st, compile, {}, {}, {}, {}};
    if (st.direct)
        LoadFound(s);
    const size_t n = st.tasks.size();
    std::vector<SourceKeys> keys(n);
    ParallelFor(n, st.options.jobs, [&](size_t i) { keys[i] = KeysOfSource(st, st.tasks[i]); });
    const std::vector<size_t> leader = Leaders(keys);
    // A variant's vertex task (a leader) carries its fragment task (a leader too) when the two
    // texts differ only in the stage's #define (CreateTasks puts them side by side).
    std::vector<size_t> partner(n, std::string::npos);
    std::vector<char> carried(n, 0), filled(n, 0);
    for (size_t i = 0; i + 1 < n; ++i) {
        const StageTask& v = st.tasks[i];
        const StageTask& f = st.tasks[i + 1];
        if (leader[i] == i && leader[i + 1] == i + 1 && v.stage == pack::Stage::kVertex &&
            f.stage == pack::Stage::kFragment && v.pass == f.pass && v.key == f.key &&
            !keys[i].unstaged.empty() && keys[i].unstaged == keys[i + 1].unstaged) {
            partner[i] = i + 1;
            carried[i + 1] = 1;
        }
    }
    std::vector<size_t> leaders, followers;
    for (size_t i = 0; i < n; ++i) {
        if (leader[i] != i)
            followers.push_back(i);
        else if (!carried[i])
            leaders.push_back(i);
    }
    ParallelFor(
        leaders.size(), st.options.jobs,
        [&](size_t k) {
            const size_t i = leaders[k];
            if (Preprocess(s, i, partner[i]))
                filled[partner[i]] = 1;
        },
        [&](size_t done) { Progress(st.options, "preprocessing", done, leaders.size()); });
    // A carried task its vertex task did not fill (a direct hit, a failure, a text that tests the
    // stage) is preprocessed itself; so is a follower whose leader failed, so that each failing
    // variant has its own messages. Other followers take their leader's result.
    std::vector<size_t> again;
    for (size_t i = 0; i < n; ++i) {
        if (carried[i] && !filled[i])
            again.push_back(i);
    }
    ParallelFor(again.size(), st.options.jobs, [&](size_t k) { Preprocess(s, again[k]); });
    again.clear();
    size_t shared = std::count(filled.begin(), filled.end(), 1);
    for (size_t i : followers) {
        StageTask& t = st.tasks[i];
        const StageTask& l = st.tasks[leader[i]];
        if (!l.preprocess_ok || l.failure || l.result_key.empty()) {
            again.push_back(i);
            continue;
        }
        t.preprocess_ok = true;
        t.direct = l.direct;
        t.result_key = l.result_key;
        ++shared;
    }
    ParallelFor(again.size(), st.options.jobs, [&](size_t k) { Preprocess(s, again[k]); });
    if (st.direct)
        st.direct->Flush();  // one manifest per shader file name
    stats.shared_preprocesses = shared;
    Dedup(st, &s, stats);
}

}  // namespace kiln::driver
