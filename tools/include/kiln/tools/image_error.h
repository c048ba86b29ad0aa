// How far a rendered image is from a reference: error in linear (scene-referred) light, FLIP on
// the display-referred images (kiln/tools/flip.h), and a heat map of a per-pixel error. Used by
// `kiln report` (docs/accuracy.md); pure CPU, no device.
#ifndef KILN_TOOLS_IMAGE_ERROR_H_
#define KILN_TOOLS_IMAGE_ERROR_H_

#include <cstdint>
#include <vector>

#include "kiln/result.h"
#include "kiln/runtime/color.h"

namespace kiln::tools {

using runtime::LinearImage;
// Over the RGB channels of every pixel (alpha, the coverage, is not compared).
struct ImageError {
    double rmse = 0;     // root of the mean squared difference
    double max_abs = 0;  // the largest absolute difference of a channel
    // 10 log10(peak^2 / MSE) with peak the reference's largest channel value (1 when it is
    // darker): the scene-referred images have no fixed white. Infinite for identical images.
    double psnr = 0;
};

// Both images must have the same size.
Result<ImageError> CompareLinear(const LinearImage& reference, const LinearImage& test);

// The image averaged over factor x factor blocks (a box filter): a supersampled render at the
// size of the others. The size must be a multiple of the factor.
Result<LinearImage> Downsample(const LinearImage& image, uint32_t factor);

// A per-pixel error in [0, 1] as 8-bit RGBA through the magma colour map (black 0, pale yellow
// 1), as FLIP's own tool shows it.
std::vector<uint8_t> HeatMap(const std::vector<float>& error);

}  // namespace kiln::tools

#endif  // KILN_TOOLS_IMAGE_ERROR_H_
