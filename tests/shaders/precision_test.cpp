// kiln compile --precision: half and fixed as 32-bit float (full), as min16float (relaxed) and
// with binary16 arithmetic (half), where HLSL's types say half: a half times a float is float,
// a float assigned to a half narrows. The shipped shaders compile in each precision.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <set>

#include "kiln/pack/reader.h"
#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {
namespace fs = std::filesystem;

constexpr uint32_t kOpTypeFloat = 22, kOpTypeVector = 23, kOpCapability = 17, kOpDecorate = 71;
constexpr uint32_t kCapabilityFloat16 = 9, kRelaxedPrecision = 0;

struct Spirv {
    bool float16 = false;     // OpCapability Float16
    size_t relaxed = 0;       // RelaxedPrecision decorations
    size_t half_results = 0;  // instructions whose result type is a 16-bit float (vector)
    // 16-bit float values an image access reads besides the image (coordinates, level, ...)
    size_t half_image_operands = 0;
};

bool IsImageAccess(uint32_t op) {
    return (op >= 87 && op <= 105) || (op >= 305 && op <= 320);  // OpImageSample* .. QueryLod
}

Spirv Inspect(const std::vector<uint32_t>& words) {
    Spirv s;
    std::set<uint32_t> half_types, half_values;
    for (size_t i = 5; i < words.size();) {
        const uint32_t count = words[i] >> 16, op = words[i] & 0xFFFF;
        if (count == 0 || i + count > words.size())
            break;
        const uint32_t* w = &words[i];
        if (op == kOpCapability && w[1] == kCapabilityFloat16)
            s.float16 = true;
        else if (op == kOpTypeFloat && w[2] == 16)
            half_types.insert(w[1]);
        else if (op == kOpTypeVector && half_types.count(w[2]))
            half_types.insert(w[1]);
        else if (op == kOpDecorate && count == 3 && w[2] == kRelaxedPrecision)
            ++s.relaxed;
        else if (count >= 3 && half_types.count(w[1]) && op != kOpTypeVector) {
            ++s.half_results;
            half_values.insert(w[2]);
        }
        if (IsImageAccess(op)) {
            for (uint32_t k = 4; k < count; ++k)
                s.half_image_operands += half_values.count(w[k]);
        }
        i += count;
    }
    return s;
}

// The fragment module of the only variant of a shader whose fragment stage is `body`.
Spirv CompileFragment(const std::string& body, Precision precision) {
    ScratchDir dir;
    const std::string file = dir.Write("P.shader", R"(Shader "Test/Precision" {
  Properties { _C ("c", Vector) = (1, 1, 1, 1) _H ("h", Vector) = (1, 1, 1, 1) }
  SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    float4 _C;
    half4 _H, _H2;
    sampler2D _Tex;
    float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
    half4 frag() : SV_Target {
)" + body + R"(
    }
    ENDCG
  } }
})");
    CompileOptions options;
    options.precision = precision;
    CompileRun run = Compile({file}, options);
    EXPECT_TRUE(run.out.ok) << Brief(run.diags);
    Result<pack::Pack> opened = pack::Pack::Open(run.out.pack);
    if (!opened) {
        ADD_FAILURE() << opened.error().message;
        return {};
    }
    const pack::Pack& p = opened.value();
    EXPECT_EQ(pack::PrecisionOf(p.meta().flags), precision);
    for (uint32_t i = 0; i < p.Count(pack::SectionTag::kModules); ++i) {
        const auto m = p.Get<pack::ModuleRec>(pack::SectionTag::kModules, i).value();
        if (pack::Stage(m.stage) != pack::Stage::kFragment)
            continue;
        const std::span<const uint8_t> bytes = p.Spirv(m);
        std::vector<uint32_t> words(bytes.size() / 4);
        std::memcpy(words.data(), bytes.data(), words.size() * 4);
        return Inspect(words);
    }
    ADD_FAILURE() << "no fragment module";
    return {};
}

TEST(Precision, HalfTimesHalfIsBinary16InAHalfBuild) {
    const std::string body = "        return _H * _H2 + 1.0;";
    EXPECT_FALSE(CompileFragment(body, Precision::kFull).float16);
    const Spirv relaxed = CompileFragment(body, Precision::kRelaxed);
    EXPECT_FALSE(relaxed.float16);
    EXPECT_GT(relaxed.relaxed, 0u);
    const Spirv half = CompileFragment(body, Precision::kHalf);
    EXPECT_TRUE(half.float16);
    EXPECT_GT(half.half_results, 0u);
}

// glslang gives `half * float` half precision (GLSL ES's rule); HLSL makes it float, and so does
// Kiln: a bright float light times a half albedo must not overflow at 65504.
TEST(Precision, HalfTimesFloatStaysFloat) {
    const Spirv s = CompileFragment("        return _H * (_C * 70000.0);", Precision::kHalf);
    EXPECT_FALSE(s.float16);
    EXPECT_EQ(s.half_results, 0u);
}

// Assigning a float to a half narrows it, as in HLSL: what follows is binary16.
TEST(Precision, AFloatAssignedToAHalfNarrows) {
    const Spirv s =
        CompileFragment("        half4 n = _C * 2.0;\n        return n * _H;", Precision::kHalf);
    EXPECT_TRUE(s.float16);
    EXPECT_GT(s.half_results, 0u);
}

// A level and coordinates computed in half are read by the sample in 32 bits: Vulkan allows no
// binary16 image operands (without VK_AMD_gpu_shader_half_float_fetch) and llvmpipe aborts on
// them; SPIRV-Tools' conversion would leave them half.
TEST(Precision, ImageCoordinatesAndLevelsStay32Bit) {
    const Spirv s = CompileFragment(
        "        half lod = _H.x * _H2.x;\n"
        "        half2 uv = _H.zw * _H2.zw;\n"
        "        return tex2Dlod(_Tex, half4(uv, 0, lod)) * (_H * _H2);",
        Precision::kHalf);
    EXPECT_TRUE(s.float16);
    EXPECT_GT(s.half_results, 0u);
    EXPECT_EQ(s.half_image_operands, 0u);
}

TEST(Precision, EveryShippedShaderCompilesInEachPrecision) {
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(DataPath("../materials"))) {
        if (e.path().extension() == ".shader")
            files.push_back(e.path().string());
    }
    for (Precision p : {Precision::kRelaxed, Precision::kHalf}) {
        CompileOptions options;
        options.precision = p;
        CompileRun run = Compile(files, options);
        ASSERT_TRUE(run.out.ok) << pack::PrecisionName(p) << ": " << Brief(run.diags);
        EXPECT_EQ(Brief(run.diags), "") << pack::PrecisionName(p);
    }
}

}  // namespace
}  // namespace kiln::test
