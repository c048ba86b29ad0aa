// Colour management with OpenColorIO 2.1. Shading is linear (Rec.709 primaries); colours authored
// in sRGB (Color properties, as Unity's linear projects do) are decoded through OCIO, and the
// final image goes through an OCIO display/view transform: the user's config ($OCIO or an
// explicit path) or Kiln's built-in one (OCIO 2.1 ships none), created in code:
//   colour spaces  "Linear Rec.709 (sRGB)" (scene_linear, reference)
//                  "sRGB - Texture" (IEC 61966-2-1 curve: ExponentWithLinear, gamma 2.4,
//                                    offset 0.055)
//   display/view   "sRGB" / "Standard" -> "sRGB - Texture"
#ifndef KILN_RUNTIME_COLOR_H_
#define KILN_RUNTIME_COLOR_H_

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kiln/base/files.h"
#include "kiln/result.h"

namespace kiln::runtime {

struct ColorOptions {
    std::string config_path;  // empty: $OCIO when set, else the built-in config
    std::string display;      // empty: the config's default display
    std::string view;         // empty: the display's default view
    float exposure = 0;       // stops, applied in scene-linear before the view
};

class ColorPipeline {
  public:
    ColorPipeline();
    ~ColorPipeline();
    ColorPipeline(ColorPipeline&&) noexcept;
    ColorPipeline& operator=(ColorPipeline&&) noexcept;

    static Result<ColorPipeline> Create(const ColorOptions& options);

    // sRGB-encoded to linear through the built-in config. Without `hdr` the input is clamped to
    // [0, 1] first (an LDR colour picker's range); with it, values above 1 follow the curve.
    void SrgbToLinear(float rgb[3], bool hdr) const;

    // Scene-linear RGBA (alpha passed through) to display-referred values in [0, 1].
    void ApplyDisplay(std::vector<float>& rgba) const;

    // Display-referred [0, 1] to 8-bit with rounding.
    static std::vector<uint8_t> Quantize(const std::vector<float>& rgba);

    // "built-in config, display 'sRGB', view 'Standard'" or the file's name.
    const std::string& description() const { return description_; }

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::string description_;
};

struct LinearImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;  // row-major from the top, 4 floats per pixel
};

// 8-bit RGBA PNG, written to a temporary file and renamed (base::WriteFileAtomically, `options`).
Status WritePng(const std::string& path,
                uint32_t width,
                uint32_t height,
                const std::vector<uint8_t>& rgba8,
                const base::WriteOptions& options = {});
// A rendered linear image through `color`'s display transform, quantized to 8 bits and written
// as an opaque PNG (coverage is not transparency).
Status WriteDisplayPng(const std::string& path,
                       const LinearImage& image,
                       const ColorPipeline& color);
// Uncompressed 32-bit float RGBA OpenEXR (scanline), written to a temporary file and renamed.
Status WriteExr(const std::string& path, const LinearImage& image);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_COLOR_H_
