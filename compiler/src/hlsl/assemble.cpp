#include "hlsl/assemble.h"

namespace kiln::hlsl {

bool IsLineSafeName(const std::string& path) {
    for (char c : path) {
        if (c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20)
            return false;
    }
    return !path.empty();
}

std::string Prelude(const AssembleInput& in) {
    std::string s = "#line 1 \"" + std::string(kPreludeName) + "\"\n";
    s += "#define SHADER_API_VULKAN 1\n";
    s += "#define SHADER_API_DESKTOP 1\n";
    s += "#define UNITY_COMPILER_HLSL 1\n";
    s += "#define KILN 1\n";
    s += "#define UNITY_VERSION " + std::to_string(kUnityVersion) + "\n";
    s += "#define SHADER_TARGET " + std::to_string(in.shader_target) + "\n";
    s += in.stage == pack::Stage::kVertex ? "#define SHADER_STAGE_VERTEX 1\n"
                                          : "#define SHADER_STAGE_FRAGMENT 1\n";
    // Cg's low-precision spellings: fixed is half, and half is 32-bit float on desktop Vulkan.
    for (const char* suffix : {"", "2", "3", "4", "2x2", "3x3", "4x4", "3x4", "4x3"}) {
        s += "#define fixed" + std::string(suffix) + " half" + suffix + "\n";
    }
    for (const auto& [name, value] : in.defines) {
        s += "#define " + name + " " + (value.empty() ? "1" : value) + "\n";
    }
    for (const std::string& kw : in.keywords)
        s += "#define " + kw + " 1\n";
    return s;
}

std::string AssembleSource(const AssembleInput& in) {
    std::string s = Prelude(in);
    for (const shaderlab::ProgramBlock* b : in.blocks) {
        s += "#line " + std::to_string(b->body_begin.line) + " \"" + in.file_name + "\"\n";
        s.append(b->body_begin.column - 1, ' ');
        s += b->text;
        s += '\n';
    }
    return s;
}

}  // namespace kiln::hlsl
