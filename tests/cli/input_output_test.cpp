// Issue 37: no output of a command may replace a file the command reads, whichever reader reads
// it (scene buffers, material textures, sidecars, .material files, sky images, usage files), and
// no file Kiln reads may hang it (a FIFO texture, a truncated run-length Radiance sky). Each row
// runs kiln on a scene of hand-made files and checks the exit, the diagnostic and that the file
// an output aimed at is byte for byte what it was.
#include <sys/stat.h>

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <functional>
#include <regex>
#include <string>

#include "support/compile_support.h"
#include "support/test_support.h"

namespace kiln::test {
namespace {

namespace fs = std::filesystem;

// A triangle whose positions are in tri.bin, its material "m" mapped by tri.kiln.json to
// m.material (Kiln/Unlit with _MainTex = tex.png), and a Radiance sky.hdr beside it.
void MakeScene(const std::string& dir) {
    std::string text = ReadFile(DataPath("cli/mistakes/triangle.gltf"));
    text =
        std::regex_replace(text, std::regex("\"uri\"\\s*:\\s*\"[^\"]*\""), "\"uri\": \"tri.bin\"");
    text.insert(text.find('{') + 1, "\"materials\": [{\"name\": \"m\"}], ");
    text.insert(text.find("\"attributes\""), "\"material\": 0, ");
    WriteFile(dir + "/tri.gltf", text);
    const float positions[9] = {-1, 0, 0, 1, 0, 0, 0, 1, 0};
    WriteFile(dir + "/tri.bin", std::string(reinterpret_cast<const char*>(positions), 36));
    WriteFile(dir + "/tri.kiln.json",
              "{\"kiln_materials\": 1, \"materials\": {\"m\": \"m.material\"}}");
    WriteFile(dir + "/m.material",
              "{\"kiln_material\": 1, \"shader\": \"Kiln/Unlit\", \"properties\": {\"_MainTex\": "
              "\"tex.png\"}}");
    fs::copy_file(DataPath("fuzz/corpus/image/png_3x2.png"), dir + "/tex.png");
    fs::copy_file(DataPath("fuzz/corpus/image/hdr_rle_9x3.hdr"), dir + "/sky.hdr");
    WriteFile(dir + "/u.json", "{\"kiln_usage\": 1, \"lookups\": []}");
}

// A test name from a row's name: every character that is not a letter or digit becomes '_'.
template <typename Row>
std::string RowName(const ::testing::TestParamInfo<Row>& info) {
    std::string n = info.param.name;
    for (char& ch : n)
        ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    return n;
}

struct Collision {
    const char* name;
    const char* args;    // {T}: the scene's folder, {S}: Kiln's Unlit.shader
    const char* victim;  // the file in {T} that must be left as it was
    int exit_code;
    const char* text;  // a substring of stderr
};

const Collision kCollisions[] = {
    {"render -o onto a scene buffer", "render {T}/tri.gltf -o {T}/tri.bin", "tri.bin", 1,
     "which this command reads"},
    {"render --exr onto a material texture", "render {T}/tri.gltf -o {T}/out.png --exr {T}/tex.png",
     "tex.png", 1, "which this command reads"},
    {"render -o onto the sidecar", "render {T}/tri.gltf -o {T}/tri.kiln.json", "tri.kiln.json", 1,
     "which this command reads"},
    {"render --usage onto a .material", "render {T}/tri.gltf -o {T}/out.png --usage {T}/m.material",
     "m.material", 1, "which this command reads"},
    {"render -o onto the sky image", "render {T}/tri.gltf --sky {T}/sky.hdr -o {T}/sky.hdr",
     "sky.hdr", 1, "which this command reads"},
    {"render --pipeline-cache onto a scene buffer",
     "render {T}/tri.gltf -o {T}/out.png --pipeline-cache {T}/tri.bin", "tri.bin", 1,
     "which this command reads"},
    // Read while drawing, after the checks: the cache is not saved over it.
    {"render --pipeline-cache onto a material texture",
     "render {T}/tri.gltf -o {T}/out.png --pipeline-cache {T}/tex.png", "tex.png", 0, ""},
    {"compile -o onto a --scene buffer",
     "compile {S} --no-cache --scene {T}/tri.gltf -o {T}/tri.bin", "tri.bin", 1,
     "refusing to overwrite it"},
    {"compile -MF onto a sidecar's .material",
     "compile {S} --no-cache --scene {T}/tri.gltf --materials {T}/tri.kiln.json -o {T}/o.kpack "
     "-MF {T}/m.material",
     "m.material", 1, "refusing to overwrite it"},
    {"compile -o onto the --usage file", "compile {S} --no-cache --usage {T}/u.json -o {T}/u.json",
     "u.json", 1, "is the input"},
};

class CollisionTest : public ::testing::TestWithParam<Collision> {};

TEST_P(CollisionTest, AnOutputNeverReplacesAFileTheCommandReads) {
    const Collision& c = GetParam();
    ScratchDir dir;
    MakeScene(dir.path());
    const std::string before = ReadFile(dir.path() + "/" + c.victim);
    std::string args = std::regex_replace(c.args, std::regex("\\{T\\}"), dir.path());
    args = std::regex_replace(args, std::regex("\\{S\\}"), DataPath("../materials/Unlit.shader"));
    const RunResult r = RunKilnWithin(args, 120);
    EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
    if (c.exit_code != 0) {
        EXPECT_NE(r.err.find("[K0002]"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir.path() + "/out.png")) << "an output was written";
    }
    EXPECT_NE(r.err.find(c.text), std::string::npos) << r.err;
    EXPECT_EQ(ReadFile(dir.path() + "/" + c.victim), before) << c.victim << " was overwritten";
}

INSTANTIATE_TEST_SUITE_P(Outputs,
                         CollisionTest,
                         ::testing::ValuesIn(kCollisions),
                         RowName<Collision>);

// --frame-debug DIR: links planted in DIR (index.html and frame.json aimed at the scene and the
// pack, steps/ at another folder) are replaced by the capture's files, never written through.
TEST(FrameDebugFolder, LinksInsideItAreReplacedNotFollowed) {
    ScratchDir dir;
    MakeScene(dir.path());
    const std::string fd = dir.path() + "/fd", elsewhere = dir.path() + "/elsewhere";
    fs::create_directories(fd);
    fs::create_directories(elsewhere);
    fs::copy_file(KILN_MATERIALS_PACK, dir.path() + "/m.kpack");
    const std::string scene = ReadFile(dir.path() + "/tri.gltf");
    const std::string pack = ReadFile(dir.path() + "/m.kpack");
    fs::create_symlink(dir.path() + "/tri.gltf", fd + "/index.html");
    fs::create_symlink(dir.path() + "/m.kpack", fd + "/frame.json");
    fs::create_directory_symlink(elsewhere, fd + "/steps");
    const RunResult r =
        RunKilnWithin("render " + dir.path() + "/tri.gltf --pack " + dir.path() +
                          "/m.kpack --frame-debug " + fd + " -o " + dir.path() + "/out.png",
                      120);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(ReadFile(dir.path() + "/tri.gltf"), scene) << "written through index.html";
    EXPECT_EQ(ReadFile(dir.path() + "/m.kpack"), pack) << "written through frame.json";
    EXPECT_TRUE(fs::is_empty(elsewhere)) << "written through steps/";
    EXPECT_FALSE(fs::is_symlink(fd + "/index.html"));
    EXPECT_FALSE(fs::is_symlink(fd + "/steps"));
    EXPECT_NE(ReadFile(fd + "/index.html").find("<html"), std::string::npos);
}

// A texture that is a FIFO: the renderer opened it and waited for a writer forever; kiln
// validate said nothing. Both now say what it is, and the render binds the default texture.
TEST(BlockingInputs, AFifoTextureIsAWarningNotAHang) {
    ScratchDir dir;
    MakeScene(dir.path());
    fs::remove(dir.path() + "/tex.png");
    ASSERT_EQ(mkfifo((dir.path() + "/tex.png").c_str(), 0600), 0);
    const RunResult r =
        RunKilnWithin("render " + dir.path() + "/tri.gltf -o " + dir.path() + "/out.png", 120);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("[K0013]"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("is a FIFO, not a regular file"), std::string::npos) << r.err;
    const RunResult v = RunKilnWithin(
        "validate --pack " + std::string(KILN_MATERIALS_PACK) + " " + dir.path() + "/m.material",
        60);
    EXPECT_NE(v.err.find("[K6014]"), std::string::npos) << v.err;
    EXPECT_NE(v.err.find("is a FIFO, not a regular file"), std::string::npos) << v.err;
}

// The 49-byte reproducer: a run-length scanline header, then the end of the file. stb_image's
// decoder spun forever on it; Kiln's says where the data ends (K0032).
TEST(BlockingInputs, ATruncatedRunLengthSkyIsAnErrorNotAHang) {
    ScratchDir dir;
    MakeScene(dir.path());
    fs::copy_file(DataPath("fuzz/corpus/image/hdr_rle_truncated.hdr"), dir.path() + "/cut.hdr");
    for (const char* flag : {"--sky", "--ambient"}) {
        const RunResult r = RunKilnWithin("render " + dir.path() + "/tri.gltf " + flag + " " +
                                              dir.path() + "/cut.hdr -o " + dir.path() + "/out.png",
                                          60);
        EXPECT_EQ(r.exit_code, 1) << flag << ": " << r.err;
        EXPECT_NE(r.err.find("[K0032]"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("truncated: its pixel data ends in row 1 of 1"), std::string::npos)
            << r.err;
        EXPECT_FALSE(fs::exists(dir.path() + "/out.png"));
    }
    ASSERT_EQ(mkfifo((dir.path() + "/fifo.hdr").c_str(), 0600), 0);
    const RunResult fifo = RunKilnWithin("render " + dir.path() + "/tri.gltf --sky " + dir.path() +
                                             "/fifo.hdr -o " + dir.path() + "/out.png",
                                         60);
    EXPECT_EQ(fifo.exit_code, 1) << fifo.err;
    EXPECT_NE(fifo.err.find("is a FIFO, not a regular file"), std::string::npos) << fifo.err;
}

// The smaller holes of issue 37, one command each.
struct Hole {
    const char* name;
    const char* args;
    int exit_code;
    const char* code;
    const char* text;
};

const Hole kHoles[] = {
    {"--time nan", "render {T}/tri.gltf --time nan -o {T}/out.png", 2, "",
     "must be a finite number of seconds"},
    {"--program-timeout 0", "compile {S} --no-cache --program-timeout 0 -o {T}/o.kpack", 2, "",
     "must be a number of seconds greater than 0, at most 86400"},
    {"pipeline cache in a missing folder",
     "render {T}/tri.gltf -o {T}/out.png --pipeline-cache {T}/missing/cache.bin", 0, "K0024",
     "the pipeline cache cannot be saved: its folder"},
    {"compile cache that cannot be created",
     "compile {S} --cache-dir /dev/null/kiln -o {T}/o.kpack", 0, "K0002",
     "the compile cache cannot be written (Not a directory); compiling without it"},
    {"sidecar material is a FIFO", "render {T}/fifo_scene.gltf -o {T}/out.png", 1, "K0001",
     "is a FIFO, not a regular file"},
    {"validate of a 17 MiB material", "validate --pack {P} {T}/big.material", 1, "K0001",
     "larger than the limit of 16777216 bytes"},
    {"compile --materials of a 17 MiB material",
     "compile {S} --no-cache --materials {T}/big.material -o {T}/o.kpack", 1, "K0001",
     "larger than the limit of 16777216 bytes"},
};

class HoleTest : public ::testing::TestWithParam<Hole> {};

TEST_P(HoleTest, SaysWhatIsWrong) {
    const Hole& h = GetParam();
    ScratchDir dir;
    MakeScene(dir.path());
    // A scene whose sidecar maps its material to a FIFO, and a material past the size limit.
    fs::copy_file(dir.path() + "/tri.gltf", dir.path() + "/fifo_scene.gltf");
    WriteFile(dir.path() + "/fifo_scene.kiln.json",
              "{\"kiln_materials\": 1, \"materials\": {\"m\": \"fifo.material\"}}");
    ASSERT_EQ(mkfifo((dir.path() + "/fifo.material").c_str(), 0600), 0);
    WriteFile(dir.path() + "/big.material",
              "{\"kiln_material\": 1, \"shader\": \"Kiln/Unlit\"}" + std::string(17u << 20, ' '));
    std::string args = std::regex_replace(h.args, std::regex("\\{T\\}"), dir.path());
    args = std::regex_replace(args, std::regex("\\{S\\}"), DataPath("../materials/Unlit.shader"));
    args = std::regex_replace(args, std::regex("\\{P\\}"), KILN_MATERIALS_PACK);
    const RunResult r = RunKilnWithin(args, 120);
    EXPECT_EQ(r.exit_code, h.exit_code) << r.err;
    if (*h.code != '\0') {
        EXPECT_NE(r.err.find(std::string("[") + h.code + "]"), std::string::npos) << r.err;
    }
    EXPECT_NE(r.err.find(h.text), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(Holes, HoleTest, ::testing::ValuesIn(kHoles), RowName<Hole>);

}  // namespace
}  // namespace kiln::test
