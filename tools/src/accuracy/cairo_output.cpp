#include "accuracy/cairo_output.h"

#include <cairo-svg.h>

#include <cstring>

namespace kiln::tools {
namespace {

cairo_status_t AppendTo(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

std::string XmlEscape(const std::string& s) {
    std::string out;
    for (char ch : s) {
        out += ch == '&' ? "&amp;" : ch == '<' ? "&lt;" : ch == '>' ? "&gt;" : std::string(1, ch);
    }
    return out;
}

}  // namespace

std::string CairoSvg(const CairoDrawing& draw,
                     double width,
                     double height,
                     const std::string& title,
                     const std::string& desc) {
    std::string svg;
    cairo_surface_t* surface = cairo_svg_surface_create_for_stream(AppendTo, &svg, width, height);
    cairo_t* cr = cairo_create(surface);
    draw(cr, width, height);
    cairo_destroy(cr);
    cairo_surface_finish(surface);
    cairo_surface_destroy(surface);
    if (const size_t open = svg.find("<svg"); open != std::string::npos) {
        if (const size_t end = svg.find('>', open); end != std::string::npos) {
            svg.insert(end + 1, "\n<title>" + XmlEscape(title) + "</title>\n<desc>" +
                                    XmlEscape(desc) + "</desc>");
        }
    }
    return svg;
}

std::vector<uint8_t> CairoImage(const CairoDrawing& draw, uint32_t width, uint32_t height) {
    cairo_surface_t* surface =
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, int(width), int(height));
    cairo_t* cr = cairo_create(surface);
    draw(cr, width, height);
    cairo_destroy(cr);
    cairo_surface_flush(surface);
    // Cairo's RGB24 is a native-endian 32-bit word per pixel, 0x00RRGGBB, rows `stride` apart.
    std::vector<uint8_t> rgba(size_t(width) * height * 4, 255);
    const unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    for (uint32_t y = 0; y < height && data; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            uint32_t word;
            std::memcpy(&word, data + size_t(y) * size_t(stride) + x * 4, 4);
            uint8_t* p = &rgba[(size_t(y) * width + x) * 4];
            p[0] = uint8_t(word >> 16), p[1] = uint8_t(word >> 8), p[2] = uint8_t(word);
        }
    }
    cairo_surface_destroy(surface);
    return rgba;
}

}  // namespace kiln::tools
