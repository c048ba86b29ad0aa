#include "image/radiance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "image/stb_guards.h"

namespace kiln::runtime::image {
namespace {

constexpr size_t kMaxHeaderLine = 1024;
constexpr size_t kMaxHeaderLines = 4096;

struct State {
    std::string_view bytes;
    const std::string& name;
    size_t at = 0;

    Error Fail(const std::string& what) const {
        return Error{DiagCode::kBadImage, "'" + name + "': " + what};
    }
    Error Truncated(uint32_t row, uint32_t height) const {
        return Fail("the file is truncated: its pixel data ends in row " + std::to_string(row + 1) +
                    " of " + std::to_string(height));
    }
    size_t Left() const { return bytes.size() - at; }
    // The next header line without its newline; false at the end of the bytes or past the limit.
    bool Line(std::string_view& line) {
        const size_t end = bytes.find('\n', at);
        if (end == std::string_view::npos || end - at > kMaxHeaderLine)
            return false;
        line = bytes.substr(at, end - at);
        at = end + 1;
        return true;
    }
};

// The Radiance pixel: a shared exponent over three 8-bit mantissas (Ward, "Real Pixels",
// Graphics Gems II): value = mantissa * 2^(e - 136); e == 0 is black.
void StoreRgbe(const uint8_t* rgbe, float* out) {
    if (rgbe[3] == 0) {
        out[0] = out[1] = out[2] = 0.0f;
        return;
    }
    const float f = std::ldexp(1.0f, int(rgbe[3]) - (128 + 8));
    out[0] = float(rgbe[0]) * f;
    out[1] = float(rgbe[1]) * f;
    out[2] = float(rgbe[2]) * f;
}

// One number of the resolution line ("-Y 512 +X 1024"); advances past it.
bool ParseSide(std::string_view& s, std::string_view label, uint32_t& out) {
    if (s.substr(0, label.size()) != label)
        return false;
    s.remove_prefix(label.size());
    uint64_t v = 0;
    size_t digits = 0;
    while (digits < s.size() && s[digits] >= '0' && s[digits] <= '9')
        v = std::min<uint64_t>(v * 10 + uint64_t(s[digits++] - '0'), 4000000000u);
    if (digits == 0)
        return false;
    s.remove_prefix(digits);
    out = uint32_t(v);  // checked against the limits by the caller
    return true;
}

Status ReadHeader(State& s, uint32_t& width, uint32_t& height) {
    std::string_view line;
    if (!s.Line(line) || (line != "#?RADIANCE" && line != "#?RGBE"))
        return s.Fail("not a Radiance file (its first line is not #?RADIANCE or #?RGBE)");
    bool rgbe = false;
    for (size_t n = 0;; ++n) {
        if (n == kMaxHeaderLines || !s.Line(line))
            return s.Fail("the header does not end (no blank line before the resolution)");
        if (line.empty())
            break;
        if (line.substr(0, 7) == "FORMAT=") {
            if (line != "FORMAT=32-bit_rle_rgbe") {
                return s.Fail("the pixel format is '" + std::string(line.substr(7)) +
                              "'; Kiln reads 32-bit_rle_rgbe");
            }
            rgbe = true;
        }
    }
    if (!rgbe)
        return s.Fail("the header has no FORMAT=32-bit_rle_rgbe line");
    if (!s.Line(line))
        return s.Fail("the resolution line is missing");
    std::string_view rest = line;
    if (!ParseSide(rest, "-Y ", height) || !ParseSide(rest, " +X ", width) || !rest.empty()) {
        return s.Fail("the resolution line is '" + std::string(line.substr(0, 40)) +
                      "'; Kiln reads the standard orientation, '-Y <height> +X <width>'");
    }
    if (std::string big = SizeProblem(width, height); !big.empty())
        return s.Fail(big);
    return {};
}

// Pixels [first, width*height) stored flat, four bytes each.
Status DecodeFlat(State& s, uint64_t first, LinearRgbImage& out) {
    const uint64_t texels = uint64_t(out.width) * out.height;
    for (uint64_t i = first; i < texels; ++i) {
        if (s.Left() < 4)
            return s.Truncated(uint32_t(i / out.width), out.height);
        StoreRgbe(reinterpret_cast<const uint8_t*>(s.bytes.data() + s.at), &out.rgb[i * 3]);
        s.at += 4;
    }
    return {};
}

// One component of a run-length encoded scanline: runs (count > 128: count - 128 copies of the
// next byte) and literals (count <= 128 bytes), each within the scanline.
Status DecodeComponent(State& s,
                       uint32_t row,
                       uint32_t height,
                       uint32_t k,
                       std::vector<uint8_t>& line) {
    const uint32_t width = uint32_t(line.size() / 4);
    for (uint32_t i = 0; i < width;) {
        if (s.Left() < 1)
            return s.Truncated(row, height);
        uint32_t count = uint8_t(s.bytes[s.at++]);
        const bool run = count > 128;
        count = run ? count - 128 : count;
        if (count == 0 || count > width - i) {
            return s.Fail("bad run-length data in row " + std::to_string(row + 1) +
                          ": a count of " + std::to_string(count) + " with " +
                          std::to_string(width - i) + " texels left");
        }
        if (s.Left() < (run ? 1 : count))
            return s.Truncated(row, height);
        for (uint32_t z = 0; z < count; ++z, ++i)
            line[size_t(i) * 4 + k] = uint8_t(s.bytes[run ? s.at : s.at + z]);
        s.at += run ? 1 : count;
    }
    return {};
}

Status DecodeRunLength(State& s, LinearRgbImage& out) {
    std::vector<uint8_t> line(size_t(out.width) * 4);
    for (uint32_t row = 0; row < out.height; ++row) {
        if (s.Left() < 4)
            return s.Truncated(row, out.height);
        const auto* p = reinterpret_cast<const uint8_t*>(s.bytes.data() + s.at);
        if (p[0] != 2 || p[1] != 2 || (p[2] & 0x80) != 0) {
            if (row == 0)  // not run-length encoded: the whole image is flat (as stb_image reads)
                return DecodeFlat(s, 0, out);
            return s.Fail("row " + std::to_string(row + 1) +
                          " does not start like a run-length encoded scanline");
        }
        const uint32_t length = uint32_t(p[2]) << 8 | p[3];
        if (length != out.width) {
            return s.Fail("row " + std::to_string(row + 1) + " says it is " +
                          std::to_string(length) + " texels long; the image is " +
                          std::to_string(out.width) + " wide");
        }
        s.at += 4;
        for (uint32_t k = 0; k < 4; ++k) {
            if (Status e = DecodeComponent(s, row, out.height, k, line); !e.ok())
                return e;
        }
        for (uint32_t i = 0; i < out.width; ++i)
            StoreRgbe(&line[size_t(i) * 4], &out.rgb[(size_t(row) * out.width + i) * 3]);
    }
    return {};
}

}  // namespace

Result<LinearRgbImage> DecodeRadiance(std::string_view bytes, const std::string& name) {
    State s{bytes, name};
    LinearRgbImage out;
    if (Status e = ReadHeader(s, out.width, out.height); !e.ok())
        return e.error();
    // Every row takes at least 4 + 2 bytes per component per 127 texels (run-length) or 4 bytes a
    // texel (flat): a file too short for that is truncated, found before the pixels are allocated.
    const bool run_length = out.width >= 8 && out.width < 32768;
    const uint64_t min_row =
        run_length ? 4 + 8 * ((uint64_t(out.width) + 126) / 127) : 4 * uint64_t(out.width);
    if (uint64_t(s.Left()) < min_row * out.height)
        return s.Truncated(uint32_t(s.Left() / min_row), out.height);
    out.rgb.resize(size_t(out.width) * out.height * 3);
    Status e = run_length ? DecodeRunLength(s, out) : DecodeFlat(s, 0, out);
    if (!e.ok())
        return e.error();
    return out;
}

}  // namespace kiln::runtime::image
