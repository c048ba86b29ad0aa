// Files read during a compile (shaders and includes), shared by all compile threads: each file is
// read once, kept for diagnostics, and recorded for the depfile.
#ifndef KILN_HLSL_FILE_CACHE_H_
#define KILN_HLSL_FILE_CACHE_H_

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <unordered_set>
#include <utility>
#include <vector>

#include "hlsl/output_memo.h"
#include "hlsl/plan_memo.h"
#include "kiln/source.h"

namespace kiln::hlsl {

struct PpSkeleton;
struct IncludedDefines;
struct LeanText;
struct SpliceFile;
struct SpliceChoice;

// A file's text as glslang's preprocessor is given it: glslang does not skip a UTF-8 byte-order
// mark, so the text after it.
std::string_view ServedText(const SourceFile& file);

class FileCache {
  public:
    // Where a file's bytes come from: nullopt when there is no such file (or it cannot be read).
    using Loader = std::function<std::optional<std::string>(const std::string& path)>;
    // Files read from this machine's disk (base::ReadRegularFile's rules and size limit).
    FileCache() = default;
    // Files from elsewhere: a worker's, asked of its client (worker/file_exchange.h).
    explicit FileCache(Loader loader) : loader_(std::move(loader)) {}

    // The file at `path`, or null when it does not exist or cannot be read. Thread-safe.
    std::shared_ptr<const SourceFile> Get(const std::string& path);
    // Registers a file already read elsewhere (the .shader files).
    void Put(std::shared_ptr<const SourceFile> file);
    // Every file successfully read, sorted by path.
    std::vector<std::shared_ptr<const SourceFile>> Files() const;
    // The directive lines of `file`'s served text (hlsl/pp_skeleton.h), scanned once per file.
    // Thread-safe.
    std::shared_ptr<const PpSkeleton> Skeleton(const std::shared_ptr<const SourceFile>& file);
    // `file`'s served text without what glslang reads in vain (hlsl/lean_text.h), made once per
    // file. Thread-safe.
    std::shared_ptr<const LeanText> Lean(const std::shared_ptr<const SourceFile>& file);
    // What the lines of `file`'s lean text hold, for splicing (hlsl/splice.h), scanned once per
    // file. Thread-safe.
    std::shared_ptr<const SpliceFile> Splice(const std::shared_ptr<const SourceFile>& file);
    // ChooseSpliceRuns of `file` for the names of `defines` (MacroWords), with the words of
    // `patch` (word id, kind; ascending) taken as those kinds of macro instead (a program's own
    // names), made once per file, `defines` and patch. Thread-safe.
    using SplicePatch = std::vector<std::pair<uint32_t, char>>;
    std::shared_ptr<const SpliceChoice> SpliceRuns(
        const std::shared_ptr<const SpliceFile>& file,
        const std::shared_ptr<const IncludedDefines>& defines,
        const SplicePatch& patch = {});
    // The words of the code lines of `files` (the SpliceFiles of the files `defines` was made
    // of), made once per `defines`. Thread-safe.
    std::shared_ptr<const std::unordered_set<std::string_view>> SpliceWords(
        const std::shared_ptr<const IncludedDefines>& defines,
        const std::vector<std::shared_ptr<const SpliceFile>>& files);
    // What the #define names of `files` (each once) say alone (hlsl/needless_defines.h), made
    // once per set of files. Thread-safe.
    std::shared_ptr<const IncludedDefines> Defines(
        const std::vector<std::shared_ptr<const PpSkeleton>>& files);
    // The inactive-text plan's walks of these files, remembered (hlsl/plan_memo.h).
    PlanMemo& plan_memo() { return plan_memo_; }
    // glslang's outputs for those walks, remembered (hlsl/output_memo.h).
    OutputMemo& output_memo() { return output_memo_; }
    // Include resolutions remembered (Includer::Resolve, whose answers depend only on the files
    // here and its key): the path, "" when not found, nullopt when not asked yet. Thread-safe.
    std::optional<std::string> Resolved(const std::string& key) const;
    void RememberResolved(const std::string& key, const std::string& path);

  private:
    Loader loader_;
    mutable std::mutex mu_;
    std::map<std::string, std::shared_ptr<const SourceFile>> files_;  // null: tried, absent
    // Path -> the file scanned and its skeleton (scanned again when the path's file changes).
    std::map<std::string,
             std::pair<std::shared_ptr<const SourceFile>, std::shared_ptr<const PpSkeleton>>>
        skeletons_;
    std::map<std::string,
             std::pair<std::shared_ptr<const SourceFile>, std::shared_ptr<const LeanText>>>
        leans_;
    std::map<std::string,
             std::pair<std::shared_ptr<const SourceFile>, std::shared_ptr<const SpliceFile>>>
        splices_;
    // The pair's owners are kept with the answer, so that neither address is reused meanwhile.
    struct MacroWordsEntry {
        std::shared_ptr<const SpliceFile> file;
        std::shared_ptr<const IncludedDefines> defines;
        std::shared_ptr<const SpliceChoice> choice;
    };
    std::map<std::tuple<const SpliceFile*, const IncludedDefines*, SplicePatch>, MacroWordsEntry>
        splice_macros_;
    struct SpliceWordsEntry {
        std::shared_ptr<const IncludedDefines> defines;
        std::vector<std::shared_ptr<const SpliceFile>> files;  // the words are views into these
        std::shared_ptr<const std::unordered_set<std::string_view>> words;
    };
    std::map<const IncludedDefines*, SpliceWordsEntry> splice_words_;
    std::map<std::string, std::string> resolved_;
    PlanMemo plan_memo_;
    OutputMemo output_memo_;
    // By the files' skeletons, sorted (a file changed is scanned again, so its set is new).
    std::map<std::vector<const PpSkeleton*>, std::shared_ptr<const IncludedDefines>> defines_;
};

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_FILE_CACHE_H_
