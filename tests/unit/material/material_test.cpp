// The .material parser and validator: every error kind with its position, the shipped
// instances, and robustness on every truncated prefix.
#include "kiln/material/material.h"
#include "kiln/material/sidecar.h"

#include <gtest/gtest.h>

#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {

using material::Material;

// "line:col Knnnn message (note)" per diagnostic; each names the file it was given.
std::string Brief(const DiagnosticList& issues) {
    std::string s;
    for (const Diagnostic& d : issues.all()) {
        EXPECT_EQ(d.file, "t.material");
        s += std::to_string(d.range.begin.line) + ":" + std::to_string(d.range.begin.column) + " " +
             FormatDiagCode(d.code) + " " + d.message +
             (d.notes.empty() ? "" : " (" + d.notes[0].message + ")") + "\n";
    }
    return s;
}

DiagnosticList Parse(const std::string& text, Material* out = nullptr) {
    DiagnosticList issues;
    Material m;
    material::ParseMaterial(text, "t.material", m, issues);
    if (out)
        *out = m;
    return issues;
}

TEST(MaterialParse, ReadsEveryField) {
    Material m;
    const auto issues = Parse(R"({
  "kiln_material": 1,
  "shader": "Kiln/StandardMetallic",
  "description": "gold",
  "properties": {"_Color": [1, 0.5, 0.25], "_Metallic": 1,
                 "_MainTex": {"path": "a.png", "scale": [2, 3], "offset": [0.5, 0]},
                 "_BumpMap": "n.png"},
  "keywords": ["_NORMALMAP"],
  "render_state": {"Cull": "off", "Blend": ["one", "OneMinusSrcAlpha"], "ColorMask": "rgb"}
})",
                              &m);
    ASSERT_EQ(Brief(issues), "");
    EXPECT_EQ(m.shader, "Kiln/StandardMetallic");
    EXPECT_EQ(m.shader_pos.line, 3u);
    EXPECT_EQ(m.shader_pos.column, 13u);
    ASSERT_EQ(m.properties.size(), 4u);
    EXPECT_EQ(m.properties[0].numbers, (std::vector<double>{1, 0.5, 0.25}));
    EXPECT_EQ(m.properties[2].texture, "a.png");
    EXPECT_EQ(m.properties[2].scale, (std::array<double, 2>{2, 3}));
    EXPECT_EQ(m.properties[2].offset, (std::array<double, 2>{0.5, 0}));
    EXPECT_EQ(m.properties[3].texture, "n.png");
    ASSERT_EQ(m.keywords.size(), 1u);
    ASSERT_EQ(m.render_state.size(), 3u);
    EXPECT_EQ(m.render_state[0].values, (std::vector<std::string>{"Off"}));
    EXPECT_EQ(m.render_state[1].values, (std::vector<std::string>{"One", "OneMinusSrcAlpha"}));
    EXPECT_EQ(m.render_state[2].values, (std::vector<std::string>{"RGB"}));
}

TEST(MaterialParse, SyntaxErrorsPointAtTheOffendingCharacter) {
    EXPECT_EQ(Brief(Parse("{\n  \"shader\": \"a\",\n}")), "3:1 K6001 trailing comma before '}'\n");
    EXPECT_EQ(Brief(Parse("{\"shader\" \"a\"}")),
              "1:11 K6001 expected ':' after the key, found '\"'\n");
    EXPECT_EQ(Brief(Parse("{\"shader\": 'a'}")), "1:12 K6001 expected a value, found '''\n");
    EXPECT_EQ(Brief(Parse("{\"shader\": \"a\"} x")),
              "1:17 K6001 unexpected 'x' after the JSON value\n");
    EXPECT_EQ(Brief(Parse("")), "1:1 K6001 expected a value, found end of file\n");
    EXPECT_EQ(Brief(Parse("{\"a\": 1e999}")), "1:7 K6001 number out of range\n");
    EXPECT_EQ(Brief(Parse(std::string(100, '['))), "1:65 K6001 nesting deeper than 64 levels\n");
}

TEST(MaterialParse, StructuralErrors) {
    EXPECT_EQ(Brief(Parse("[]")), "1:1 K6003 a material must be a JSON object, not an array\n");
    EXPECT_EQ(Brief(Parse("{}")), "1:1 K6005 material has no \"shader\" field\n");
    EXPECT_EQ(Brief(Parse(R"({"shader": 3})")),
              "1:12 K6003 'shader' must be a string, not a number\n");
    EXPECT_EQ(Brief(Parse(R"({"shadr": "x", "shader": "y"})")),
              "1:2 K6002 unknown material field 'shadr' (did you mean 'shader')\n");
    EXPECT_EQ(Brief(Parse(R"({"shader": "y", "kiln_material": 2})")),
              "1:34 K6004 unsupported material format version (this build reads version 1)\n");
    // found by the fuzzer: a version too large for an int
    EXPECT_EQ(Brief(Parse(R"({"shader": "y", "kiln_material": 1e300})")),
              "1:34 K6004 unsupported material format version (this build reads version 1)\n");
    EXPECT_EQ(Brief(Parse(R"({"shader": "y", "properties": {"_A": 1, "_A": 2, "_B": true}})")),
              "1:41 K6015 property '_A' is set twice\n"
              "1:56 K6003 property '_B' must be a number, an array of 1 to 4 numbers, or a "
              "texture\n");
    EXPECT_EQ(Brief(Parse(R"({"shader": "y", "keywords": ["A", "A", 1]})")),
              "1:35 K6015 keyword 'A' is listed twice\n1:40 K6003 a keyword must be a string\n");
    EXPECT_EQ(
        Brief(Parse(R"({"shader": "y", "render_state": {"ColorMask": "GRR", "ZTest": "lequal"}})")),
        "1:47 K6013 ColorMask must be \"0\" or a combination of R, G, B and A such as "
        "\"RGB\"\n");
}

// A pack with one shader whose Properties and keywords cover every check.
const pack::Pack& TestPack() {
    static std::vector<uint8_t> bytes;
    static pack::Pack p;
    if (bytes.empty()) {
        ScratchDir dir;
        const std::string path = dir.Write("m.shader", R"(Shader "Test/M" {
    Properties {
        _Color ("Color", Color) = (1, 1, 1, 1)
        _Offset ("Offset", Vector) = (0, 0, 0, 0)
        _Gloss ("Gloss", Range(0.25, 2)) = 1
        _Count ("Count", Int) = 1
        _MainTex ("Tex", 2D) = "white" {}
        [Toggle(_RIMLIGHT)] _Rim ("Rim", Float) = 0
        [ToggleOff] _Specular ("Specular", Float) = 1
        [KeywordEnum(Low, High Quality)] _Mode ("Mode", Float) = 0
    }
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #pragma multi_compile DIRECTIONAL POINT
        #pragma shader_feature _ _RED _GREEN
        #pragma shader_feature _GLOW
        #pragma shader_feature _RIMLIGHT
        #pragma shader_feature _SPECULAR_OFF
        #pragma shader_feature _MODE_LOW _MODE_HIGH_QUALITY
        float4 _Color; float4 _Offset; float _Gloss; int _Count; sampler2D _MainTex;
        float4 vert(float4 p : POSITION) : SV_POSITION { return p + _Offset; }
        float4 frag() : SV_Target { return _Color * _Gloss * _Count * tex2D(_MainTex, 0); }
        ENDCG
    } }
})");
        CompileRun run = Compile({path});
        EXPECT_TRUE(run.out.ok) << test::Brief(run.diags);
        bytes = run.out.pack;
        EXPECT_TRUE(kiln::test::OpenInto(bytes, p));
    }
    return p;
}

std::string Validate(const std::string& props,
                     const std::string& keywords = "[]",
                     const std::string& shader = "Test/M") {
    const std::string text = "{\"shader\": \"" + shader + "\",\n\"properties\": " + props +
                             ",\n\"keywords\": " + keywords + "}";
    Material m;
    DiagnosticList issues;
    EXPECT_TRUE(material::ParseMaterial(text, "t.material", m, issues)) << Brief(issues);
    const bool ok = material::ValidateMaterial(m, TestPack(), "", issues);
    EXPECT_EQ(ok, !issues.has_errors());
    return Brief(issues);
}

TEST(MaterialValidate, AcceptsWellTypedValues) {
    EXPECT_EQ(Validate(R"({"_Color": [1, 0, 0], "_Offset": [1, 2, 3, 4], "_Gloss": 0.25,
                           "_Count": 3, "_MainTex": "x.png"})",
                       R"(["_RED", "_GLOW"])"),
              "");
}

// As in Unity, [Toggle], [ToggleOff] and [KeywordEnum] properties drive their keywords; a
// property the material does not set contributes through its default.
TEST(MaterialKeywords, TogglesAndKeywordEnumsDriveKeywords) {
    auto enabled = [](const std::string& props, const std::string& keywords = "[]") {
        const std::string text = "{\"shader\": \"Test/M\", \"properties\": " + props +
                                 ", \"keywords\": " + keywords + "}";
        Material m;
        DiagnosticList issues;
        EXPECT_TRUE(material::ParseMaterial(text, "t.material", m, issues)) << Brief(issues);
        std::string out;
        for (const std::string& k :
             material::EnabledKeywords(m, TestPack(), *TestPack().FindShader("Test/M")))
            out += k + " ";
        return out;
    };
    EXPECT_EQ(enabled("{}"), "_MODE_LOW ");
    EXPECT_EQ(enabled(R"({"_Rim": 1})"), "_MODE_LOW _RIMLIGHT ");
    EXPECT_EQ(enabled(R"({"_Specular": 0, "_Mode": 1})"), "_MODE_HIGH_QUALITY _SPECULAR_OFF ");
    EXPECT_EQ(enabled(R"({"_Mode": 7})", R"(["_GLOW"])"), "_GLOW _MODE_HIGH_QUALITY ");
}

TEST(MaterialValidate, AKeywordItsToggleTurnsOffIsAWarning) {
    EXPECT_EQ(Validate(R"({"_Rim": 0})", R"(["_RIMLIGHT"])"),
              "3:14 K6016 keyword '_RIMLIGHT' is listed, but property '_Rim' = 0 turns it off "
              "(the property drives the keyword as in Unity: set the property, not the keyword)\n");
    EXPECT_EQ(Validate(R"({"_Rim": 1})", R"(["_RIMLIGHT"])"), "");
}

TEST(MaterialValidate, UnknownShaderAndPropertySuggestTheClosestName) {
    EXPECT_EQ(Validate("{}", "[]", "Test/N"),
              "1:12 K6006 no shader 'Test/N' in the pack (did you mean 'Test/M')\n");
    EXPECT_EQ(Validate(R"({"_Colour": [1, 1, 1]})"),
              "2:16 K6007 shader 'Test/M' has no property '_Colour' (did you mean '_Color')\n");
    EXPECT_EQ(Validate(R"({"_Zebra": 1})"),
              "2:16 K6007 shader 'Test/M' has no property '_Zebra'\n");
}

TEST(MaterialValidate, WrongTypesAndOutOfRangeValues) {
    EXPECT_EQ(Validate(R"({"_Color": [1, 1]})"),
              "2:16 K6008 property '_Color' is a Color: give 3 or 4 numbers (r, g, b[, a])\n");
    EXPECT_EQ(Validate(R"({"_Color": "red.png"})"),
              "2:16 K6008 property '_Color' is a Color, not a texture\n");
    EXPECT_EQ(Validate(R"({"_Gloss": [1, 2]})"),
              "2:16 K6008 property '_Gloss' is a Range: give one number\n");
    EXPECT_EQ(Validate(R"({"_Count": 1.5})"),
              "2:16 K6008 property '_Count' is a Int: give one whole number\n");
    EXPECT_EQ(
        Validate(R"({"_MainTex": 1})"),
        "2:16 K6008 property '_MainTex' is a 2D texture, not a number (write a path string or "
        "{\"path\": ..., \"scale\": [x, y], \"offset\": [x, y]})\n");
    EXPECT_EQ(Validate(R"({"_Gloss": 2.5})"),
              "2:16 K6009 value 2.5 of property '_Gloss' is outside its range (declared "
              "Range(0.25, 2))\n");
    EXPECT_EQ(Validate(R"({"_Gloss": 0.2})"),
              "2:16 K6009 value 0.2 of property '_Gloss' is outside its range (declared "
              "Range(0.25, 2))\n");
}

TEST(MaterialValidate, KeywordsMustBeDeclaredAndNotAlternatives) {
    EXPECT_EQ(
        Validate("{}", R"(["_GLOWW"])"),
        "3:14 K6010 keyword '_GLOWW' is not declared by shader 'Test/M' (did you mean '_GLOW')\n");
    EXPECT_EQ(Validate("{}", R"(["_RED", "_GREEN"])"),
              "3:22 K6011 keywords '_RED' and '_GREEN' are alternatives of one keyword set (enable "
              "at most one keyword of each set)\n");
    EXPECT_EQ(
        Validate("{}", R"(["POINT"])"),
        "3:14 K6012 keyword 'POINT' is a multi_compile keyword the renderer chooses per draw; "
        "the material setting is ignored\n");
}

TEST(MaterialValidate, EveryTruncatedPrefixFailsCleanly) {
    const std::string text = ReadFile(DataPath("../materials/StandardMetallic.material"));
    for (size_t n = 0; n < text.size(); ++n) {
        DiagnosticList issues;
        Material m;
        const bool ok = material::ParseMaterial(text.substr(0, n), "t.material", m, issues);
        // Every prefix that stops before the closing brace is incomplete JSON.
        if (n <= text.rfind('}')) {
            EXPECT_FALSE(ok) << n;
            ASSERT_TRUE(issues.has_errors()) << n;
            EXPECT_LE(issues.all().front().range.begin.offset, n);
        }
    }
}

// The sidecar reader lives with the material reader (no renderer needed): paths relative to the
// sidecar, errors with the file, line and column.
TEST(MaterialSidecar, ReadsMaterialsAndAmbientAndPointsAtMistakes) {
    ScratchDir dir;
    const std::string good = dir.Write(
        "s.kiln.json",
        R"({"kiln_materials": 1, "materials": {"Red": "m/red.material"}, "ambient": [0.1, 0.2, 0.3]})");
    const Result<material::MaterialSidecar> read = material::ReadMaterialSidecar(good);
    ASSERT_TRUE(read) << read.error().message;
    EXPECT_EQ(read.value().materials.at("Red"), dir.path() + "/m/red.material");
    EXPECT_TRUE(read.value().has_ambient);
    EXPECT_FLOAT_EQ(read.value().ambient[2], 0.3f);
    const std::string bad = dir.Write("t.kiln.json", "{\n  \"materiels\": {}\n}");
    const Result<material::MaterialSidecar> typo = material::ReadMaterialSidecar(bad);
    ASSERT_FALSE(typo);
    EXPECT_EQ(typo.error().code, DiagCode::kBadScene);
    EXPECT_EQ(typo.error().message,
              bad + ":2:3: unknown field 'materiels' (expected kiln_materials, materials, "
                    "ambient, lights, description)");
    const Result<material::MaterialSidecar> missing =
        material::ReadMaterialSidecar(dir.path() + "/none.kiln.json");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, DiagCode::kCannotReadFile);
}

TEST(MaterialSidecar, AmbientMayBeUnitysGradient) {
    ScratchDir dir;
    const std::string good =
        dir.Write("g.kiln.json", R"({"kiln_materials": 1, "ambient": {"sky": [0.4, 0.5, 0.9],
            "equator": [0.2, 0.2, 0.15], "ground": [0.05, 0.03, 0.02]}})");
    const Result<material::MaterialSidecar> read = material::ReadMaterialSidecar(good);
    ASSERT_TRUE(read) << read.error().message;
    EXPECT_TRUE(read.value().has_ambient);
    EXPECT_TRUE(read.value().trilight);
    EXPECT_FLOAT_EQ(read.value().ambient[2], 0.9f);
    EXPECT_FLOAT_EQ(read.value().equator[0], 0.2f);
    EXPECT_FLOAT_EQ(read.value().ground[1], 0.03f);
    const std::string partial =
        dir.Write("p.kiln.json", "{\"ambient\": {\"sky\": [1, 1, 1],\n \"ground\": [0, 0, 0]}}");
    const Result<material::MaterialSidecar> missing = material::ReadMaterialSidecar(partial);
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().message,
              partial +
                  ":1:13: a gradient 'ambient' needs 'equator' (sky, equator and ground, "
                  "each three numbers)");
    const std::string short_colour =
        dir.Write("c.kiln.json", R"({"ambient": {"sky": [1, 1], "equator": [0, 0, 0],
            "ground": [0, 0, 0]}})");
    const Result<material::MaterialSidecar> bad = material::ReadMaterialSidecar(short_colour);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("'sky' must be three numbers (linear RGB)"),
              std::string::npos);
}

}  // namespace
}  // namespace kiln::test
