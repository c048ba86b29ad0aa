// JPEG through libjpeg-turbo (Debian's libjpeg62-turbo, fuzzed upstream on OSS-Fuzz), in place of
// stb_image 2.27's JPEG decoder, whose bit reader shifts by more than 31 and reads state it never
// set on damaged files (found by kiln_fuzz_image). A file that ends early ("Premature end of JPEG
// file", which libjpeg only warns of and fills with grey) is truncated: an error here.
#ifndef KILN_RUNTIME_IMAGE_JPEG_DECODER_H_
#define KILN_RUNTIME_IMAGE_JPEG_DECODER_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace kiln::runtime::image {

struct JpegImage {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> pixels;  // `channels` (3 or 4, alpha opaque) per texel, rows from the top
};

// Decodes `bytes` to 3 or 4 channels; false with `error` set (no name in it) on failure. Sizes are
// checked by `fits(width, height, progressive)` before anything is allocated: "" to go on, else
// the error to give.
using JpegSizeCheck = std::string (*)(uint32_t width,
                                      uint32_t height,
                                      bool progressive,
                                      size_t bytes);
bool DecodeJpeg(std::string_view bytes,
                int channels,
                JpegSizeCheck fits,
                JpegImage& out,
                std::string& error);

}  // namespace kiln::runtime::image

#endif  // KILN_RUNTIME_IMAGE_JPEG_DECODER_H_
