// Inputs that reach known defects of the stb_image Kiln builds with (Debian 12's libstb-dev,
// stb_image 2.27), refused before stb_image sees them, and the size checks made before any
// decoder allocates pixels. Each defect was found by kiln_fuzz_image (tests/fuzz/image_fuzz.cpp)
// under AddressSanitizer and UndefinedBehaviorSanitizer; each check walks the file once.
#ifndef KILN_RUNTIME_IMAGE_STB_GUARDS_H_
#define KILN_RUNTIME_IMAGE_STB_GUARDS_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace kiln::runtime::image {

// What stb_image 2.27 would mishandle in `bytes` (checked before any stb_image call); "" when
// nothing known. PNG: a size past Kiln's limits in IHDR, and a chunk longer than the bytes left,
// which stb_image allocates before it reads (an IDAT declaring 2 GiB in a 100-byte file): a
// truncated file.
std::string StbHazard(std::string_view bytes);

// Where a JPEG's data starts after its SOI marker (0xFF, any fill bytes 0xFF, then 0xD8); 0 when
// `bytes` is no JPEG.
size_t JpegStart(std::string_view bytes);

// "the image is WxH; Kiln reads ..." for a size outside Kiln's limits (kiln/runtime/image.h);
// "" within them.
std::string SizeProblem(uint64_t width, uint64_t height);

// A file of `bytes` bytes too short for `texels` texels, which a decoder would allocate in full (a
// 100-byte file asked for 1 GiB) and fill before the truncation shows. No format Kiln reads holds
// more than 8,256 texels a byte but progressive JPEG, which codes runs of empty blocks in a few
// bits (no bound); baseline JPEG holds at most 256 (2 bits an 8x8 block). "" when they fit.
std::string TooShortFor(size_t bytes, uint64_t texels, bool jpeg, bool progressive);

}  // namespace kiln::runtime::image

#endif  // KILN_RUNTIME_IMAGE_STB_GUARDS_H_
