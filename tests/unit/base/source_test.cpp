#include "kiln/source.h"

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace kiln::test {
namespace {

TEST(SourceFile, LocationsAndLines) {
    const SourceFile f("a.shader", "ab\r\ncd\n\nlast");
    EXPECT_EQ(f.line_count(), 4u);
    EXPECT_EQ(f.LocAt(0).line, 1u);
    EXPECT_EQ(f.LocAt(1).column, 2u);
    EXPECT_EQ(f.LocAt(4).line, 2u);
    EXPECT_EQ(f.LocAt(4).column, 1u);
    EXPECT_EQ(f.LocAt(7).line, 3u);
    EXPECT_EQ(f.LocAt(8).line, 4u);
    EXPECT_EQ(f.LocAt(9).column, 2u);
    EXPECT_EQ(f.LocAt(1000).offset, 12u);  // clamped to the end
    EXPECT_EQ(f.Line(1), "ab");            // '\r' dropped
    EXPECT_EQ(f.Line(3), "");
    EXPECT_EQ(f.Line(4), "last");
    EXPECT_EQ(f.Line(0), "");
    EXPECT_EQ(f.Line(5), "");
}

TEST(SourceFile, ReadErrorsAreMessagesNotExceptions) {
    Result<SourceFile> r = ReadSourceFile("/nonexistent/dir/x.shader");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("cannot open"), std::string::npos);
    Result<SourceFile> dir = ReadSourceFile("/");
    EXPECT_FALSE(dir.ok());
}

TEST(SourceFile, ReadsFromDisk) {
    Result<SourceFile> r = ReadSourceFile(DataPath("lecture/01_Lambert.shader"));
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_GT(r.value().text().size(), 100u);
}

}  // namespace
}  // namespace kiln::test
