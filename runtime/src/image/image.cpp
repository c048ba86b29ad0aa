#include "kiln/runtime/image.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

#include "image/jpeg_decoder.h"
#include "image/radiance.h"
#include "image/stb_decoder.h"
#include "image/stb_guards.h"
#include "kiln/base/files.h"

namespace kiln::runtime {
namespace {

Error Fail(const std::string& name, const std::string& what) {
    return Error{DiagCode::kBadImage, "'" + name + "': " + what};
}

// stb_image reads through these callbacks; a read or skip past the end of the bytes means the
// decoder wanted data the file does not have: the file is truncated (stb_image itself would go on
// with zeros).
struct Cursor {
    std::string_view bytes;
    size_t at = 0;
    bool past_end = false;
};

int ReadBytes(void* user, char* out, int size) {
    auto* c = static_cast<Cursor*>(user);
    const size_t n = std::min(size_t(std::max(size, 0)), c->bytes.size() - c->at);
    if (n == 0) {
        c->past_end = true;
        return 0;
    }
    std::memcpy(out, c->bytes.data() + c->at, n);
    c->at += n;
    return int(n);
}

void SkipBytes(void* user, int n) {
    auto* c = static_cast<Cursor*>(user);
    if (n <= 0)
        return;
    if (size_t(n) > c->bytes.size() - c->at) {
        c->past_end = true;
        c->at = c->bytes.size();
        return;
    }
    c->at += size_t(n);
}

int AtEnd(void* user) {
    const auto* c = static_cast<const Cursor*>(user);
    return c->at >= c->bytes.size() ? 1 : 0;
}

// The formats stb_image reads that Kiln does not hand it: Softimage PIC and PNM (Unity imports
// neither). Radiance files are Kiln's own (image/radiance.cpp).
std::string RefusedFormat(std::string_view b) {
    if (b.size() >= 4 && b.substr(0, 4) == std::string_view("\x53\x80\xF6\x34", 4))
        return "a Softimage PIC image";
    if (b.size() >= 2 && b[0] == 'P' && (b[1] == '5' || b[1] == '6'))
        return "a PNM image";
    return "";
}

struct FreePixels {
    void operator()(uint8_t* p) const { image::StbFree(p); }
};

std::string JpegFits(uint32_t width, uint32_t height, bool progressive, size_t bytes) {
    if (std::string big = image::SizeProblem(width, height); !big.empty())
        return big;
    return image::TooShortFor(bytes, uint64_t(width) * height, true, progressive);
}

// 8-bit pixels with `channels` channels: JPEG through libjpeg-turbo, the other formats through
// stb_image; truncation and size checked.
Result<std::vector<uint8_t>> DecodeEightBit(std::string_view bytes,
                                            const std::string& name,
                                            int channels,
                                            uint32_t& width,
                                            uint32_t& height) {
    if (std::string refused = RefusedFormat(bytes); !refused.empty()) {
        return Fail(name, "the file is " + refused +
                              "; Kiln reads PNG, JPEG, TGA, BMP, PSD, GIF and Radiance HDR");
    }
    if (bytes.size() > size_t(std::numeric_limits<int>::max()))
        return Fail(name, "the file is too large");
    if (image::JpegStart(bytes) != 0) {
        image::JpegImage jpeg;
        std::string why;
        if (!image::DecodeJpeg(bytes, channels, &JpegFits, jpeg, why))
            return Fail(name, why);
        width = jpeg.width;
        height = jpeg.height;
        return std::move(jpeg.pixels);
    }
    if (std::string hazard = image::StbHazard(bytes); !hazard.empty())
        return Fail(name, hazard);
    int w = 0, h = 0, n = 0;
    if (!image::StbInfo(reinterpret_cast<const uint8_t*>(bytes.data()), int(bytes.size()), w, h,
                        n)) {
        return Fail(name, "not an image Kiln can read (" + std::string(image::StbFailure()) +
                              "); Kiln reads PNG, JPEG, TGA, BMP, PSD, GIF and Radiance HDR");
    }
    const uint64_t w64 = uint64_t(std::max(w, 0)), h64 = uint64_t(std::max(h, 0));
    if (std::string big = image::SizeProblem(w64, h64); !big.empty())
        return Fail(name, big);
    if (std::string short_file = image::TooShortFor(bytes.size(), w64 * h64, false, false);
        !short_file.empty())
        return Fail(name, short_file);
    Cursor cursor{bytes};
    std::unique_ptr<uint8_t, FreePixels> pixels(
        image::StbLoad({&ReadBytes, &SkipBytes, &AtEnd, &cursor}, w, h, channels));
    if (cursor.past_end)  // whether or not stb_image gave up: it ran out of bytes first
        return Fail(name, "the file is truncated: it ends before the image data does");
    if (!pixels)
        return Fail(name, "cannot decode the image: " + std::string(image::StbFailure()));
    width = uint32_t(w);
    height = uint32_t(h);
    const uint8_t* p = pixels.get();
    return std::vector<uint8_t>(p, p + size_t(width) * height * size_t(channels));
}

float SrgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

bool IsRadianceImage(std::string_view bytes) {
    return bytes.substr(0, 10) == "#?RADIANCE" || bytes.substr(0, 6) == "#?RGBE";
}

Result<LinearRgbImage> DecodeImageLinearRgb(std::string_view bytes, const std::string& name) {
    if (IsRadianceImage(bytes))
        return image::DecodeRadiance(bytes, name);
    LinearRgbImage out;
    Result<std::vector<uint8_t>> rgb = DecodeEightBit(bytes, name, 3, out.width, out.height);
    if (!rgb)
        return rgb.error();
    std::array<float, 256> table{};
    for (size_t i = 0; i < table.size(); ++i)
        table[i] = SrgbToLinear(float(i) / 255.0f);
    out.rgb.resize(rgb.value().size());
    std::transform(rgb.value().begin(), rgb.value().end(), out.rgb.begin(),
                   [&](uint8_t v) { return table[v]; });
    return out;
}

Result<Rgba8Image> DecodeImageRgba8(std::string_view bytes, const std::string& name) {
    Rgba8Image out;
    if (!IsRadianceImage(bytes)) {
        Result<std::vector<uint8_t>> rgba = DecodeEightBit(bytes, name, 4, out.width, out.height);
        if (!rgba)
            return rgba.error();
        out.rgba = std::move(rgba.value());
        return out;
    }
    Result<LinearRgbImage> hdr = image::DecodeRadiance(bytes, name);
    if (!hdr)
        return hdr.error();
    // As stb_image gives an HDR file to an 8-bit reader: gamma 1/2.2, clamped, opaque.
    out.width = hdr.value().width;
    out.height = hdr.value().height;
    out.rgba.resize(size_t(out.width) * out.height * 4);
    const std::vector<float>& rgb = hdr.value().rgb;
    for (size_t i = 0, texels = size_t(out.width) * out.height; i < texels; ++i) {
        for (size_t k = 0; k < 3; ++k) {
            const float v = std::pow(std::max(rgb[i * 3 + k], 0.0f), 1.0f / 2.2f) * 255.0f + 0.5f;
            out.rgba[i * 4 + k] = uint8_t(std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 255.0f));
        }
        out.rgba[i * 4 + 3] = 255;
    }
    return out;
}

Result<Rgba8Image> ReadImageRgba8(const std::string& path) {
    Result<std::string> bytes = base::ReadRegularFile(path, kMaxImageFileBytes);
    if (!bytes)
        return Error{DiagCode::kBadImage, bytes.error().message};
    return DecodeImageRgba8(bytes.value(), path);
}

Result<LinearRgbImage> ReadImageLinearRgb(const std::string& path) {
    Result<std::string> bytes = base::ReadRegularFile(path, kMaxImageFileBytes);
    if (!bytes)
        return Error{DiagCode::kBadImage, bytes.error().message};
    return DecodeImageLinearRgb(bytes.value(), path);
}

}  // namespace kiln::runtime
