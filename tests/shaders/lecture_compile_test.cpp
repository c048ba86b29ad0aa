// The lecture's shaders (tests/lecture, assembled in the order the lecture builds them) compile
// in every variant with only Kiln's templates. Where the lecture's own text has a type error, the
// test asserts Kiln's diagnostic and its position, applies the fix a student would make, and
// requires the fixed shader to compile in every variant.
#include <gtest/gtest.h>

#include <algorithm>

#include "kiln/pack/reader.h"
#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {

struct LectureError {
    std::string line;       // the lecture's line, as printed
    std::string column_at;  // the diagnostic points at the first occurrence of this on the line
    std::string message;    // Kiln's message
    std::string fixed;      // the line as a student fixes it
};

struct LectureShader {
    std::string file;
    std::vector<LectureError> errors;  // in the order Kiln reports them (one per compile)
    size_t variants;                   // all passes, from the shader's pragmas
};

const LectureError kLightColorIsFloat3 = {"float4 lightColor = _LightColor0.rgb;", "=",
                                          "cannot convert from 'float3' to 'float4'",
                                          "float4 lightColor = _LightColor0;"};
const LectureError kAlbedoIsFloat3 = {"float4 albedo = tex2D(_MainTex, v2f.uv).rgb * _Color;", "=",
                                      "cannot convert from 'float3' to 'float4'",
                                      "float4 albedo = tex2D(_MainTex, v2f.uv) * _Color;"};

// 1-based line and column of `needle` inside the first line containing `line`.
std::pair<uint32_t, uint32_t> Position(const std::string& text,
                                       const std::string& line,
                                       const std::string& needle) {
    const size_t at = text.find(line);
    if (at == std::string::npos)
        return {0, 0};
    const uint32_t line_no =
        1 + static_cast<uint32_t>(std::count(text.begin(), text.begin() + at, '\n'));
    const size_t line_start =
        text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
    const size_t col = text.find(needle, at) - line_start + 1;
    return {line_no, static_cast<uint32_t>(col)};
}

class LectureCompile : public testing::TestWithParam<LectureShader> {};

TEST_P(LectureCompile, CompilesInEveryVariantOnceTheLecturesTyposAreFixed) {
    const LectureShader& shader = GetParam();
    std::string text = ReadFile(DataPath("lecture/" + shader.file));
    ScratchDir dir;
    CompileOptions options;
    options.include_dirs = {DataPath("lecture")};  // LightShader.cginc
    for (const LectureError& e : shader.errors) {
        const std::string path = dir.Write(shader.file, text);
        CompileRun run = Compile({path}, options);
        EXPECT_FALSE(run.out.ok);
        ASSERT_FALSE(run.diags.all().empty()) << "expected: " << e.message;
        const Diagnostic& d = run.diags.all().front();
        const auto [line, column] = Position(text, e.line, e.column_at);
        ASSERT_GT(line, 0u) << e.line;
        EXPECT_EQ(d.severity, Severity::kError);
        EXPECT_EQ(FormatDiagCode(d.code), "K5001");
        EXPECT_EQ(d.file, path);
        EXPECT_EQ(d.message, e.message);
        EXPECT_EQ(d.range.begin.line, line) << Brief(run.diags);
        EXPECT_EQ(d.range.begin.column, column) << Brief(run.diags);
        EXPECT_EQ(run.diags.error_count(), 1u) << Brief(run.diags);
        text = Replace(text, e.line, e.fixed);
    }

    const std::string path = dir.Write(shader.file, text);
    CompileRun run = Compile({path}, options);
    ASSERT_TRUE(run.out.ok) << Brief(run.diags);
    EXPECT_EQ(Brief(run.diags), "") << "no warnings either";
    EXPECT_EQ(run.out.stats.permutations, shader.variants);
    EXPECT_EQ(run.out.stats.variants, shader.variants) << "every permutation is a variant";
    pack::Pack p;
    ASSERT_TRUE(kiln::test::OpenInto(run.out.pack, p));
    EXPECT_EQ(p.Count(pack::SectionTag::kVariants), shader.variants);
}

INSTANTIATE_TEST_SUITE_P(
    Lecture,
    LectureCompile,
    testing::Values(LectureShader{"01_Lambert.shader", {kLightColorIsFloat3}, 1},
                    LectureShader{"02_LambertAmbient.shader", {kLightColorIsFloat3}, 1},
                    LectureShader{"03_Phong.shader", {kLightColorIsFloat3}, 1},
                    LectureShader{"04_DiffuseSpecular.shader", {kLightColorIsFloat3}, 1},
                    LectureShader{"05_Textured.shader", {kLightColorIsFloat3, kAlbedoIsFloat3}, 1},
                    LectureShader{"06_EnergyConservation.shader", {}, 1},
                    LectureShader{"07_PhysicallyBased.shader", {}, 1},
                    // ForwardBase + ForwardAdd; then ForwardAdd with DIRECTIONAL POINT and SPOT
                    LectureShader{"08_MultipleLights.shader", {}, 2},
                    LectureShader{"09_PointLight.shader", {}, 2},
                    LectureShader{"10_PointAndDirectional.shader", {}, 1 + 2},
                    LectureShader{"11_SpotLight.shader", {}, 1 + 3},
                    LectureShader{"12_Deferred.shader", {}, 2}),
    [](const testing::TestParamInfo<LectureShader>& param) {
        return param.param.file.substr(3, param.param.file.find('.') - 3);
    });

}  // namespace
}  // namespace kiln::test
