#include "hlsl/splice.h"

#include <algorithm>

#include "hlsl/file_cache.h"
#include "hlsl/needless_defines.h"
#include "hlsl/pp_macros.h"
#include "hlsl/pp_skeleton.h"

// Which runs of a plan's inclusions are served as markers (hlsl/splice.h).

namespace kiln::hlsl {
namespace {

// The program's own #define names (its main text's, and PlanOptions::unknown), with what each
// may be where a file's line names it (any last word of a body taken as a macro's name).
std::vector<std::pair<std::string_view, char>> OwnNames(const std::vector<std::string>& unknown,
                                                        const PpSkeleton& main) {
    std::vector<std::pair<std::string_view, char>> own;
    for (const std::string& name : unknown)
        own.emplace_back(name, kMacro);
    for (const PpDirective& d : main.directives) {
        if (d.kind != PpKind::kDefine)
            continue;
        const DefineEnd end = EndOfDefine(d.rest);
        const bool empty = !end.calls && end.body.find_first_not_of(" \t") == std::string::npos;
        own.emplace_back(DirectiveMacroName(d.rest), end.calls || !end.last_word.empty()
                                                         ? kCallMacro
                                                     : empty ? kEmptyMacro
                                                             : kMacro);
    }
    return own;
}

}  // namespace

std::vector<InclusionSplice> ChooseSplices(FileCache& cache,
                                           const std::vector<std::string>& unknown,
                                           const PpSkeleton& main_skeleton,
                                           std::string_view main,
                                           const std::vector<SpliceInclusion>& inclusions) {
    if (main.find(kSpliceMarker) != std::string_view::npos)
        return {};
    std::vector<std::shared_ptr<const PpSkeleton>> read;
    for (const SpliceInclusion& p : inclusions) {
        if (std::find(read.begin(), read.end(), p.skeleton) == read.end())
            read.push_back(p.skeleton);
    }
    const std::shared_ptr<const IncludedDefines> included = cache.Defines(read);
    std::vector<std::pair<std::string_view, char>> own = OwnNames(unknown, main_skeleton);
    std::vector<InclusionSplice> chosen(inclusions.size());
    std::vector<std::shared_ptr<const SpliceFile>> files;
    for (size_t i = 0; i < inclusions.size(); ++i) {
        chosen[i].file = cache.Splice(inclusions[i].file);
        if (!chosen[i].file->usable)
            return {};  // its lines are not known: a macro call may run on past its end
        files.push_back(chosen[i].file);
    }
    // Only the own names that are words of some file's code patch what the files' names say.
    const std::shared_ptr<const std::unordered_set<std::string_view>> words =
        cache.SpliceWords(included, files);
    own.erase(std::remove_if(own.begin(), own.end(),
                             [&](const auto& name) { return !words->count(name.first); }),
              own.end());
    for (size_t i = 0; i < inclusions.size(); ++i) {
        const SpliceInclusion& p = inclusions[i];
        InclusionSplice& c = chosen[i];
        c.choice = cache.SpliceRuns(c.file, included);
        FileCache::SplicePatch patch;  // where one of the program's own names is a word here
        for (const auto& [name, kind] : own) {
            const auto it = c.file->word_ids.find(name);
            if (it != c.file->word_ids.end() && c.choice->macro[it->second] < kind)
                patch.emplace_back(it->second, kind);
        }
        if (!patch.empty()) {
            // A name twice (a main text's #define and an unknown): the stronger kind.
            std::sort(patch.begin(), patch.end(), [](const auto& a, const auto& b) {
                return a.first != b.first ? a.first < b.first : a.second > b.second;
            });
            patch.erase(
                std::unique(patch.begin(), patch.end(),
                            [](const auto& a, const auto& b) { return a.first == b.first; }),
                patch.end());
            c.choice = cache.SpliceRuns(c.file, included, patch);
        }
        if (c.choice->poisoned)
            return {};
        // Runs on lines the plan blanked stay blank.
        auto range = p.blank->begin();
        for (uint32_t r = 0; r < c.choice->runs.size(); ++r) {
            const uint32_t line = c.choice->runs[r].line;
            while (range != p.blank->end() && range->second < line)
                ++range;
            if (range == p.blank->end() || line < range->first)
                c.runs.push_back(r);
        }
    }
    return chosen;
}

}  // namespace kiln::hlsl
