#include "core/mesh/mesh_picture.h"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "core/common/error.h"
#include "core/io/svg_picture.h"

namespace autoblock {
namespace {

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// Model to picture coordinates: scale k, margins, y flipped.
struct View {
  Box box;
  double k = 1, left = 0, top = 0;
  double x(double mx) const { return left + (mx - box.xmin) * k; }
  double y(double my) const { return top + (box.ymax - my) * k; }
};

struct Raster {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  void set(int px, int py, const unsigned char c[3]) {
    if (px < 0 || py < 0 || px >= width || py >= height) return;
    unsigned char* p = &rgb[3 * (static_cast<size_t>(py) * static_cast<size_t>(width) + static_cast<size_t>(px))];
    p[0] = c[0];
    p[1] = c[1];
    p[2] = c[2];
  }
  void fill(double x0, double y0, double x1, double y1, const unsigned char c[3]) {
    for (int py = static_cast<int>(std::lround(std::min(y0, y1))); py < std::lround(std::max(y0, y1)); ++py) {
      for (int px = static_cast<int>(std::lround(std::min(x0, x1))); px < std::lround(std::max(x0, x1)); ++px) set(px, py, c);
    }
  }
  // A segment `thickness` pixels wide (square pen).
  void line(double x0, double y0, double x1, double y1, int thickness, const unsigned char c[3]) {
    const int steps = static_cast<int>(std::ceil(std::max(std::fabs(x1 - x0), std::fabs(y1 - y0)))) + 1;
    const int half = thickness / 2;
    for (int s = 0; s <= steps; ++s) {
      const double t = static_cast<double>(s) / steps;
      const int px = static_cast<int>(std::lround(x0 + t * (x1 - x0))), py = static_cast<int>(std::lround(y0 + t * (y1 - y0)));
      for (int dy = -half; dy < thickness - half; ++dy) {
        for (int dx = -half; dx < thickness - half; ++dx) set(px + dx, py + dy, c);
      }
    }
  }
};

void colour_bytes(const std::string& hex, unsigned char out[3]) {
  for (int k = 0; k < 3; ++k) out[k] = static_cast<unsigned char>(std::stoi(hex.substr(1 + 2 * static_cast<size_t>(k), 2), nullptr, 16));
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

}  // namespace

std::string mesh_svg(const RectilinearPolygon& polygon, const std::vector<Box>& blocks, const QuadMesh& mesh,
                     const std::string& title) {
  const double margin = 24, title_height = 46, target = 720, min_width = 640;
  View v;
  v.box = ring_bbox(polygon.outer);
  v.k = target / v.box.longer_side();
  const double width = std::max(min_width, v.box.width() * v.k + 2 * margin);
  const double height = v.box.height() * v.k + 2 * margin + title_height;
  v.left = 0.5 * (width - v.box.width() * v.k);
  v.top = title_height + margin;
  std::ostringstream svg;
  svg.precision(6);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 "
      << width << ' ' << height << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const size_t bar = title.find(" | ");
  const std::string lines[2] = {title.substr(0, bar), bar == std::string::npos ? "" : title.substr(bar + 3)};
  for (int l = 0; l < 2; ++l) {
    svg << "<text x=\"" << margin << "\" y=\"" << 20 + 18 * l << "\" font-family=\"sans-serif\" font-size=\""
        << (l ? 13 : 15) << "\">" << escape(lines[l]) << "</text>\n";
  }
  for (size_t b = 0; b < blocks.size(); ++b) {
    const Box& r = blocks[b];
    svg << "<rect x=\"" << v.x(r.xmin) << "\" y=\"" << v.y(r.ymax) << "\" width=\"" << r.width() * v.k << "\" height=\""
        << r.height() * v.k << "\" fill=\"" << block_colour(static_cast<int>(b)) << "\"/>\n";
  }
  svg << "<path fill=\"none\" stroke=\"#444\" stroke-width=\"0.6\" d=\"";
  for (const MeshEdge& e : mesh_edges(mesh)) {
    const Point2& a = mesh.nodes[static_cast<size_t>(e.a)];
    const Point2& b = mesh.nodes[static_cast<size_t>(e.b)];
    svg << 'M' << v.x(a.x) << ',' << v.y(a.y) << 'L' << v.x(b.x) << ',' << v.y(b.y);
  }
  svg << "\"/>\n<path fill=\"none\" stroke=\"#222\" stroke-width=\"1.6\" d=\"";
  for (const Box& r : blocks) {
    svg << 'M' << v.x(r.xmin) << ',' << v.y(r.ymin) << 'H' << v.x(r.xmax) << 'V' << v.y(r.ymax) << 'H' << v.x(r.xmin) << 'Z';
  }
  svg << "\"/>\n<path fill=\"none\" stroke=\"black\" stroke-width=\"2.5\" d=\"";
  auto ring_path = [&](const Ring& ring) {
    for (size_t i = 0; i < ring.size(); ++i) svg << (i == 0 ? 'M' : 'L') << v.x(ring[i].x) << ',' << v.y(ring[i].y);
    svg << 'Z';
  };
  ring_path(polygon.outer);
  for (const Ring& hole : polygon.holes) ring_path(hole);
  svg << "\"/>\n</svg>\n";
  return svg.str();
}

std::string mesh_png(const RectilinearPolygon& polygon, const std::vector<Box>& blocks, const QuadMesh& mesh,
                     int longer_side_pixels) {
  const int margin = 16;
  View v;
  v.box = ring_bbox(polygon.outer);
  v.k = longer_side_pixels / v.box.longer_side();
  v.left = margin;
  v.top = margin;
  Raster raster;
  raster.width = static_cast<int>(std::ceil(v.box.width() * v.k)) + 2 * margin;
  raster.height = static_cast<int>(std::ceil(v.box.height() * v.k)) + 2 * margin;
  raster.rgb.assign(3 * static_cast<size_t>(raster.width) * static_cast<size_t>(raster.height), 255);
  unsigned char colour[3];
  for (size_t b = 0; b < blocks.size(); ++b) {
    colour_bytes(block_colour(static_cast<int>(b)), colour);
    raster.fill(v.x(blocks[b].xmin), v.y(blocks[b].ymin), v.x(blocks[b].xmax), v.y(blocks[b].ymax), colour);
  }
  const unsigned char edge[3] = {80, 80, 80}, side[3] = {30, 30, 30}, outline[3] = {0, 0, 0};
  for (const MeshEdge& e : mesh_edges(mesh)) {
    const Point2& a = mesh.nodes[static_cast<size_t>(e.a)];
    const Point2& b = mesh.nodes[static_cast<size_t>(e.b)];
    raster.line(v.x(a.x), v.y(a.y), v.x(b.x), v.y(b.y), 1, edge);
  }
  for (const Box& r : blocks) {
    raster.line(v.x(r.xmin), v.y(r.ymin), v.x(r.xmax), v.y(r.ymin), 2, side);
    raster.line(v.x(r.xmax), v.y(r.ymin), v.x(r.xmax), v.y(r.ymax), 2, side);
    raster.line(v.x(r.xmax), v.y(r.ymax), v.x(r.xmin), v.y(r.ymax), 2, side);
    raster.line(v.x(r.xmin), v.y(r.ymax), v.x(r.xmin), v.y(r.ymin), 2, side);
  }
  auto ring_lines = [&](const Ring& ring) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const Point2& a = ring[i];
      const Point2& b = ring[(i + 1) % ring.size()];
      raster.line(v.x(a.x), v.y(a.y), v.x(b.x), v.y(b.y), 3, outline);
    }
  };
  ring_lines(polygon.outer);
  for (const Ring& hole : polygon.holes) ring_lines(hole);

  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(raster.width);
  image.height = static_cast<png_uint_32>(raster.height);
  image.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&image, nullptr, &size, 0, raster.rgb.data(), 0, nullptr)) {
    throw std::runtime_error(std::string("libpng: ") + image.message);
  }
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&image, bytes.data(), &size, 0, raster.rgb.data(), 0, nullptr)) {
    throw std::runtime_error(std::string("libpng: ") + image.message);
  }
  bytes.resize(size);
  return bytes;
}

std::string mesh_picture(const std::string& path, const RectilinearPolygon& polygon, const std::vector<Box>& blocks,
                         const QuadMesh& mesh, const std::string& title) {
  const std::string ext = lower_extension(path);
  if (ext == ".svg") return mesh_svg(polygon, blocks, mesh, title);
  if (ext == ".png") return mesh_png(polygon, blocks, mesh);
  throw InputError(path + ": unknown picture type '" + ext + "' (expected .svg or .png)");
}

}  // namespace autoblock
