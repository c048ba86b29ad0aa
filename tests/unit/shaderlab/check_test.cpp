// Semantic checks that need the whole tree (kiln::shaderlab::Check).
#include <gtest/gtest.h>

#include "support/test_support.h"

namespace kiln::test {
namespace {

TEST(Check, DuplicatePropertyHasNoteAtFirstDeclaration) {
    ParseOutcome out = ParseText(
        "Shader \"x\" {\nProperties {\n  _A (\"A\", Float) = 0\n  _A (\"B\", Color) = "
        "(1,1,1,1)\n}\n}");
    ASSERT_EQ(out.diags.error_count(), 1u) << Summarize(out.diags);
    const Diagnostic& d = out.diags.all()[0];
    EXPECT_EQ(d.code, DiagCode::kDuplicateProperty);
    EXPECT_EQ(d.range.begin.line, 4u);
    ASSERT_EQ(d.notes.size(), 1u);
    EXPECT_EQ(d.notes[0].range.begin.line, 3u);
}

TEST(Check, EveryStateSlotIsCheckedForReferences) {
    // Each command references an undeclared property: every one must be reported.
    ParseOutcome out = ParseText(R"(Shader "x" {
Properties { _Known ("K", Float) = 0 }
Category { Cull [_a]
SubShader { ZTest [_b] ZWrite [_c] ZClip [_d] AlphaToMask [_e] Conservative [_f]
  Pass { Offset [_g], [_h] Blend [_i] [_j], [_k] [_l] BlendOp [_m], [_n] ColorMask [_o]
         Stencil { Ref [_p] Comp [_q] } Cull [_Known] }
} } })");
    size_t undeclared = 0;
    for (const Diagnostic& d : out.diags.all()) {
        undeclared += d.code == DiagCode::kUndeclaredProperty ? 1 : 0;
    }
    EXPECT_EQ(undeclared, 17u) << Summarize(out.diags);
    // As in Unity, an undeclared name is a global property: a warning, not an error.
    EXPECT_EQ(out.diags.error_count(), 0u) << Summarize(out.diags);
}

TEST(Check, UndeclaredReferenceWithoutPropertiesBlockHasNoNote) {
    ParseOutcome out = ParseText("Shader \"x\" { SubShader { Cull [_C] } }");
    ASSERT_EQ(out.diags.all().size(), 1u);
    EXPECT_EQ(out.diags.all()[0].severity, Severity::kWarning);
    EXPECT_TRUE(out.diags.all()[0].notes.empty());
}

TEST(Check, UndeclaredReferenceSuggestsTheClosestProperty) {
    ParseOutcome out = ParseText(
        "Shader \"x\" { Properties { _Cull (\"Cull\", Float) = 2 }\n"
        "SubShader { Cull [_Cul] ZTest [unity_GUIZTestMode] } }");
    ASSERT_EQ(out.diags.all().size(), 2u) << Summarize(out.diags);
    EXPECT_EQ(out.diags.all()[0].message,
              "'_Cul' is not declared in Properties; as in Unity its value is a global property "
              "that the material or the runtime must set; did you mean '_Cull'?");
    ASSERT_EQ(out.diags.all()[0].notes.size(), 1u);
    EXPECT_EQ(out.diags.all()[0].notes[0].message, "'_Cull' declared here");
    EXPECT_EQ(out.diags.all()[1].message.find("'unity_GUIZTestMode' is not declared"), 0u);
    EXPECT_EQ(out.diags.all()[1].notes[0].message, "properties are declared here");
}

TEST(Check, ProgramsAtTheRightLevels) {
    ParseOutcome ok = ParseText(
        "Shader \"x\" { CGINCLUDE ENDCG Category { HLSLINCLUDE ENDHLSL SubShader { CGINCLUDE ENDCG "
        "Pass { CGINCLUDE ENDCG CGPROGRAM ENDCG } } } }");
    EXPECT_TRUE(ok.diags.all().empty()) << Summarize(ok.diags);
    ParseOutcome bad = ParseText("Shader \"x\" { HLSLPROGRAM ENDHLSL }");
    ASSERT_EQ(bad.diags.error_count(), 1u);
    EXPECT_EQ(bad.diags.all()[0].code, DiagCode::kProgramOutsidePass);
    EXPECT_EQ(bad.diags.all()[0].range.end.column - bad.diags.all()[0].range.begin.column, 11u);
}

TEST(Check, SurfacePragmaInsideAPassIsMisplaced) {
    ParseOutcome out = ParseText(
        "Shader \"x\" { SubShader { Pass { CGPROGRAM\n#pragma surface surf Standard\nENDCG } } }");
    ASSERT_EQ(out.diags.error_count(), 1u);
    EXPECT_EQ(out.diags.all()[0].code, DiagCode::kBadSurfaceShader);
    EXPECT_EQ(out.diags.all()[0].range.begin.line, 2u);
}

// Unity's terrain splat shaders declare `#pragma surface` in a Shader-level CGINCLUDE and put
// their CGPROGRAMs in the SubShaders: no K3009 for those programs (they are the surface
// shader's, where Unity expects them; driver/surface_passes.h generates their passes). A Category's
// CGINCLUDE counts too; a SubShader-level CGPROGRAM of a shader without one is still misplaced.
TEST(Check, ProgramsOfASurfaceShaderDeclaredInAnIncludeAreNotMisplaced) {
    for (const char* text :
         {"Shader \"x\" { CGINCLUDE\n#pragma surface surf Lambert\nENDCG SubShader { CGPROGRAM "
          "ENDCG } SubShader { CGPROGRAM ENDCG } }",
          "Shader \"x\" { Category { CGINCLUDE\n#pragma surface surf Lambert\nENDCG SubShader { "
          "CGPROGRAM ENDCG } } }",
          "Shader \"x\" { SubShader { CGINCLUDE\n#pragma surface surf Lambert\nENDCG CGPROGRAM "
          "ENDCG } }"}) {
        ParseOutcome out = ParseText(text);
        EXPECT_EQ(out.diags.error_count(), 0u) << text << "\n" << Summarize(out.diags);
    }
    ParseOutcome sibling = ParseText(
        "Shader \"x\" { Category { CGINCLUDE\n#pragma surface surf Lambert\nENDCG } SubShader { "
        "CGPROGRAM ENDCG } }");
    EXPECT_EQ(sibling.diags.error_count(), 1u) << Summarize(sibling.diags);
    EXPECT_EQ(sibling.diags.all().back().code, DiagCode::kProgramOutsidePass);
}

TEST(Check, DuplicatePassNamesAreCaseInsensitive) {
    ParseOutcome out =
        ParseText("Shader \"x\" { SubShader { Pass { Name \"Base\" } Pass { Name \"BASE\" } } }");
    ASSERT_EQ(out.diags.all().size(), 1u);
    EXPECT_EQ(out.diags.all()[0].code, DiagCode::kDuplicatePassName);
    EXPECT_EQ(out.diags.all()[0].severity, Severity::kWarning);
}

}  // namespace
}  // namespace kiln::test
