// The engine's names, from the one table both sides read (kiln/pack/engine_names.h): every
// default texture the ShaderLab check accepts is one the renderer binds by that name, and every
// built-in global the renderer fills is one the compiler does not ask to be a Property.
#include "kiln/pack/engine_names.h"

#include <gtest/gtest.h>

#include <cctype>
#include <string>

#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln {
namespace {

std::string ShaderReading(const std::string& globals, const std::string& texture_default) {
    return "Shader \"Bridge/Names\" {\n"
           "  Properties { _MainTex (\"Tex\", 2D) = \"" +
           texture_default +
           "\" {} }\n"
           "  SubShader { Pass {\n"
           "    HLSLPROGRAM\n#pragma vertex vert\n#pragma fragment frag\n"
           "sampler2D _MainTex;\n" +
           globals +
           "float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n"
           "float4 frag() : SV_Target { return tex2D(_MainTex, 0.5) * USE; }\n"
           "    ENDHLSL\n  } }\n}\n";
}

TEST(EngineNames, EveryEngineGlobalIsNotAskedToBeAProperty) {
    std::string globals, use = "1";
    for (const char* g : pack::kEngineGlobals) {
        EXPECT_TRUE(pack::IsEngineGlobal(g)) << g;
        globals += std::string("float4 ") + g + ";\n";  // the type does not matter here
        use += std::string(" + ") + g;
    }
    EXPECT_TRUE(pack::IsEngineGlobal("unity_ObjectToWorld"));
    EXPECT_FALSE(pack::IsEngineGlobal("_Color"));
    test::ScratchDir dir;
    const std::string engine = "#define USE (" + use + ")\n";
    test::CompileRun run =
        test::Compile({dir.Write("engine.shader", ShaderReading(globals + engine, "white"))});
    ASSERT_TRUE(run.out.ok) << test::Brief(run.diags);
    EXPECT_EQ(test::Brief(run.diags).find("K5006"), std::string::npos) << test::Brief(run.diags);
    // The same check does warn for a global no one sets.
    run = test::Compile(
        {dir.Write("mine.shader", ShaderReading("float4 _Mine;\n#define USE _Mine\n", "white"))});
    ASSERT_TRUE(run.out.ok) << test::Brief(run.diags);
    EXPECT_NE(test::Brief(run.diags).find("K5006"), std::string::npos) << test::Brief(run.diags);
}

TEST(EngineNames, EveryDefaultTextureTheCompilerAcceptsIsOneTheRendererBinds) {
    test::ScratchDir dir;
    for (const pack::DefaultTexture& t : pack::kDefaultTextures) {
        std::string capitalized = t.name;
        capitalized[0] = char(std::toupper(static_cast<unsigned char>(capitalized[0])));
        for (const std::string& name : {std::string(t.name), capitalized}) {
            const test::CompileRun run =
                test::Compile({dir.Write("t.shader", ShaderReading("#define USE 1\n", name))});
            EXPECT_EQ(test::Brief(run.diags).find("K3011"), std::string::npos)
                << name << ": " << test::Brief(run.diags);
            ASSERT_NE(pack::FindDefaultTexture(name), nullptr) << name;
            EXPECT_STREQ(pack::FindDefaultTexture(name)->name, t.name);
        }
    }
    const test::CompileRun run =
        test::Compile({dir.Write("t.shader", ShaderReading("#define USE 1\n", "whit"))});
    EXPECT_NE(test::Brief(run.diags).find("K3011"), std::string::npos) << test::Brief(run.diags);
    EXPECT_EQ(pack::FindDefaultTexture("whit"), nullptr);
    ASSERT_NE(pack::FindDefaultTexture(pack::kDefaultTextureFallback), nullptr);
}

}  // namespace
}  // namespace kiln
