// Rasterise an SVG document to a PNG file (Qt's SVG renderer; works headless).
#pragma once

#include <string>

namespace autoblock {

// Inputs:  svg, an SVG document; path, the PNG to write; width, in pixels (height follows the
//          document's aspect ratio).
// Writes the file atomically. Throws InputError when the folder is missing or the file cannot be
// written, std::runtime_error when the SVG cannot be rendered.
void write_png_from_svg(const std::string& svg, const std::string& path, int width);

}  // namespace autoblock
