// WritePng (stb_image_write) and WriteExr (a minimal uncompressed scanline OpenEXR writer: the
// attributes the specification requires, channels A, B, G, R as 32-bit float).
#include <stb/stb_image_write.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "kiln/base/files.h"
#include "kiln/pack/records.h"
#include "kiln/runtime/color.h"

namespace kiln::runtime {
namespace {

void PutString(pack::ByteWriter& w, std::string_view s) {
    w.PutBytes({reinterpret_cast<const uint8_t*>(s.data()), s.size()});
    w.PutBytes(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(""), 1));
}

void Attribute(pack::ByteWriter& w,
               std::string_view name,
               std::string_view type,
               const std::vector<uint8_t>& value) {
    PutString(w, name);
    PutString(w, type);
    w.Put(uint32_t(value.size()));
    w.PutBytes(value);
}

}  // namespace

Status WritePng(const std::string& path,
                uint32_t width,
                uint32_t height,
                const std::vector<uint8_t>& rgba8,
                const base::WriteOptions& options) {
    if (width == 0 || height == 0 || rgba8.size() != size_t{width} * height * 4) {
        return Error{DiagCode::kRenderFailed, "image data does not match its size"};
    }
    std::vector<uint8_t> png;
    auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<uint8_t>*>(context);
        const auto* p = static_cast<const uint8_t*>(data);
        out->insert(out->end(), p, p + size);
    };
    if (!stbi_write_png_to_func(append, &png, int(width), int(height), 4, rgba8.data(),
                                int(width * 4))) {
        return Error{DiagCode::kCannotWriteFile, "cannot encode '" + path + "' as PNG"};
    }
    if (const Status written = base::WriteFileAtomically(path, png, options); !written.ok()) {
        return written.error();
    }
    return {};
}

Status WriteDisplayPng(const std::string& path,
                       const LinearImage& image,
                       const ColorPipeline& color) {
    std::vector<float> display = image.rgba;
    color.ApplyDisplay(display);
    std::vector<uint8_t> rgba8 = ColorPipeline::Quantize(display);
    for (size_t i = 3; i < rgba8.size(); i += 4) {
        rgba8[i] = 255;
    }
    return WritePng(path, image.width, image.height, rgba8);
}

Status WriteExr(const std::string& path, const LinearImage& image) {
    const uint32_t w = image.width, h = image.height;
    if (w == 0 || h == 0 || image.rgba.size() != size_t{w} * h * 4) {
        return Error{DiagCode::kRenderFailed, "image data does not match its size"};
    }
    pack::ByteWriter out;
    out.Put(uint32_t{20000630});  // magic 76 2f 31 01
    out.Put(uint32_t{2});         // version 2, single-part scanline
    pack::ByteWriter channels;
    for (const char* name : {"A", "B", "G", "R"}) {
        PutString(channels, name);
        channels.Put(uint32_t{2});  // FLOAT
        channels.Put(uint32_t{0});  // pLinear + 3 reserved bytes
        channels.Put(uint32_t{1});  // x sampling
        channels.Put(uint32_t{1});  // y sampling
    }
    channels.PutBytes(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(""), 1));
    Attribute(out, "channels", "chlist", channels.bytes());
    Attribute(out, "compression", "compression", {0});
    pack::ByteWriter box;
    box.Put(int32_t{0});
    box.Put(int32_t{0});
    box.Put(int32_t(w - 1));
    box.Put(int32_t(h - 1));
    Attribute(out, "dataWindow", "box2i", box.bytes());
    Attribute(out, "displayWindow", "box2i", box.bytes());
    Attribute(out, "lineOrder", "lineOrder", {0});
    pack::ByteWriter one;
    one.Put(1.0f);
    Attribute(out, "pixelAspectRatio", "float", one.bytes());
    pack::ByteWriter center;
    center.Put(0.0f);
    center.Put(0.0f);
    Attribute(out, "screenWindowCenter", "v2f", center.bytes());
    Attribute(out, "screenWindowWidth", "float", one.bytes());
    out.PutBytes(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(""), 1));

    const uint64_t line_bytes = uint64_t{w} * 4 * 4;
    const uint64_t table_end = out.size() + uint64_t{h} * 8;
    for (uint32_t y = 0; y < h; ++y) {
        out.Put(uint64_t{table_end + y * (8 + line_bytes)});
    }
    for (uint32_t y = 0; y < h; ++y) {
        out.Put(int32_t(y));
        out.Put(uint32_t(line_bytes));
        for (int c : {3, 2, 1, 0}) {  // A, B, G, R
            for (uint32_t x = 0; x < w; ++x) {
                out.Put(image.rgba[(size_t{y} * w + x) * 4 + size_t(c)]);
            }
        }
    }
    if (const Status written = base::WriteFileAtomically(path, out.bytes()); !written.ok()) {
        return written.error();
    }
    return {};
}

}  // namespace kiln::runtime
