#include "hlsl/reduce.h"

#include <gtest/gtest.h>

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
