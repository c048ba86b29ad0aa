// Resolves `#include` for glslang: relative to the including file, then each -I directory in
// order, then the built-in templates/ directory (the files of the --unity-version release). Include
// guards and `#pragma once` are handled by glslang's preprocessor; this class finds and serves
// files (read once via FileCache), with the lines glslang would skip blanked when given a plan
// (hlsl/inactive_text.h).
#ifndef KILN_HLSL_INCLUDER_H_
#define KILN_HLSL_INCLUDER_H_

#include <memory>
#include <string>
#include <vector>

#include <glslang/Public/ShaderLang.h>

#include "hlsl/file_cache.h"

namespace kiln::hlsl {

struct InactiveTextPlan;

struct IncludePaths {
    std::vector<std::string> dirs;  // -I, in order
    std::string templates_dir;      // the built-in library
    // UNITY_VERSION: the library serves only the files that release ships
    // (hlsl/unity_versions.h); 0: every file.
    int unity_version = 0;
};

class Includer : public glslang::TShader::Includer {
  public:
    static constexpr size_t kMaxDepth = 64;

    Includer(const IncludePaths& paths, FileCache& files) : paths_(paths), files_(files) {}
    // A new Includer with the same paths and files, and nothing served yet.
    Includer Fresh() const { return Includer(paths_, files_); }

    IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override;
    IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override;
    void releaseInclude(IncludeResult* result) override;

    // Resolution without glslang: the path `header` resolves to, or "" when not found.
    std::string Resolve(const std::string& header, const std::string& includer, bool local) const;

    // What Resolve's answers depend on besides the header and the including file: the search
    // paths (the -I directories, the library and its release).
    std::string PathsKey() const;

    // Serves the plan's blanked texts (hlsl/inactive_text.h) while glslang asks for the files it
    // planned, in its order; from the first other request on, files as they are. Null: none.
    // The plan must outlive the preprocessing.
    void UsePlan(const InactiveTextPlan* plan);
    // Counts `files` as served, in order, without glslang asking for them (a shared preamble's
    // files, hlsl/preamble.h, when the program is preprocessed from its macro table).
    void Hold(const std::vector<std::shared_ptr<const SourceFile>>& files);
    // Files served from the plan since UsePlan.
    size_t served_from_plan() const { return from_plan_; }

    // The path of every file served so far, in the order first served (for depfiles and for the
    // diagnostics of a compile that ran in a worker process).
    std::vector<std::string> Served() const;

  private:
    IncludeResult* Serve(const std::string& path, size_t depth);
    // Resolve's search, without the FileCache's memory of earlier answers.
    std::string Search(const std::string& header, const std::string& includer, bool local) const;

    const IncludePaths& paths_;
    FileCache& files_;
    std::vector<std::shared_ptr<const SourceFile>> held_;
    std::string error_text_;
    const InactiveTextPlan* plan_ = nullptr;
    size_t requests_ = 0;   // files served since UsePlan
    size_t from_plan_ = 0;  // of which from the plan
};

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_INCLUDER_H_
