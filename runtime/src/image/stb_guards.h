// Inputs that reach known defects of the stb_image Kiln builds with (Debian 12's libstb-dev,
// stb_image 2.27, fixed upstream in 2.28 and later), refused before stb_image sees them. Each
// was found by kiln_fuzz_image (tests/fuzz/image_fuzz.cpp) under AddressSanitizer and
// UndefinedBehaviorSanitizer; each check walks the file once.
#ifndef KILN_RUNTIME_IMAGE_STB_GUARDS_H_
#define KILN_RUNTIME_IMAGE_STB_GUARDS_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace kiln::runtime::image {

// What stb_image 2.27 would mishandle in `bytes` (before any stb_image call, stbi_info too); ""
// when nothing known. JPEG: a Huffman table (DHT) of more than 256 codes, which
// stbi__build_huffman writes past its 257-entry array (2.28 checks "bad DHT header"); tables are
// walked as stb_image reads them, past the end of their segment while its length left is above 0.
// PNG: a chunk longer than the bytes left, which stb_image allocates before it reads (an IDAT
// declaring 2 GiB in a 100-byte file): a truncated file.
std::string StbHazard(std::string_view bytes);

// A file too short for the `texels` its header declares, which stb_image would allocate in full
// (a 100-byte file asked for 1 GiB) and fill from zeros before the truncation shows; any format
// but progressive JPEG. "" when the bytes can hold them.
std::string TooShortFor(std::string_view bytes, uint64_t texels);

// Where a JPEG's data starts after its SOI marker, found as stb_image finds it (0xFF, fill bytes,
// 0xD8); 0 when `bytes` is no JPEG.
size_t JpegStart(std::string_view bytes);

}  // namespace kiln::runtime::image

#endif  // KILN_RUNTIME_IMAGE_STB_GUARDS_H_
