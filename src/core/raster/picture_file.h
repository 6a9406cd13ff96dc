// Writing a picture (an SVG document) to a file as SVG or PNG, chosen by the file's extension.
#pragma once

#include <string>

namespace autoblock {

// Inputs: path; option, the command-line option naming it (for messages). Throws InputError unless
// path ends in .svg or .png (any case).
void check_picture_path(const std::string& path, const std::string& option);

// Inputs: path (.svg or .png), svg, the picture. Writes it atomically, as is or rasterised
// (1200 pixels wide, by Qt in libautoblock_raster.so, loaded on first use: common/plugin.h). Throws InputError for another extension or when the file cannot be written.
void write_picture(const std::string& path, const std::string& svg);

}  // namespace autoblock
