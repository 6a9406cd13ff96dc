#include "core/raster/picture_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/common/error.h"
#include "core/io/text_file.h"
#include "core/common/plugin.h"

namespace autoblock {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

}  // namespace

void check_picture_path(const std::string& path, const std::string& option) {
  const std::string ext = lower_extension(path);
  if (ext != ".svg" && ext != ".png") throw InputError(option + " " + path + ": expected a .svg or .png file");
}

void write_picture(const std::string& path, const std::string& svg) {
  check_picture_path(path, "picture");
  if (lower_extension(path) == ".svg") {
    write_text_file(path, svg);
  } else {
    // Qt rasterises it, in libautoblock_raster.so, loaded now (a command that writes no PNG never
    // loads Qt).
    using Entry = void (*)(const std::string&, const std::string&, int);
    auto entry = reinterpret_cast<Entry>(
        plugin_symbol("libautoblock_raster.so", "autoblock_write_png_from_svg", "AUTOBLOCK_RASTER_LIBRARY"));
    entry(svg, path, 1200);
  }
}

}  // namespace autoblock
