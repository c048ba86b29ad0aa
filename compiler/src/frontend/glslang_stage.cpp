#include "frontend/glslang_stage.h"

#include <mutex>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <glslang/build_info.h>

#include "hlsl/includer.h"

namespace kiln::frontend {
namespace {

constexpr int kDefaultVersion = 100;

EShLanguage Language(pack::Stage stage) {
    switch (stage) {
        case pack::Stage::kVertex:
            return EShLangVertex;
        case pack::Stage::kFragment:
            return EShLangFragment;
        case pack::Stage::kGeometry:
            return EShLangGeometry;
        case pack::Stage::kTessControl:
            return EShLangTessControl;
        case pack::Stage::kTessEval:
            return EShLangTessEvaluation;
    }
    return EShLangVertex;
}

EShMessages Messages() {
    return static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules | EShMsgReadHlsl |
                                    EShMsgHlslDX9Compatible | EShMsgEnhanced);
}

// glslang keeps pointers to these until the shader is parsed: the Input lives beside the shader.
struct Input {
    Input(const std::string& source, const std::string& name)
        : text(source.c_str()), length(static_cast<int>(source.size())), file(name.c_str()) {}
    const char* text;
    int length;
    const char* file;
};

void Configure(glslang::TShader& shader, pack::Stage stage, const Input& in) {
    shader.setStringsWithLengthsAndNames(&in.text, &in.length, &in.file, 1);
    shader.setEnvInput(glslang::EShSourceHlsl, Language(stage), glslang::EShClientVulkan,
                       kDefaultVersion);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
    // Emits HLSL semantics as decorations for reflection; stripped before the module is stored.
    shader.setEnvTargetHlslFunctionality1();
}

}  // namespace

void InitializeGlslang() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

std::string GlslangVersion() {
    return std::to_string(GLSLANG_VERSION_MAJOR) + "." + std::to_string(GLSLANG_VERSION_MINOR) +
           "." + std::to_string(GLSLANG_VERSION_PATCH) + GLSLANG_VERSION_FLAVOR;
}

StageOutput Preprocess(pack::Stage stage,
                       const std::string& source,
                       const std::string& name,
                       hlsl::Includer& includer) {
    InitializeGlslang();
    StageOutput out;
    glslang::TShader shader(Language(stage));
    const Input input(source, name);
    Configure(shader, stage, input);
    out.ok = shader.preprocess(GetDefaultResources(), kDefaultVersion, ENoProfile, false, false,
                               Messages(), &out.text, includer);
    out.info_log = shader.getInfoLog();
    return out;
}

StageOutput Compile(pack::Stage stage,
                    const std::string& source,
                    const std::string& name,
                    const std::string& entry_point,
                    hlsl::Includer& includer,
                    bool debug_info) {
    InitializeGlslang();
    StageOutput out;
    glslang::TShader shader(Language(stage));
    const Input input(source, name);
    Configure(shader, stage, input);
    shader.setEntryPoint(entry_point.c_str());
    shader.setSourceEntryPoint(entry_point.c_str());
    EShMessages messages = Messages();
    if (debug_info)
        messages = static_cast<EShMessages>(messages | EShMsgDebugInfo);
    const bool parsed =
        shader.parse(GetDefaultResources(), kDefaultVersion, false, messages, includer);
    out.info_log = shader.getInfoLog();
    if (!parsed)
        return out;
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages)) {
        out.info_log += program.getInfoLog();
        return out;
    }
    // glslang links a program without its entry point, warning "Entry point not found", and
    // would emit an entry point that does nothing.
    if (std::string(program.getInfoLog()).find("Entry point not found") != std::string::npos) {
        out.entry_missing = true;
        return out;
    }
    glslang::SpvOptions options;
    options.generateDebugInfo = debug_info;
    options.disableOptimizer = true;  // SPIRV-Tools runs legalization and -O afterwards
    options.validate = false;         // spirv-val runs on the final module
    spv::SpvBuildLogger logger;
    glslang::GlslangToSpv(*program.getIntermediate(Language(stage)), out.spirv, &logger, &options);
    const std::string extra = logger.getAllMessages();
    if (!extra.empty())
        out.info_log += extra;
    out.ok = !out.spirv.empty();
    return out;
}

}  // namespace kiln::frontend
