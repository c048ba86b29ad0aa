// Kiln's Radiance (.hdr, RGBE) decoder: the header, flat and run-length encoded scanlines, every
// read bounded by the bytes there are and every loop bounded by the scanline it fills.
#ifndef KILN_RUNTIME_IMAGE_RADIANCE_H_
#define KILN_RUNTIME_IMAGE_RADIANCE_H_

#include <string>
#include <string_view>

#include "kiln/runtime/image.h"

namespace kiln::runtime::image {

// Linear radiance as stored (FORMAT=32-bit_rle_rgbe, "-Y H +X W" orientation). Errors (K0032)
// name the image and say what is wrong: a truncated file says in which row its data ends.
Result<LinearRgbImage> DecodeRadiance(std::string_view bytes, const std::string& name);

}  // namespace kiln::runtime::image

#endif  // KILN_RUNTIME_IMAGE_RADIANCE_H_
