// kiln_base's inputs and outputs: only regular files are read, within their limit and without
// blocking; outputs replace a regular file atomically with a unique temporary name (40 writers of
// one path all succeed), never an input, a directory, a FIFO or a device, and errors say why.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <thread>

#include "kiln/base/files.h"
#include "kiln/base/text.h"
#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {
namespace fs = std::filesystem;

TEST(BaseFiles, OnlyRegularFilesWithinTheLimitAreRead) {
    ScratchDir dir;
    const std::string file = dir.Write("a.txt", "hello");
    ASSERT_TRUE(base::ReadRegularFile(file, 5));
    EXPECT_EQ(base::ReadRegularFile(file, 5).value(), "hello");
    Result<std::string> r = base::ReadRegularFile(file, 4);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, DiagCode::kCannotReadFile);
    EXPECT_NE(r.error().message.find("larger than the limit of 4 bytes"), std::string::npos);
    r = base::ReadRegularFile(dir.path(), 100);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("is a directory, not a regular file"), std::string::npos);
    r = base::ReadRegularFile("/dev/zero", 100);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("is a character device"), std::string::npos);
    const std::string fifo = dir.path() + "/fifo";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    r = base::ReadRegularFile(fifo, 100);  // returns at once: no writer is waited for
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("is a FIFO"), std::string::npos);
    r = base::ReadRegularFile(dir.path() + "/missing", 100);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("No such file or directory"), std::string::npos);
}

TEST(BaseFiles, OutputsReplaceRegularFilesAndKeepTheirMode) {
    ScratchDir dir;
    const std::string out = dir.Write("out.bin", "old");
    ASSERT_EQ(chmod(out.c_str(), 0640), 0);
    ASSERT_TRUE(base::WriteFileAtomically(out, std::string_view("new")).ok());
    EXPECT_EQ(ReadFile(out), "new");
    struct stat st {};
    ASSERT_EQ(stat(out.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0640u);
    size_t left = 0;
    for (const auto& e : fs::directory_iterator(dir.path()))
        left += e.path().filename().string().find(".tmp.") != std::string::npos;
    EXPECT_EQ(left, 0u);
}

TEST(BaseFiles, AnOutputThatIsAnInputADirectoryAFifoOrADeviceIsRefused) {
    ScratchDir dir;
    const std::string in = dir.Write("in.shader", "source");
    base::WriteOptions options;
    options.inputs = {in};
    Status r = base::WriteFileAtomically(in, std::string_view("pack"), options);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, DiagCode::kCannotWriteFile);
    EXPECT_NE(r.error().message.find("is the input"), std::string::npos) << r.error().message;
    EXPECT_EQ(ReadFile(in), "source");
    // Through a link to the input, too.
    fs::create_symlink(in, dir.path() + "/link");
    EXPECT_FALSE(
        base::WriteFileAtomically(dir.path() + "/link", std::string_view("x"), options).ok());
    EXPECT_EQ(ReadFile(in), "source");

    r = base::WriteFileAtomically(dir.path(), std::string_view("x"));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("is a directory; kiln writes only regular files"),
              std::string::npos);
    const std::string fifo = dir.path() + "/fifo";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    r = base::WriteFileAtomically(fifo, std::string_view("x"));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("is a FIFO"), std::string::npos);
    struct stat st {};
    ASSERT_EQ(lstat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO was replaced";
    // Devices are only checked here, never written: a regression must not replace /dev/null.
    Result<std::string> check = base::CheckOutputPath("/dev/null", {});
    ASSERT_FALSE(check);
    EXPECT_NE(check.error().message.find("is a character device"), std::string::npos);
}

TEST(BaseFiles, AnOutputThatIsALinkIsWrittenThroughAndStaysALink) {
    ScratchDir dir;
    const std::string target = dir.Write("real.kpack", "old");
    const std::string link = dir.path() + "/link.kpack";
    fs::create_symlink("real.kpack", link);
    ASSERT_TRUE(base::WriteFileAtomically(link, std::string_view("new")).ok());
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(ReadFile(target), "new");
    // A dangling link creates its target.
    fs::create_symlink("made.kpack", dir.path() + "/dangling");
    ASSERT_TRUE(base::WriteFileAtomically(dir.path() + "/dangling", std::string_view("made")).ok());
    EXPECT_EQ(ReadFile(dir.path() + "/made.kpack"), "made");
}

// The input guard (on in the kiln tools) is process-wide: ctest runs each test in its own process.
TEST(BaseFilesGuard, AFileReadUnderTheGuardIsNeverReplaced) {
    base::GuardInputFiles();
    ScratchDir dir;
    const std::string read = dir.Write("read.txt", "input");
    ASSERT_TRUE(base::ReadRegularFile(read, 100));
    Result<std::string> checked = base::CheckOutputPath(read, {});
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().message.find("which this command reads"), std::string::npos)
        << checked.error().message;
    EXPECT_FALSE(base::WriteFileAtomically(read, std::string_view("output")).ok());
    // The same file by another name (a hard link) is the same input.
    fs::create_hard_link(read, dir.path() + "/alias.txt");
    EXPECT_FALSE(base::WriteFileAtomically(dir.path() + "/alias.txt", std::string_view("x")).ok());
    EXPECT_EQ(ReadFile(read), "input");
    // A cache read in order to be replaced is not remembered; a file never read is writable.
    const std::string cache = dir.Write("cache.bin", "old");
    ASSERT_TRUE(base::ReadRegularFile(cache, 100, base::ReadAs::kCache));
    EXPECT_TRUE(base::WriteFileAtomically(cache, std::string_view("new")).ok());
    EXPECT_TRUE(base::WriteFileAtomically(dir.path() + "/fresh.txt", std::string_view("x")).ok());
    // A mapped pack or a file another library reads is remembered when noted.
    const std::string noted = dir.Write("noted.txt", "n");
    base::NoteInputFile(noted);
    EXPECT_FALSE(base::WriteFileAtomically(noted, std::string_view("x")).ok());
}

// Files in a folder Kiln fills (--frame-debug): a link there is replaced, not written through.
TEST(BaseFiles, WithoutFollowingLinksALinkIsReplaced) {
    ScratchDir dir;
    const std::string target = dir.Write("target.txt", "keep");
    const std::string link = dir.path() + "/link.txt";
    fs::create_symlink(target, link);
    base::WriteOptions replace_links;
    replace_links.follow_symlinks = false;
    ASSERT_TRUE(base::WriteFileAtomically(link, std::string_view("new"), replace_links).ok());
    EXPECT_EQ(ReadFile(target), "keep");
    EXPECT_FALSE(fs::is_symlink(link));
    EXPECT_EQ(ReadFile(link), "new");
    fs::create_directories(dir.path() + "/folder");
    EXPECT_FALSE(
        base::WriteFileAtomically(dir.path() + "/folder", std::string_view("x"), replace_links)
            .ok());
}

TEST(BaseFiles, AnUnwritableOutputSaysWhy) {
    const Status r = base::WriteFileAtomically("/nonexistent-dir/out.kpack", std::string_view("x"));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("No such file or directory"), std::string::npos)
        << r.error().message;
    EXPECT_EQ(r.error().message.find("Success"), std::string::npos) << r.error().message;
}

// One fixed temporary name let 1 of 40 concurrent renders sharing --usage fail.
TEST(BaseFiles, ConcurrentWritersOfOnePathAllSucceed) {
    ScratchDir dir;
    const std::string out = dir.path() + "/usage.json";
    std::vector<std::thread> threads;
    std::atomic<int> ok{0};
    for (int t = 0; t < 40; ++t) {
        threads.emplace_back([&, t] {
            const std::string text(4096, char('a' + t % 26));
            ok += base::WriteFileAtomically(out, text).ok() ? 1 : 0;
        });
    }
    for (auto& t : threads)
        t.join();
    EXPECT_EQ(ok.load(), 40);
    const std::string final_text = ReadFile(out);
    ASSERT_EQ(final_text.size(), 4096u);
    EXPECT_EQ(final_text, std::string(4096, final_text[0])) << "one writer's whole file";
}

TEST(BaseText, ControlBytesAndInvalidUtf8AreEscapedAndNulDoesNotCut) {
    const std::string in =
        std::string("a\0b", 3) + "\x1b[31m" + "\xff\xfe" + "\t\xc3\xa9" + "\xc2\x9b" + "\x7f";
    EXPECT_EQ(base::EscapeForTerminal(in), "a\\x00b\\x1b[31m\\xff\\xfe\t\xc3\xa9\\xc2\\x9b\\x7f");
}

// The one case folding: ASCII only (a UTF-8 byte is never folded into another).
TEST(Text, CaseFoldingIsAsciiOnly) {
    EXPECT_TRUE(base::EqualsIgnoreCase("ForwardBase", "FORWARDBASE"));
    EXPECT_FALSE(base::EqualsIgnoreCase("ForwardBase", "ForwardBas"));
    EXPECT_FALSE(base::EqualsIgnoreCase("a[", "A{"));  // '[' is not '{' in another case
    EXPECT_EQ(base::ToLower("ZWrite \xc3\x89"), "zwrite \xc3\x89");
    EXPECT_EQ(base::ToUpper("shadowcaster_1"), "SHADOWCASTER_1");
}

}  // namespace
}  // namespace kiln::test
