#include "image/stb_decoder.h"

// The implementation, private to this file (STB_IMAGE_STATIC), for the formats Kiln reads.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
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
