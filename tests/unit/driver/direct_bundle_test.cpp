// The direct mode's manifest text (driver/direct_bundle.h): what is written reads back the same;
// a manifest cut at any byte, a number that names no earlier line, a malformed key or an unknown
// line is refused whole, never read in part or past its end.
#include "driver/direct_bundle.h"

#include <gtest/gtest.h>

namespace kiln::driver {
namespace {

const std::string kKeyA(32, 'a'), kKeyB(32, 'b'), kKeyC(32, 'c');

DirectBundle Sample() {
    DirectBundle b;
    b.files = {kKeyA + "\tT:UnityCG.cginc", kKeyB + "\tS:inc.cginc"};
    b.includes = {"1\tS:direct.shader\tinc.cginc\tS:inc.cginc", "0\tS:inc.cginc\tnone.h\t"};
    b.sets = {{{0, 1}, {0, 1}}, {{}, {}}};
    b.entries = {{kKeyA, kKeyB, 0}, {kKeyC, kKeyA, 1}, {kKeyB, kKeyC, 0}};
    return b;
}

void ExpectSame(const DirectBundle& a, const DirectBundle& b) {
    EXPECT_EQ(a.files, b.files);
    EXPECT_EQ(a.includes, b.includes);
    EXPECT_EQ(a.sets, b.sets);
    ASSERT_EQ(a.entries.size(), b.entries.size());
    for (size_t i = 0; i < a.entries.size(); ++i) {
        EXPECT_EQ(a.entries[i].direct, b.entries[i].direct);
        EXPECT_EQ(a.entries[i].result, b.entries[i].result);
        EXPECT_EQ(a.entries[i].set, b.entries[i].set);
    }
}

TEST(DirectBundle, WhatIsWrittenReadsBackTheSame) {
    const std::string text = SerializeDirectBundle(Sample());
    const std::optional<DirectBundle> read = ParseDirectBundle(text);
    ASSERT_TRUE(read);
    ExpectSame(*read, Sample());
    EXPECT_EQ(SerializeDirectBundle(*read), text);
    EXPECT_TRUE(ParseDirectBundle(SerializeDirectBundle(DirectBundle{})));
}

// Every prefix that does not end a line is refused; one that does reads as the lines it holds
// (the cache's hash over the whole entry is what refuses those).
TEST(DirectBundle, EveryTruncatedPrefixIsRefusedOrReadsItsWholeLines) {
    const std::string text = SerializeDirectBundle(Sample());
    for (size_t n = 0; n < text.size(); ++n) {
        const std::string prefix = text.substr(0, n);
        const std::optional<DirectBundle> read = ParseDirectBundle(prefix);
        if (n == 0 || prefix.back() != '\n') {
            EXPECT_FALSE(read) << n;
            continue;
        }
        ASSERT_TRUE(read) << n;
        EXPECT_EQ(SerializeDirectBundle(*read), prefix) << n;
    }
}

TEST(DirectBundle, BadLinesAreRefused) {
    const std::string good = SerializeDirectBundle(Sample());
    ASSERT_TRUE(ParseDirectBundle(good));
    auto with = [&](const std::string& line) { return ParseDirectBundle(good + line + "\n"); };
    EXPECT_FALSE(with("entry\t" + kKeyA + "\t" + kKeyB + "\t2"));  // no set 2
    EXPECT_FALSE(with("entry\t" + kKeyA + "\t" + kKeyB + "\t-1"));
    EXPECT_FALSE(with("entry\t" + kKeyA + "\t" + kKeyB + "\t99999999999999999999"));
    EXPECT_FALSE(with("entry\t" + kKeyA + "\tabc\t0"));  // a short key
    EXPECT_FALSE(with("entry\t" + std::string(32, 'G') + "\t" + kKeyB + "\t0"));
    EXPECT_FALSE(with("set\t0,2\t"));  // no file 2
    EXPECT_FALSE(with("set\t0,,1\t0"));
    EXPECT_FALSE(with("set\t01\t"));                    // a leading zero
    EXPECT_FALSE(with("file\t" + kKeyA + "\tS:late"));  // a file after the entries
    EXPECT_FALSE(with("set\t\t5"));                     // no include 5
    EXPECT_FALSE(with("file\t" + kKeyA));               // no tag
    EXPECT_FALSE(with("include\t2\tS:a\tb\tS:b"));      // neither 0 nor 1
    EXPECT_FALSE(with("include\t1\tS:a\t\tS:b"));       // no header
    EXPECT_FALSE(with("unknown\tline"));
    EXPECT_FALSE(with(""));                              // an empty line
    EXPECT_FALSE(ParseDirectBundle("kiln-direct 1\n"));  // the old format
    EXPECT_FALSE(ParseDirectBundle(std::string(200, 'x')));
    // A set may name only lines before it.
    EXPECT_FALSE(ParseDirectBundle("kiln-direct 2\nset\t0\t\nfile\t" + kKeyA + "\tS:a\n"));
}

TEST(DirectBundle, FieldsWithTabsOrLineBreaksAreNotStorable) {
    EXPECT_TRUE(DirectStorable("S:folder with spaces/inc.cginc"));
    EXPECT_FALSE(DirectStorable("a\tb"));
    EXPECT_FALSE(DirectStorable("a\nb"));
    EXPECT_FALSE(DirectStorable("a\rb"));
}

}  // namespace
}  // namespace kiln::driver
