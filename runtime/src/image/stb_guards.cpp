#include "image/stb_guards.h"

#include "kiln/runtime/image.h"

namespace kiln::runtime::image {
namespace {

uint8_t At(std::string_view b, size_t i) {
    return uint8_t(b[i]);
}

uint32_t Be32(std::string_view b, size_t at) {
    return uint32_t(At(b, at)) << 24 | uint32_t(At(b, at + 1)) << 16 |
           uint32_t(At(b, at + 2)) << 8 | At(b, at + 3);
}

// PNG: the size in IHDR (stb_image refuses one past 1 GiB only as "unknown image type"), then the
// chunks: a length past the end of the file is a truncated file, which stb_image would first
// allocate in full.
std::string CheckPng(std::string_view b) {
    if (b.size() >= 24 && b.substr(12, 4) == "IHDR") {
        if (std::string big = SizeProblem(Be32(b, 16), Be32(b, 20)); !big.empty())
            return big;
    }
    for (size_t at = 8; at + 8 <= b.size();) {
        const uint64_t length = Be32(b, at);
        if (length > b.size() - at - 8) {
            return "the file is truncated: a PNG chunk of " + std::to_string(length) +
                   " bytes where " + std::to_string(b.size() - at - 8) + " are left";
        }
        if (b.substr(at + 4, 4) == "IEND")
            return "";
        at += 12 + length;  // length, type, data, CRC
    }
    return "";
}

}  // namespace

std::string StbHazard(std::string_view bytes) {
    if (bytes.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8))
        return CheckPng(bytes);
    return "";
}

size_t JpegStart(std::string_view bytes) {
    if (bytes.empty() || At(bytes, 0) != 0xFF)
        return 0;
    size_t at = 1;
    while (at < bytes.size() && At(bytes, at) == 0xFF)
        ++at;
    return at < bytes.size() && At(bytes, at) == 0xD8 ? at + 1 : 0;
}

std::string SizeProblem(uint64_t width, uint64_t height) {
    if (width >= 1 && height >= 1 && width <= kMaxImageSide && height <= kMaxImageSide &&
        width * height <= kMaxImageTexels)
        return "";
    return "the image is " + std::to_string(width) + "x" + std::to_string(height) +
           "; Kiln reads images of 1 to " + std::to_string(kMaxImageSide) +
           " texels a side and at most " + std::to_string(kMaxImageTexels) + " texels";
}

std::string TooShortFor(size_t bytes, uint64_t texels, bool jpeg, bool progressive) {
    // With a factor of 2 to spare over the densest coding of each format.
    const uint64_t per_byte = jpeg ? 2 * 256 : 2 * 8256;
    if (progressive || texels / per_byte <= bytes)
        return "";
    return "the file is truncated: " + std::to_string(bytes) +
           " bytes cannot hold that many texels";
}

}  // namespace kiln::runtime::image
