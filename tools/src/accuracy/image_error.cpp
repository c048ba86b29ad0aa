#include "kiln/tools/image_error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace kiln::tools {

using runtime::LinearImage;
namespace {

std::string SizeOf(const LinearImage& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

}  // namespace

Result<ImageError> CompareLinear(const LinearImage& reference, const LinearImage& test) {
    const size_t pixels = size_t(reference.width) * reference.height;
    if (reference.width != test.width || reference.height != test.height ||
        reference.rgba.size() != pixels * 4 || test.rgba.size() != pixels * 4 || pixels == 0) {
        return Error{DiagCode::kBadCommandLine, "cannot compare a " + SizeOf(test) +
                                                    " image with a " + SizeOf(reference) +
                                                    " reference (the sizes must match)"};
    }
    double sum = 0, max_abs = 0, peak = 1.0;
    for (size_t i = 0; i < pixels; ++i) {
        for (size_t k = 0; k < 3; ++k) {
            const double r = reference.rgba[i * 4 + k], t = test.rgba[i * 4 + k];
            const double d = std::abs(r - t);
            sum += d * d;
            max_abs = std::max(max_abs, d);
            peak = std::max(peak, r);
        }
    }
    ImageError e;
    const double mse = sum / double(pixels * 3);
    e.rmse = std::sqrt(mse);
    e.max_abs = max_abs;
    e.psnr =
        mse > 0 ? 10.0 * std::log10(peak * peak / mse) : std::numeric_limits<double>::infinity();
    return e;
}

Result<LinearImage> Downsample(const LinearImage& image, uint32_t factor) {
    if (factor == 0 || image.width % factor != 0 || image.height % factor != 0 ||
        image.rgba.size() != size_t(image.width) * image.height * 4) {
        return Error{DiagCode::kBadCommandLine, "cannot reduce a " + SizeOf(image) + " image by " +
                                                    std::to_string(factor) + " (not a multiple)"};
    }
    LinearImage out;
    out.width = image.width / factor;
    out.height = image.height / factor;
    out.rgba.assign(size_t(out.width) * out.height * 4, 0.0f);
    const double scale = 1.0 / double(factor * factor);
    for (uint32_t y = 0; y < out.height; ++y) {
        for (uint32_t x = 0; x < out.width; ++x) {
            std::array<double, 4> sum{};
            for (uint32_t j = 0; j < factor; ++j) {
                const float* row =
                    &image.rgba[(size_t(y * factor + j) * image.width + size_t(x) * factor) * 4];
                for (uint32_t i = 0; i < factor * 4; ++i) {
                    sum[i % 4] += row[i];
                }
            }
            for (size_t k = 0; k < 4; ++k) {
                out.rgba[(size_t(y) * out.width + x) * 4 + k] = float(sum[k] * scale);
            }
        }
    }
    return out;
}

std::vector<uint8_t> HeatMap(const std::vector<float>& error) {
    // matplotlib's magma at t = 0, 1/8, ..., 7/8, 15/16, 1 (display-referred sRGB).
    static constexpr float kStops[][4] = {
        {0.0f, 0.001462f, 0.000466f, 0.013866f},    {0.125f, 0.078815f, 0.054184f, 0.211667f},
        {0.25f, 0.232077f, 0.059889f, 0.437695f},   {0.375f, 0.390384f, 0.100379f, 0.501864f},
        {0.5f, 0.550287f, 0.161158f, 0.505719f},    {0.625f, 0.716387f, 0.214982f, 0.475290f},
        {0.75f, 0.868793f, 0.287728f, 0.409303f},   {0.875f, 0.967671f, 0.439703f, 0.359810f},
        {0.9375f, 0.994738f, 0.624350f, 0.427397f}, {1.0f, 0.987053f, 0.991438f, 0.749504f}};
    constexpr size_t kCount = sizeof kStops / sizeof kStops[0];
    std::vector<uint8_t> out(error.size() * 4);
    for (size_t i = 0; i < error.size(); ++i) {
        const float t = std::isfinite(error[i]) ? std::clamp(error[i], 0.0f, 1.0f) : 1.0f;
        size_t k = 1;
        while (k + 1 < kCount && kStops[k][0] < t) {
            ++k;
        }
        const float* a = kStops[k - 1];
        const float* b = kStops[k];
        const float f = (t - a[0]) / (b[0] - a[0]);
        for (size_t c = 0; c < 3; ++c) {
            const float v = a[c + 1] + (b[c + 1] - a[c + 1]) * f;
            out[i * 4 + c] = uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
        }
        out[i * 4 + 3] = 255;
    }
    return out;
}

}  // namespace kiln::tools
