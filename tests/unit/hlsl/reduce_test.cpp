#include "hlsl/reduce.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace kiln::hlsl {
namespace {

TEST(Reduce, DropsFunctionsTheEntryPointDoesNotReachAndKeepsLines) {
    const std::string text =
        "#line 1 \"a.shader\"\n"
        "#pragma vertexvert\n"
        "struct S { float4 p : POSITION; };\n"
        "float4 _Color;\n"
        "float helper(float x) { return x * 2; }\n"
        "float unused(float x)\n{\n  return x;\n}\n"
        "float4 vert(S s) : SV_POSITION { return s.p * helper(1); }\n"
        "float4 frag() : SV_Target { return _Color; }\n";
    const std::string reduced = ReduceToEntryPoint(text, "vert").text;
    EXPECT_EQ(reduced,
              "#line 1 \"a.shader\"\n"
              "\n"
              "struct S { float4 p : POSITION; };\n"
              "float4 _Color;\n"
              "float helper(float x) { return x * 2; }\n"
              "\n\n\n\n"
              "float4 vert(S s) : SV_POSITION { return s.p * helper(1); }\n"
              "\n");
}

TEST(Reduce, VariantsDifferingOnlyInUnreachedCodeGiveTheSameText) {
    const std::string a =
        "cbuffer C : register(b0) { float4 x; }\n"
        "float4 frag() : SV_Target { return 1; }\n"
        "float4 vert() : SV_POSITION { return x; }\n";
    const std::string b =
        "cbuffer C : register(b0) { float4 x; }\n"
        "float4 frag() : SV_Target { return 2 * x; }\n"
        "float4 vert() : SV_POSITION { return x; }\n";
    EXPECT_EQ(ReduceToEntryPoint(a, "vert").text, ReduceToEntryPoint(b, "vert").text);
    EXPECT_NE(ReduceToEntryPoint(a, "frag").text, ReduceToEntryPoint(b, "frag").text);
}

TEST(Reduce, TransitiveCallsAndGlobalInitializersAreKept) {
    const std::string text =
        "float c() { return 1; }\n"
        "static const float k = c();\n"
        "float b() { return 2; }\n"
        "float a() { return b(); }\n"
        "float4 main() : SV_Target { return a() + k; }\n";
    EXPECT_EQ(ReduceToEntryPoint(text, "main").text, text);
    EXPECT_TRUE(ReduceToEntryPoint(text, "main").functions_if_entry_missing.empty());
}

TEST(Reduce, AMissingEntryPointListsTheFunctionsThatExist) {
    const std::string text =
        "struct S { float4 p : POSITION; };\n"
        "float4 vert(S s) : SV_POSITION { return s.p; }\n"
        "float4 frag() : SV_Target { return 1; }\n";
    const Reduced r = ReduceToEntryPoint(text, "fragg");
    EXPECT_EQ(r.functions_if_entry_missing, (std::vector<std::string>{"vert", "frag"}));
}

// Unity's includes declare cbuffers, textures and structs most programs never read: those nothing
// reached names go as unreached functions do (their line breaks stay). A cbuffer goes or stays
// whole, by its name or any member's; a loose uniform stays (the $Global block's layout).
TEST(Reduce, DropsTheStructsCbuffersResourcesAndStaticsNothingReachedNames) {
    const std::string text =
        "struct Unused { float4 a; };\n"
        "struct V { float4 p : POSITION; };\n"
        "cbuffer UnityPerCamera { float4 _Time; float4 _SinTime; };\n"
        "cbuffer Other : register(b3) {\n float4x4 m;\n float4 arr[4] : packoffset(c4);\n"
        " row_major float3 a1, a2;\n}\n"
        "[[vk::push_constant]] cbuffer Push { float4 q; };\n"
        "Texture2D _MainTex; SamplerState sampler_MainTex;\n"
        "Texture2D<float4> _Unused : register(t3);\n"
        "uniform sampler2D _Dx9[2];\n"
        "static const float kUnused = 2, kUnused2[2] = {1, 2};\n"
        "static float3 kUsed = float3(1, 2, 3);\n"
        "float4 _Color;\n"
        "float4 vert(V v) : SV_POSITION {\n"
        "  return v.p * _Time.y + _MainTex.SampleLevel(sampler_MainTex, 0, 0) * arr[2] + kUsed.x;\n"
        "}\n";
    EXPECT_EQ(ReduceToEntryPoint(text, "vert").text,
              "\n"
              "struct V { float4 p : POSITION; };\n"
              "cbuffer UnityPerCamera { float4 _Time; float4 _SinTime; };\n"
              "cbuffer Other : register(b3) {\n float4x4 m;\n float4 arr[4] : packoffset(c4);\n"
              " row_major float3 a1, a2;\n}\n"
              "\n"
              "Texture2D _MainTex; SamplerState sampler_MainTex;\n"
              "\n"
              "\n"
              "\n"
              "static float3 kUsed = float3(1, 2, 3);\n"
              "float4 _Color;\n"
              "float4 vert(V v) : SV_POSITION {\n"
              "  return v.p * _Time.y + _MainTex.SampleLevel(sampler_MainTex, 0, 0) * arr[2] + "
              "kUsed.x;\n"
              "}\n");
    // By a member of the second declarator, and through a kept static's type and a function.
    const std::string chain =
        "cbuffer Other { float3 a1, a2; };\n"
        "struct Light { float3 dir; };\n"
        "static Light gLight;\n"
        "float3 L() { return gLight.dir * a2; }\n"
        "float4 frag() : SV_Target { return float4(L(), 1); }\n"
        "float4 vert() : SV_POSITION { return 0; }\n";
    EXPECT_EQ(ReduceToEntryPoint(chain, "frag").text,
              chain.substr(0, chain.find("float4 vert")) + "\n");
    // (A cbuffer ends at its brace: the `;` after it is an empty declaration, kept.)
    EXPECT_EQ(ReduceToEntryPoint(chain, "vert").text,
              ";\n\n\n\n\nfloat4 vert() : SV_POSITION { return 0; }\n");
    // Without dropping declarations (the names a "did you mean" reads), only functions go.
    EXPECT_EQ(ReduceToEntryPoints(chain, Tokenize(chain), {"vert"}, nullptr, false)[0].text,
              chain.substr(0, chain.find("float3 L()")) +
                  "\n\nfloat4 vert() : SV_POSITION { return 0; }\n");
}

// What is not one of those shapes exactly stays, named or not: a cbuffer holding a struct, an
// anonymous struct's variable, a typedef, a prototype, a sampler with a state block, a resource
// declared twice in one statement.
TEST(Reduce, DeclarationsNotReadWithCertaintyAreKept) {
    const std::string text =
        "cbuffer I { struct { float4 c; } arr[2]; };\n"
        "struct { float a; } g;\n"
        "typedef float4 T;\n"
        "static float f(float x);\n"
        "SamplerState s { Filter = MIN_MAG_MIP_LINEAR; };\n"
        "Texture2D t1, t2;\n"
        "static struct S2 { float b; } h;\n"
        "float4 frag() : SV_Target { return 1; }\n";
    EXPECT_EQ(ReduceToEntryPoint(text, "frag").text, text);
}

// The worker reduces a variant's two stages from the rewrite's tokens, splitting the text once:
// the same texts as reducing each alone.
TEST(Reduce, BothEntryPointsFromOneSplitMatchEachAlone) {
    const std::string text =
        "#line 1 \"a.shader\"\n"
        "struct V { float4 p : POSITION; };\n"
        "float Patch() { return 1; }\n"
        "float shared(float x) { return x; }\n"
        "  #pragma fragment frag\n"
        "[patchconstantfunc(\"Patch\")] float4 vert(V v) : SV_POSITION { return v.p * shared(2); "
        "}\n"
        "float onlyFrag() {\n#line 40 \"b.cginc\"\n return 3; }\n"
        "float4 frag() : SV_Target { return onlyFrag() + shared(1); }";
    const std::vector<Reduced> both = ReduceToEntryPoints(text, Tokenize(text), {"vert", "frag"});
    ASSERT_EQ(both.size(), 2u);
    EXPECT_EQ(both[0].text, ReduceToEntryPoint(text, "vert").text);
    EXPECT_EQ(both[1].text, ReduceToEntryPoint(text, "frag").text);
    // A dropped function keeps its #line directive and its newlines; the pragma line is blank;
    // the string naming Patch keeps it; the last line has no newline to keep.
    EXPECT_EQ(both[0].text,
              "#line 1 \"a.shader\"\n"
              "struct V { float4 p : POSITION; };\n"
              "float Patch() { return 1; }\n"
              "float shared(float x) { return x; }\n"
              "\n"
              "[patchconstantfunc(\"Patch\")] float4 vert(V v) : SV_POSITION { return v.p * "
              "shared(2); }\n"
              "\n#line 40 \"b.cginc\"\n\n"
              "");
    EXPECT_NE(both[1].text.find("onlyFrag() {"), std::string::npos);
    EXPECT_EQ(both[1].text.find("Patch() {"), std::string::npos);
}

// A pass's preamble splits its prefix once (MakeReducePrefix); every program whose output goes on
// from it with a line break is reduced from that split: the same texts, tokens and names as
// splitting the whole text, wherever the prefix ends (inside a function, a cbuffer, a directive,
// between items), for reached and missing entry points.
TEST(Reduce, APrefixSplitOnceReducesAsTheWholeText) {
    const std::string text =
        "#line 1 \"a.shader\"\n"
        "cbuffer C {\n float4 c;\n};\n"
        "struct V { float4 p : POSITION; };\n"
        "float Patch() { return 1; }\n"
        "float shared(float x)\n{\n  return x;\n}\n"
        "  #pragma fragment frag\n"
        "static float g = shared(4);\n"
        "float onlyFrag() {\n#line 40 \"b.cginc\"\n return 3; }\n"
        "[patchconstantfunc(\"Patch\")] float4 vert(V v) : SV_POSITION\n{ return v.p * shared(2); "
        "}\n"
        "float4 frag() : SV_Target { return onlyFrag() + shared(1) + c.x; }\n"
        "float unused() { return 0; }";
    const std::vector<std::vector<std::string>> entry_sets = {{"vert", "frag"}, {"main"}};
    size_t cuts = 0;
    for (size_t cut = 0; cut < text.size(); ++cut) {
        if (text[cut] != '\n')
            continue;
        ++cuts;
        std::shared_ptr<const ReducePrefix> prefix;
        std::vector<Token> head;
        {
            const std::string start = text.substr(0, cut);  // gone before the prefix is used
            head = Tokenize(start);
            prefix = MakeReducePrefix(start, head);
        }
        for (const auto& entries : entry_sets) {
            const std::vector<Reduced> want = ReduceToEntryPoints(text, Tokenize(text), entries);
            const std::vector<Reduced> got =
                ReduceToEntryPoints(text, TokenizeAfter(text, cut, head), entries, prefix.get());
            ASSERT_EQ(got.size(), want.size());
            for (size_t e = 0; e < want.size(); ++e) {
                EXPECT_EQ(got[e].text, want[e].text) << "cut at " << cut;
                ASSERT_EQ(got[e].tokens.size(), want[e].tokens.size()) << "cut at " << cut;
                for (size_t k = 0; k < want[e].tokens.size(); ++k) {
                    const Token& g = got[e].tokens[k];
                    const Token& w = want[e].tokens[k];
                    EXPECT_TRUE(g.begin == w.begin && g.end == w.end && g.ident == w.ident &&
                                g.text.data() == got[e].text.data() + w.begin)
                        << "cut at " << cut << ", token " << k;
                }
                EXPECT_EQ(got[e].functions_if_entry_missing, want[e].functions_if_entry_missing)
                    << "cut at " << cut;
            }
        }
    }
    EXPECT_EQ(cuts, 18u);
    // The reduction itself: frag reaches onlyFrag and shared, not Patch or unused.
    const std::vector<Reduced> r = ReduceToEntryPoints(text, Tokenize(text), {"frag"});
    EXPECT_NE(r[0].text.find("onlyFrag() {"), std::string::npos);
    EXPECT_EQ(r[0].text.find("unused()"), std::string::npos);
}

// The reduced text's tokens are made from the whole text's (the rewrite reads them): each must be
// what tokenizing the reduced text gives, at the same bytes of it.
void ExpectOwnTokens(const std::string& text, const std::vector<std::string>& entries) {
    const std::vector<Reduced> reduced = ReduceToEntryPoints(text, Tokenize(text), entries);
    for (const Reduced& r : reduced) {
        const std::vector<Token> want = Tokenize(r.text);
        ASSERT_EQ(r.tokens.size(), want.size()) << r.text;
        for (size_t i = 0; i < want.size(); ++i) {
            EXPECT_EQ(r.tokens[i].begin, want[i].begin) << i << " in " << r.text;
            EXPECT_EQ(r.tokens[i].end, want[i].end) << i;
            EXPECT_EQ(r.tokens[i].ident, want[i].ident) << i;
            EXPECT_EQ(r.tokens[i].text.data(), r.text.data() + want[i].begin) << i;
        }
        EXPECT_TRUE(SameTokens(r.tokens, want)) << r.text;
    }
}

TEST(Reduce, TokensOfTheReducedTextAreItsOwn) {
    ExpectOwnTokens(
        "#line 1 \"a.shader\"\n"
        "struct V { float4 p : POSITION; };\n"
        "float gone(float x) { return x; } float4 kept = 1;\n"
        "  #pragma fragment frag\n"
        "float4 vert(V v) : SV_POSITION { return v.p * kept; }\n"
        "float onlyFrag() {\n#line 40 \"b.cginc\"\n return 3; } float4 frag() : SV_Target "
        "{ return onlyFrag(); }",
        {"vert", "frag"});
    // A '#' token after a dropped function on its line would start the line once the function is
    // gone, where the tokenizer skips the line as a directive: the tokens are made again.
    ExpectOwnTokens("float gone() { return 1; } # x;\nfloat4 vert() : SV_POSITION { return 0; }\n",
                    {"vert"});
    ExpectOwnTokens("float gone() { return 1; }\t\r# x;\nfloat4 vert() { return 0; }", {"vert"});
    // Every text of a few pieces, each kept or dropped.
    const char* pieces[] = {"float a() { return 1; }",
                            " ",
                            "\n",
                            "#line 3 \"c\"\n",
                            "#pragma x\n",
                            "float4 vert() { return a(); }",
                            "int g;",
                            "# y;",
                            "float b() { return 2; }\n",
                            "struct S { int i; };"};
    for (int mask = 0; mask < 1 << 10; mask += 7) {
        std::string text;
        for (int p = 0; p < 10; ++p) {
            if (mask & (1 << p))
                text += pieces[(p * 3 + mask) % 10];
        }
        ExpectOwnTokens(text, {"vert", "b"});
    }
}

}  // namespace
}  // namespace kiln::hlsl

namespace kiln::hlsl {
namespace {

// The tokens of a text's head, made once, and the rest's are the whole text's where the rest
// starts a line; elsewhere (a token could span the seam) the text is tokenized whole.
TEST(Tokens, AHeadsTokensJoinTheRestsWhereALineStarts) {
    const std::string head = "float4 a = 1.5e+3;\n#line 3 \"x.h\"\nfloat b = a.x";
    const std::string text = head + "\n#pragma once\nfloat c = b >>= 2; \"s\" c.y\n";
    const std::vector<Token> whole = Tokenize(text);
    EXPECT_TRUE(SameTokens(TokenizeAfter(text, head.size(), Tokenize(head)), whole));
    // The same tokens of a copy of the text are not the text's own.
    const std::string copy = text;
    EXPECT_FALSE(SameTokens(Tokenize(copy), whole));
    EXPECT_FALSE(SameTokens(std::vector<Token>(whole.begin(), whole.end() - 1), whole));
    // Cut inside a line: the head's tokens are not used (`a.x` and the rest would not split).
    const std::string cut = "float4 a = 1";
    const std::vector<Token> wrong = {{0, 2, true, "fl"}};
    EXPECT_TRUE(SameTokens(TokenizeAfter(text, cut.size() - 4, wrong), whole));
    EXPECT_TRUE(SameTokens(TokenizeAfter(text, text.size(), wrong), whole));
}

}  // namespace
}  // namespace kiln::hlsl
