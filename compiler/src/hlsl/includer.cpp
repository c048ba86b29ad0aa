#include "hlsl/includer.h"

#include <algorithm>
#include <filesystem>
#include <string_view>

#include "hlsl/blank_inclusions.h"
#include "hlsl/inactive_text.h"
#include "hlsl/output_memo.h"
#include "hlsl/unity_versions.h"

namespace kiln::hlsl {
namespace fs = std::filesystem;

namespace {

std::string Join(const fs::path& dir, const std::string& name) {
    return (dir / name).lexically_normal().string();
}

// Unity resolves `#include "Assets/..."` and `"Packages/..."` from the project's root folder:
// the folder above the Assets folder the including file is in, if it is in one.
std::string ProjectRootOf(const std::string& includer) {
    for (fs::path dir = fs::path(includer).parent_path(); !dir.empty() && dir != dir.parent_path();
         dir = dir.parent_path()) {
        if (dir.filename() == "Assets")
            return dir.parent_path().string();
    }
    return "";
}

bool IsProjectPath(const std::string& header) {
    return header.rfind("Assets/", 0) == 0 || header.rfind("Packages/", 0) == 0;
}

}  // namespace

std::string Includer::Resolve(const std::string& header,
                              const std::string& includer,
                              bool local) const {
    if (header.empty())
        return "";
    // Everything the answer depends on: the header, the including file's folder (local and
    // project includes start there), the search paths.
    std::string key = header;
    key += '\n';
    key += includer.substr(0, includer.find_last_of('/') + 1);
    key += local ? "\nL\n" : "\nS\n";
    key += PathsKey();
    if (std::optional<std::string> known = files_.Resolved(key))
        return *known;
    std::string path = Search(header, includer, local);
    files_.RememberResolved(key, path);
    return path;
}

std::string Includer::PathsKey() const {
    std::string key;
    for (const std::string& dir : paths_.dirs)
        key += dir + '\n';
    return key + paths_.templates_dir + '\n' + std::to_string(paths_.unity_version);
}

std::string Includer::Search(const std::string& header,
                             const std::string& includer,
                             bool local) const {
    std::vector<std::string> candidates;
    if (fs::path(header).is_absolute()) {
        candidates.push_back(fs::path(header).lexically_normal().string());
    } else {
        if (local)
            candidates.push_back(Join(fs::path(includer).parent_path(), header));
        for (const std::string& dir : paths_.dirs)
            candidates.push_back(Join(dir, header));
        if (IsProjectPath(header)) {
            if (const std::string root = ProjectRootOf(includer); !root.empty())
                candidates.push_back(Join(root, header));
        }
        if (!paths_.templates_dir.empty() &&
            (paths_.unity_version == 0 || UnityShips(header, paths_.unity_version))) {
            candidates.push_back(Join(paths_.templates_dir, header));
        }
    }
    for (const std::string& c : candidates) {
        if (files_.Get(c))
            return c;
    }
    return "";
}

glslang::TShader::Includer::IncludeResult* Includer::Serve(const std::string& path, size_t depth) {
    if (depth > kMaxDepth) {
        // A failed result carries its reason in the data field; glslang reports it at the
        // #include line.
        error_text_ = "includes nested more than 64 deep (recursive include without a guard?)";
        return new IncludeResult("", error_text_.data(), error_text_.size(), nullptr);
    }
    if (path.empty())
        return nullptr;  // not found: glslang reports it at the #include
    auto file = files_.Get(path);
    if (!file)
        return nullptr;
    held_.push_back(file);
    std::string_view text = ServedText(*file);
    if (plan_) {
        if (requests_ < plan_->inclusions.size() && plan_->inclusions[requests_].path == path) {
            text = plan_->inclusions[requests_].text;
            ++from_plan_;
            const size_t index = requests_++;
            if (index < plan_->blank_inclusions.size() && plan_->blank_inclusions[index] > 0) {
                return new IncludeResult(BlankInclusionName(index, path), text.data(), text.size(),
                                         nullptr);
            }
            if (index < plan_->output_marks.size() && plan_->output_marks[index] > 0) {
                const OutputMark& m = plan_->outputs[plan_->output_marks[index] - 1];
                if (m.output) {
                    // Its output is given back whole: the files it includes are not asked for,
                    // but read as far as the compile's dependencies go.
                    requests_ = index + m.count;
                    from_plan_ += m.count - 1;
                    held_.insert(held_.end(), m.words->nested.begin(), m.words->nested.end());
                }
                return new IncludeResult(OutputMarkName(index, path), text.data(), text.size(),
                                         nullptr);
            }
        } else {
            plan_ = nullptr;  // glslang left the plan: as they are from here on
        }
    }
    return new IncludeResult(path, text.data(), text.size(), nullptr);
}

glslang::TShader::Includer::IncludeResult* Includer::includeLocal(const char* header,
                                                                  const char* includer,
                                                                  size_t depth) {
    return Serve(Resolve(header, std::string(UnmarkedName(includer ? includer : "")), true), depth);
}

glslang::TShader::Includer::IncludeResult* Includer::includeSystem(const char* header,
                                                                   const char* includer,
                                                                   size_t depth) {
    return Serve(Resolve(header, std::string(UnmarkedName(includer ? includer : "")), false),
                 depth);
}

std::vector<std::string> Includer::Served() const {
    std::vector<std::string> out;
    for (const auto& file : held_) {
        if (std::find(out.begin(), out.end(), file->path()) == out.end())
            out.push_back(file->path());
    }
    return out;
}

void Includer::Hold(const std::vector<std::shared_ptr<const SourceFile>>& files) {
    held_.insert(held_.end(), files.begin(), files.end());
}

void Includer::UsePlan(const InactiveTextPlan* plan) {
    plan_ = plan;
    requests_ = 0;
    from_plan_ = 0;
}

void Includer::releaseInclude(IncludeResult* result) {
    delete result;
}

}  // namespace kiln::hlsl
