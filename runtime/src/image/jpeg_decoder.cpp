#include "image/jpeg_decoder.h"

// jpeglib.h needs FILE and size_t declared first.
#include <cstdio>
// clang-format off
#include <jpeglib.h>
#include <jerror.h>
// clang-format on

#include <csetjmp>
#include <cstdlib>
#include <cstring>

namespace kiln::runtime::image {
namespace {

// libjpeg reports errors through error_exit, which must not return: it jumps back to
// DecodeJpegPlain. Nothing with a destructor lives in the frames it jumps over.
struct Errors {
    jpeg_error_mgr base;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
    bool truncated;
};

[[noreturn]] void OnError(j_common_ptr info) {
    Errors* e = reinterpret_cast<Errors*>(info->err);
    (*info->err->format_message)(info, e->message);
    std::longjmp(e->jump, 1);
}

void OnMessage(j_common_ptr info, int level) {
    Errors* e = reinterpret_cast<Errors*>(info->err);
    // Warnings (level -1) of damaged data are libjpeg's to recover from, as every viewer does;
    // the end of the data before the end of the image is a truncated file.
    if (level < 0 && info->err->msg_code == JWRN_JPEG_EOF)
        e->truncated = true;
}

// Adobe's CMYK and YCCK JPEGs store inverted ink: RGB = C' K' / 255 (as stb_image reads them).
void CmykToRgb(const uint8_t* cmyk, uint8_t* out, uint32_t width, int channels) {
    for (uint32_t x = 0; x < width; ++x, cmyk += 4, out += channels) {
        const unsigned k = cmyk[3];
        for (int c = 0; c < 3; ++c)
            out[c] = uint8_t((cmyk[c] * k + 127) / 255);
        if (channels == 4)
            out[3] = 255;
    }
}

// The decoder proper, in C terms (setjmp): pixels are malloc'd, and *why names the failure.
uint8_t* DecodeJpegPlain(const uint8_t* data,
                         size_t size,
                         int channels,
                         JpegSizeCheck fits,
                         uint32_t* width,
                         uint32_t* height,
                         std::string* why) {
    jpeg_decompress_struct info;
    Errors errors;
    std::memset(&info, 0, sizeof info);
    std::memset(&errors, 0, sizeof errors);
    info.err = jpeg_std_error(&errors.base);
    errors.base.error_exit = OnError;
    errors.base.emit_message = OnMessage;
    uint8_t* volatile pixels = nullptr;
    uint8_t* volatile row = nullptr;
    if (setjmp(errors.jump) != 0) {
        jpeg_destroy_decompress(&info);
        std::free(pixels);
        std::free(row);
        *why = errors.message;
        return nullptr;
    }
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, data, static_cast<unsigned long>(size));
    jpeg_read_header(&info, TRUE);
    if (std::string bad =
            fits(info.image_width, info.image_height, info.progressive_mode != 0, size);
        !bad.empty()) {
        jpeg_destroy_decompress(&info);
        *why = bad;
        return nullptr;
    }
    const bool cmyk = info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK;
    info.out_color_space = cmyk ? JCS_CMYK : (channels == 4 ? JCS_EXT_RGBA : JCS_RGB);
    jpeg_start_decompress(&info);
    const size_t stride = size_t(info.output_width) * size_t(channels);
    pixels = static_cast<uint8_t*>(std::calloc(stride, info.output_height));
    row = cmyk ? static_cast<uint8_t*>(std::calloc(info.output_width, 4)) : nullptr;
    if (pixels == nullptr || (cmyk && row == nullptr))
        ERREXIT1(&info, JERR_OUT_OF_MEMORY, 0);
    while (info.output_scanline < info.output_height) {
        uint8_t* target = pixels + stride * info.output_scanline;
        JSAMPROW rows[1] = {cmyk ? row : target};
        if (jpeg_read_scanlines(&info, rows, 1) != 1)
            break;
        if (cmyk)
            CmykToRgb(row, target, info.output_width, channels);
    }
    jpeg_finish_decompress(&info);
    *width = info.output_width;
    *height = info.output_height;
    jpeg_destroy_decompress(&info);
    std::free(row);
    if (errors.truncated) {
        std::free(pixels);
        *why = "the file is truncated: it ends before the image data does";
        return nullptr;
    }
    return pixels;
}

}  // namespace

bool DecodeJpeg(std::string_view bytes,
                int channels,
                JpegSizeCheck fits,
                JpegImage& out,
                std::string& error) {
    uint32_t width = 0, height = 0;
    uint8_t* pixels = DecodeJpegPlain(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(),
                                      channels, fits, &width, &height, &error);
    if (pixels == nullptr)
        return false;
    out.width = width;
    out.height = height;
    out.pixels.assign(pixels, pixels + size_t(width) * height * size_t(channels));
    std::free(pixels);
    return true;
}

}  // namespace kiln::runtime::image
