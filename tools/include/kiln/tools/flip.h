// FLIP, the perceptual difference of two images as seen when alternating between them, written
// from the paper: P. Andersson, J. Nilsson, T. Akenine-Moller, M. Oskarsson, K. Astrom and M. D.
// Fairchild, "FLIP: A Difference Evaluator for Alternating Images", Proc. ACM Comput. Graph.
// Interact. Tech. 3(2), 2020 (LDR-FLIP, section 4). A colour pipeline (contrast sensitivity
// filters in YCxCz, Hunt-adjusted CIELAB, the HyAB distance, compressed and redistributed) and a
// feature pipeline (edges and points of the achromatic channel) give a per-pixel error in [0, 1];
// the report uses its mean. 0 for identical images.
#ifndef KILN_TOOLS_FLIP_H_
#define KILN_TOOLS_FLIP_H_

#include <cstdint>
#include <vector>

#include "kiln/result.h"

namespace kiln::tools {

struct FlipOptions {
    // The observer: a 0.7 m wide 3840-pixel monitor seen from 0.7 m (the paper's default).
    double pixels_per_degree = 67.0223;
};

struct FlipMap {
    uint32_t width = 0, height = 0;
    std::vector<float> error;  // per pixel, row-major, in [0, 1]
    double mean = 0;
};

// `reference` and `test` are display-referred, sRGB-encoded RGBA in [0, 1] (what
// ColorPipeline::ApplyDisplay gives; alpha is ignored), both width x height.
Result<FlipMap> Flip(uint32_t width,
                     uint32_t height,
                     const std::vector<float>& reference,
                     const std::vector<float>& test,
                     const FlipOptions& options = {});

}  // namespace kiln::tools

#endif  // KILN_TOOLS_FLIP_H_
