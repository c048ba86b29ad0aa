// stb_image compiled into Kiln (from Debian's libstb-dev header, not its prebuilt library) for
// exactly the formats Kiln hands it: PNG, BMP, TGA, PSD and GIF, no file I/O, no HDR (Kiln's own,
// image/radiance.h), no JPEG (libjpeg-turbo, image/jpeg_decoder.h), at most 16384 texels a side.
// Compiled with the rest of Kiln, it is under the sanitizers and libFuzzer's coverage in those
// builds (tests/fuzz/image_fuzz.cpp).
#ifndef KILN_RUNTIME_IMAGE_STB_DECODER_H_
#define KILN_RUNTIME_IMAGE_STB_DECODER_H_

#include <cstdint>

namespace kiln::runtime::image {

// Where stb_image reads from: stbi_io_callbacks by another name, so that no other file includes
// stb_image.h.
struct ByteSource {
    int (*read)(void* user, char* out, int size);
    void (*skip)(void* user, int n);
    int (*at_end)(void* user);
    void* user;
};

// stbi_info_from_memory: the size and channels from the header; false when no reader knows it.
bool StbInfo(const uint8_t* data, int size, int& width, int& height, int& channels);
// stbi_load_from_callbacks with `channels` channels; nullptr on failure. Free with StbFree.
uint8_t* StbLoad(const ByteSource& source, int& width, int& height, int channels);
void StbFree(uint8_t* pixels);
// Why the last call on this thread failed ("no reason given" when stb_image did not say).
const char* StbFailure();

}  // namespace kiln::runtime::image

#endif  // KILN_RUNTIME_IMAGE_STB_DECODER_H_
