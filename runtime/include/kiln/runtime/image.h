// Decoding the images Kiln reads (material textures, sky images, glTF images): bounded in input
// size, dimensions and work, and strict about truncation. A file that ends before its pixels do is
// an error (K0032) that says how far it got, never an image whose missing rows read as zero.
//
// Radiance .hdr (RGBE, flat and run-length encoded) is decoded by Kiln itself: stb_image's
// run-length decoder spins forever on a scanline that ends early. JPEG goes to libjpeg-turbo; PNG,
// TGA, BMP, PSD and GIF to stb_image (compiled into Kiln, guarded against the defects of the
// version Debian ships) through a reader that notes any read past the end of the bytes, which is
// how truncation is told. Softimage PIC and PNM, which Unity does not import either, are refused.
// docs/runtime.md, "Images".
#ifndef KILN_RUNTIME_IMAGE_H_
#define KILN_RUNTIME_IMAGE_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "kiln/result.h"

namespace kiln::runtime {

inline constexpr uint64_t kMaxImageFileBytes = uint64_t{512} << 20;
inline constexpr uint32_t kMaxImageSide = 16384;
inline constexpr uint64_t kMaxImageTexels = uint64_t{1} << 27;  // 16384 x 8192

// 8-bit RGBA as stored (sRGB-encoded colour, or data); an HDR file is tone-mapped as stb_image
// does (gamma 2.2, clamped).
struct Rgba8Image {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgba;
};

// Linear RGB: an HDR file's radiance as stored, an 8-bit file decoded from sRGB.
struct LinearRgbImage {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> rgb;
};

// True when `bytes` start as a Radiance file ("#?RADIANCE" or "#?RGBE").
bool IsRadianceImage(std::string_view bytes);

// Decode `bytes`; `name` names the image in messages (a path, or "image 3 'albedo'").
Result<Rgba8Image> DecodeImageRgba8(std::string_view bytes, const std::string& name);
Result<LinearRgbImage> DecodeImageLinearRgb(std::string_view bytes, const std::string& name);

// The same for a file, read through base::ReadRegularFile (regular files of at most
// kMaxImageFileBytes: a FIFO or device is an error, never a wait).
Result<Rgba8Image> ReadImageRgba8(const std::string& path);
Result<LinearRgbImage> ReadImageLinearRgb(const std::string& path);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_IMAGE_H_
