// Reading a frame's targets back (render/frame_readback.cpp): every format a frame target has
// decodes to what a shader reads from it, and the halves the frame debugger keeps for its texel
// readout convert exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "render/frame_internal.h"

namespace kiln::runtime {
namespace {

// Every half converts to a float and back to itself (NaNs to a NaN); floats between two halves
// go to the nearer, ties to the even one.
TEST(Readback, FloatToHalfIsTheNearestHalf) {
    for (uint32_t h = 0; h < 0x10000; ++h) {
        const float f = HalfToFloat(uint16_t(h));
        if (std::isnan(f)) {
            EXPECT_TRUE(std::isnan(HalfToFloat(FloatToHalf(f)))) << h;
            continue;
        }
        ASSERT_EQ(FloatToHalf(f), h) << f;
    }
    EXPECT_EQ(FloatToHalf(1.0f + 1.0f / 2048), FloatToHalf(1.0f));  // tie: to even
    EXPECT_EQ(FloatToHalf(1.0f + 3.0f / 2048), uint16_t(FloatToHalf(1.0f) + 2));
    EXPECT_EQ(FloatToHalf(65519.0f), 0x7BFF);          // the largest half
    EXPECT_EQ(FloatToHalf(65520.0f), 0x7C00);          // rounds past it: infinity
    EXPECT_EQ(FloatToHalf(std::ldexp(1.0f, -25)), 0);  // tie with 0: to even
    EXPECT_EQ(FloatToHalf(std::ldexp(1.5f, -25)), 1);  // the smallest subnormal
    EXPECT_EQ(FloatToHalf(-std::numeric_limits<float>::infinity()), 0xFC00);
}

std::vector<uint8_t> Bytes(uint32_t v) {
    std::vector<uint8_t> out(4);
    std::memcpy(out.data(), &v, 4);
    return out;
}

TEST(Readback, EveryTargetFormatDecodesToWhatAShaderReads) {
    FrameTarget srgb{"gbuffer0", VK_FORMAT_R8G8B8A8_SRGB, false, {}};
    const std::vector<float> s = DecodeTexels(srgb, Bytes(0x80FF0000u | 188u));
    ASSERT_EQ(s.size(), 4u);
    EXPECT_NEAR(s[0], 0.5029f, 1e-3f);  // sRGB 188 is linear 0.503
    EXPECT_EQ(s[1], 0.0f);
    EXPECT_EQ(s[2], 1.0f);
    EXPECT_NEAR(s[3], 128.0f / 255, 1e-6f);  // alpha as stored
    FrameTarget normal{"gbuffer2", VK_FORMAT_A2B10G10R10_UNORM_PACK32, false, {}};
    const std::vector<float> n = DecodeTexels(normal, Bytes(1023u | 512u << 10 | 3u << 30));
    EXPECT_EQ(n, (std::vector<float>{1.0f, 512.0f / 1023, 0.0f, 1.0f}));
    FrameTarget depth{"depth", VK_FORMAT_D24_UNORM_S8_UINT, true, {}};
    const std::vector<float> d = DecodeTexels(depth, Bytes(0xAB000000u | 0xFFFFFFu));
    EXPECT_EQ(d, (std::vector<float>{1.0f}));  // the stencil bits are not depth
    EXPECT_EQ(DecodedChannels(depth), 1u);
    FrameTarget mask{"screen-space shadows", VK_FORMAT_R8_UNORM, false, {}};
    EXPECT_EQ(DecodeTexels(mask, {0, 255}), (std::vector<float>{0.0f, 1.0f}));
    EXPECT_EQ(DecodedChannels(mask), 1u);
}

}  // namespace
}  // namespace kiln::runtime
