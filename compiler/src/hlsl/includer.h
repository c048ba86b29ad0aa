// Resolves `#include` for glslang: relative to the including file, then each -I directory in
// order, then the built-in templates/ directory (the files of the --unity-version release). Include
// guards and `#pragma once` are handled by glslang's preprocessor; this class only finds and serves
// files (read once via FileCache).
#ifndef KILN_HLSL_INCLUDER_H_
#define KILN_HLSL_INCLUDER_H_

#include <memory>
#include <string>
#include <vector>

#include <glslang/Public/ShaderLang.h>

#include "hlsl/file_cache.h"

namespace kiln::hlsl {

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

    IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override;
    IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override;
    void releaseInclude(IncludeResult* result) override;

    // Resolution without glslang: the path `header` resolves to, or "" when not found.
    std::string Resolve(const std::string& header, const std::string& includer, bool local) const;

    // The path of every file served so far, in the order first served (for depfiles and for the
    // diagnostics of a compile that ran in a worker process).
    std::vector<std::string> Served() const;

  private:
    IncludeResult* Serve(const std::string& path, size_t depth);

    const IncludePaths& paths_;
    FileCache& files_;
    std::vector<std::shared_ptr<const SourceFile>> held_;
    std::string error_text_;
};

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_INCLUDER_H_
