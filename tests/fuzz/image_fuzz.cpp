// libFuzzer target: Kiln's image readers (kiln/runtime/image.h), the paths of material textures
// (8-bit RGBA), sky images (linear RGB) and glTF images, on arbitrary bytes. Each decode must end
// (libFuzzer's -timeout catches a hang, as stb_image's run-length Radiance loop was) in an image
// whose size matches its dimensions within Kiln's limits, or in a K0032 error with a message; both
// readers decide alike, and decoding twice gives the same pixels.
// The corpus in corpus/image (make_image_seeds.py) is replayed by ctest in every build.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "kiln/runtime/image.h"

namespace {

void Check(bool ok) {
    if (!ok)
        __builtin_trap();
}

template <typename Image>
void CheckResult(const kiln::Result<Image>& r, size_t channels, size_t texel_values) {
    if (!r) {
        Check(r.error().code == kiln::DiagCode::kBadImage && !r.error().message.empty());
        return;
    }
    const Image& image = r.value();
    Check(image.width >= 1 && image.height >= 1);
    Check(image.width <= kiln::runtime::kMaxImageSide &&
          image.height <= kiln::runtime::kMaxImageSide);
    Check(uint64_t(image.width) * image.height <= kiln::runtime::kMaxImageTexels);
    Check(texel_values == size_t(image.width) * image.height * channels);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const auto rgba = kiln::runtime::DecodeImageRgba8(bytes, "fuzz");
    CheckResult(rgba, 4, rgba ? rgba.value().rgba.size() : 0);
    const auto rgb = kiln::runtime::DecodeImageLinearRgb(bytes, "fuzz");
    CheckResult(rgb, 3, rgb ? rgb.value().rgb.size() : 0);
    Check(bool(rgba) == bool(rgb));  // one decision per file, whichever reader asks
    // The same bytes decode to the same pixels every time (no read of uninitialised memory).
    const auto again = kiln::runtime::DecodeImageRgba8(bytes, "fuzz");
    Check(bool(again) == bool(rgba));
    if (again)
        Check(again.value().rgba == rgba.value().rgba);
    return 0;
}
