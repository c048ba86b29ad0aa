#include "image/stb_decoder.h"

#include <string.h>

// stb_image 2.27 copies 0 bytes from or to a null pointer (an empty first IDAT chunk of a PNG,
// found by kiln_fuzz_image): undefined behaviour in C though harmless in practice. Its copies and
// fills go through these, which skip empty ones. (string.h is included first, so only stb's calls
// are renamed.)
namespace {
void* CopyBytes(void* to, const void* from, size_t n) {
    return n == 0 ? to : memcpy(to, from, n);
}
void* FillBytes(void* to, int value, size_t n) {
    return n == 0 ? to : memset(to, value, n);
}
}  // namespace
#define memcpy(to, from, n) CopyBytes(to, from, n)
#define memset(to, value, n) FillBytes(to, value, n)

// Every allocation zeroed: stb_image 2.27's JPEG decoder (no longer built here) read state it never
// set, and one file decoded two ways (found by kiln_fuzz_image); whatever else reads before it
// writes now reads zeros, the same each time, and no stale heap bytes can reach an image.
#include <stdlib.h>
#define STBI_MALLOC(size) calloc(1, size)
#define STBI_REALLOC(p, size) realloc(p, size)
#define STBI_FREE(p) free(p)

// The implementation, private to this file (STB_IMAGE_STATIC), for the formats Kiln reads.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#define STBI_ONLY_PSD
#define STBI_ONLY_GIF
#define STBI_NO_STDIO
#define STBI_NO_HDR
#define STBI_NO_LINEAR
#define STBI_MAX_DIMENSIONS 16384
#include <stb/stb_image.h>

namespace kiln::runtime::image {

bool StbInfo(const uint8_t* data, int size, int& width, int& height, int& channels) {
    return stbi_info_from_memory(data, size, &width, &height, &channels) != 0;
}

uint8_t* StbLoad(const ByteSource& source, int& width, int& height, int channels) {
    const stbi_io_callbacks io{source.read, source.skip, source.at_end};
    int in_file = 0;
    return stbi_load_from_callbacks(&io, source.user, &width, &height, &in_file, channels);
}

void StbFree(uint8_t* pixels) {
    stbi_image_free(pixels);
}

const char* StbFailure() {
    const char* why = stbi_failure_reason();
    return why != nullptr ? why : "no reason given";
}

}  // namespace kiln::runtime::image
