// Kiln's image readers (kiln/runtime/image.h): the Radiance decoder against values written here,
// every truncated prefix of every seed image refused (never decoded with rows of zeros), the size
// limits, the refused formats and non-regular files.
#include "kiln/runtime/image.h"

#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "kiln/runtime/scene.h"

namespace kiln::runtime {
namespace {

namespace fs = std::filesystem;

std::string Seed(const std::string& name) {
    std::ifstream in(std::string(KILN_SOURCE_DIR) + "/tests/fuzz/corpus/image/" + name,
                     std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

const std::string kHeader = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";

TEST(RadianceImage, FlatPixelsDecodeToTheirValues) {
    // 2x1: (1, 0.5, 0.25) is mantissas (128, 64, 32) at exponent 129; black is exponent 0.
    const std::string file = kHeader + "-Y 1 +X 2\n" + std::string("\x80\x40\x20\x81", 4) +
                             std::string("\x10\x10\x10\x00", 4);
    Result<LinearRgbImage> image = DecodeImageLinearRgb(file, "flat.hdr");
    ASSERT_TRUE(image) << image.error().message;
    ASSERT_EQ(image.value().width, 2u);
    ASSERT_EQ(image.value().height, 1u);
    const std::vector<float> expected = {1.0f, 0.5f, 0.25f, 0.0f, 0.0f, 0.0f};
    EXPECT_EQ(image.value().rgb, expected);
}

TEST(RadianceImage, RunLengthScanlinesDecodeLikeFlatOnes) {
    // 8 texels of one colour: each component one run of 8 (count 136), the exponent a literal.
    std::string rle = kHeader + "-Y 1 +X 8\n" + std::string("\x02\x02\x00\x08", 4);
    rle += std::string("\x88\x80", 2) + std::string("\x88\x40", 2) + std::string("\x88\x20", 2);
    rle += std::string("\x08", 1) + std::string(8, '\x81');
    Result<LinearRgbImage> image = DecodeImageLinearRgb(rle, "rle.hdr");
    ASSERT_TRUE(image) << image.error().message;
    for (uint32_t i = 0; i < 8; ++i) {
        EXPECT_EQ(image.value().rgb[i * 3 + 0], 1.0f);
        EXPECT_EQ(image.value().rgb[i * 3 + 1], 0.5f);
        EXPECT_EQ(image.value().rgb[i * 3 + 2], 0.25f);
    }
    Result<Rgba8Image> ldr = DecodeImageRgba8(rle, "rle.hdr");
    ASSERT_TRUE(ldr);
    EXPECT_EQ(ldr.value().rgba[0], 255);  // 1.0 -> 255, as stb_image tone-maps
    EXPECT_EQ(ldr.value().rgba[3], 255);
}

// The hang of issue 37 (stb_image spun on a count of zero at the end of the file) and its
// neighbours: each ends in K0032 saying what is wrong.
TEST(RadianceImage, DamagedRunLengthDataIsAnError) {
    const struct {
        std::string bytes;
        const char* text;
    } cases[] = {
        {Seed("hdr_rle_truncated.hdr"), "truncated: its pixel data ends in row 1 of 1"},
        {Seed("hdr_rle_zero_count.hdr"), "bad run-length data in row 1: a count of 0"},
        {kHeader + "-Y 1 +X 8\n" + std::string("\x02\x02\x00\x08\x89\x01", 6) + std::string(20, 1),
         "a count of 9 with 8 texels left"},
        {kHeader + "-Y 1 +X 8\n" + std::string("\x02\x02\x00\x09", 4) + std::string(40, 1),
         "says it is 9 texels long; the image is 8 wide"},
        {kHeader + "-Y 2 +X 1\n" + std::string(4, 1), "ends in row 2 of 2"},
        {"#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n1234", "Kiln reads 32-bit_rle_rgbe"},
        {kHeader + "+Y 1 +X 1\n1234", "'-Y <height> +X <width>'"},
        {kHeader + "-Y 99999 +X 99999\n", "Kiln reads images of 1 to 16384"},
        {"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n", "the header does not end"},
    };
    for (const auto& c : cases) {
        Result<LinearRgbImage> image = DecodeImageLinearRgb(c.bytes, "bad.hdr");
        ASSERT_FALSE(image) << c.text;
        EXPECT_EQ(image.error().code, DiagCode::kBadImage);
        EXPECT_NE(image.error().message.find(c.text), std::string::npos) << image.error().message;
        EXPECT_EQ(image.error().message.rfind("'bad.hdr': ", 0), 0u) << image.error().message;
    }
}

// Every seed in every format decodes whole, and every strictly shorter prefix of it is an error:
// a file cut short never decodes to an image with missing rows read as zero. (GIF's last byte is
// the trailer after the image, which the reader does not need.)
TEST(ImageReaders, EveryTruncatedPrefixOfEverySeedIsRefused) {
    for (const char* name :
         {"png_3x2.png", "bmp_3x2.bmp", "tga_3x2.tga", "tga_rle_3x2.tga", "gif_1x1.gif",
          "hdr_flat_4x2.hdr", "hdr_rle_9x3.hdr", "jpeg_8x8.jpg"}) {
        const std::string bytes = Seed(name);
        ASSERT_FALSE(bytes.empty()) << name;
        Result<Rgba8Image> whole = DecodeImageRgba8(bytes, name);
        ASSERT_TRUE(whole) << name << ": " << whole.error().message;
        EXPECT_EQ(whole.value().rgba.size(),
                  size_t(whole.value().width) * whole.value().height * 4);
        const size_t needed = std::string(name).ends_with(".gif") ? bytes.size() - 1 : bytes.size();
        for (size_t n = 0; n < needed; ++n) {
            Result<Rgba8Image> cut = DecodeImageRgba8(std::string_view(bytes).substr(0, n), name);
            EXPECT_FALSE(cut) << name << " cut to " << n << " of " << bytes.size()
                              << " bytes decoded";
            if (!cut) {
                EXPECT_EQ(cut.error().code, DiagCode::kBadImage);
            }
        }
    }
}

TEST(ImageReaders, TheSeedsDecodeToTheirPixels) {
    // png_3x2: texel (x, y) is (60x, 60y, 128, 255), as make_image_seeds.py writes it.
    for (const char* name : {"png_3x2.png", "tga_3x2.tga", "tga_rle_3x2.tga"}) {
        Result<Rgba8Image> image = DecodeImageRgba8(Seed(name), name);
        ASSERT_TRUE(image) << name;
        ASSERT_EQ(image.value().width, 3u);
        ASSERT_EQ(image.value().height, 2u);
        const uint8_t* t = &image.value().rgba[(1 * 3 + 2) * 4];  // x = 2, y = 1
        EXPECT_EQ(t[0], 120) << name;
        EXPECT_EQ(t[1], 60) << name;
        EXPECT_EQ(t[2], 128) << name;
        EXPECT_EQ(t[3], 255) << name;
    }
}

TEST(ImageReaders, RefusedFormatsAndSizesSayWhy) {
    EXPECT_NE(DecodeImageRgba8(Seed("pic_refused.pic"), "x").error().message.find("Softimage PIC"),
              std::string::npos);
    EXPECT_NE(DecodeImageRgba8(Seed("pnm_refused.ppm"), "x").error().message.find("a PNM image"),
              std::string::npos);
    EXPECT_NE(DecodeImageRgba8("hello", "x").error().message.find("not an image Kiln can read"),
              std::string::npos);
    // A PNG header that claims 20000 x 20000 texels is refused before anything is allocated,
    // and so is one of 16385 x 1 (within stb_image's own limit, past Kiln's).
    std::string png = Seed("png_3x2.png");
    png[16] = 0, png[17] = 0, png[18] = char(0x4e), png[19] = char(0x20);
    png[20] = 0, png[21] = 0, png[22] = char(0x4e), png[23] = char(0x20);
    Result<Rgba8Image> big = DecodeImageRgba8(png, "big.png");
    ASSERT_FALSE(big);
    EXPECT_NE(big.error().message.find("the image is 20000x20000"), std::string::npos)
        << big.error().message;
    png[16] = 0, png[17] = 0, png[18] = char(0x40), png[19] = char(0x01);
    png[20] = 0, png[21] = 0, png[22] = 0, png[23] = 1;
    big = DecodeImageRgba8(png, "wide.png");
    ASSERT_FALSE(big);
    EXPECT_NE(big.error().message.find("the image is 16385x1; Kiln reads images of 1 to 16384"),
              std::string::npos)
        << big.error().message;
}

// Found by kiln_fuzz_image under the sanitizers in stb_image 2.27: JPEG Huffman tables of more
// than 256 codes written past their arrays and decoder state read before it was set (JPEG now goes
// to libjpeg-turbo, which refuses these files), a PNG chunk allocated at its declared size before
// it is read (2 GiB in a 100-byte file), and a header's whole size allocated before the file is
// found too short.
TEST(ImageReaders, InputsThatReachStbImageDefectsAreRefused) {
    for (const char* name : {"jpeg_dht_257_codes.jpg", "jpeg_dht_junk_before_tables.jpg",
                             "jpeg_dht_table_past_segment.jpg", "jpeg_undefined_huffman_table.jpg",
                             "png_idat_2gib.png"}) {
        Result<Rgba8Image> image = DecodeImageRgba8(Seed(name), name);
        ASSERT_FALSE(image) << name;
        EXPECT_EQ(image.error().code, DiagCode::kBadImage);
    }
    EXPECT_NE(DecodeImageRgba8(Seed("png_idat_2gib.png"), "x")
                  .error()
                  .message.find("the file is truncated: a PNG chunk of"),
              std::string::npos);
    EXPECT_NE(DecodeImageRgba8(Seed("jpeg_dht_257_codes.jpg"), "x")
                  .error()
                  .message.find("Bogus Huffman table definition"),
              std::string::npos);
    // An uncompressed TGA header of 16384 x 8192 texels and 40 bytes in all.
    std::string tga = Seed("tga_3x2.tga").substr(0, 18) + std::string(22, '\x7f');
    tga[12] = 0, tga[13] = char(0x40), tga[14] = 0, tga[15] = char(0x20);
    Result<Rgba8Image> big = DecodeImageRgba8(tga, "big.tga");
    ASSERT_FALSE(big);
    EXPECT_NE(big.error().message.find("40 bytes cannot hold that many texels"), std::string::npos)
        << big.error().message;
}

TEST(ImageReaders, AFifoIsAnErrorNotAWait) {
    const std::string fifo = testing::TempDir() + "/kiln_image_fifo_" + std::to_string(getpid());
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    Result<Rgba8Image> image = ReadImageRgba8(fifo);
    ASSERT_FALSE(image);
    EXPECT_NE(image.error().message.find("is a FIFO, not a regular file"), std::string::npos);
    Result<std::shared_ptr<const Sky>> sky = LoadSky(fifo, 1.0f);
    ASSERT_FALSE(sky);
    EXPECT_NE(sky.error().message.find("is a FIFO, not a regular file"), std::string::npos);
    fs::remove(fifo);
}

}  // namespace
}  // namespace kiln::runtime
