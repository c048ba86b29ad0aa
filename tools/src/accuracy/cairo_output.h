// One cairo drawing written as SVG and as an RGBA8 image (the report's figures: accuracy/plot.cpp,
// accuracy/scaling_output.cpp).
#ifndef KILN_TOOLS_ACCURACY_CAIRO_OUTPUT_H_
#define KILN_TOOLS_ACCURACY_CAIRO_OUTPUT_H_

#include <cairo.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace kiln::tools {

using CairoDrawing = std::function<void(cairo_t* cr, double width, double height)>;

// The drawing as SVG; cairo draws text as glyph outlines, so `title` and `desc` go into the
// SVG's <title> and <desc>, for screen readers, search and a reader of the file.
std::string CairoSvg(const CairoDrawing& draw,
                     double width,
                     double height,
                     const std::string& title,
                     const std::string& desc);

// The drawing as opaque RGBA8, rows top first.
std::vector<uint8_t> CairoImage(const CairoDrawing& draw, uint32_t width, uint32_t height);

}  // namespace kiln::tools

#endif  // KILN_TOOLS_ACCURACY_CAIRO_OUTPUT_H_
