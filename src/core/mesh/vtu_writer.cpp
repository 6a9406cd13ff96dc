#include "core/mesh/vtu_writer.h"

#include "core/mesh/msh41_writer.h"

namespace autoblock {

std::string vtu_text(const std::vector<std::array<double, 3>>& points, const VtuCells& cells) {
  const size_t n = cells.block.size();
  const size_t k = static_cast<size_t>(cells.nodes_per_cell);
  std::string out;
  out.reserve(points.size() * 48 + n * (16 * k + 32) + 1024);
  out += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n";
  out += "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(points.size()) + "\" NumberOfCells=\"" +
         std::to_string(n) + "\">\n";
  out += "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& p : points) {
    append_point(out, p, " ");
    out += '\n';
  }
  out += "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (size_t c = 0; c < n; ++c) {
    for (size_t j = 0; j < k; ++j) out += std::to_string(cells.connectivity[c * k + j]) + (j + 1 == k ? '\n' : ' ');
  }
  out += "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (size_t c = 0; c < n; ++c) out += std::to_string(k * (c + 1)) + '\n';
  out += "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  const std::string type = std::to_string(cells.vtk_type) + '\n';
  for (size_t c = 0; c < n; ++c) out += type;
  out += "</DataArray>\n</Cells>\n<CellData Scalars=\"block\">\n<DataArray type=\"Int32\" Name=\"block\" format=\"ascii\">\n";
  for (int b : cells.block) out += std::to_string(b + 1) + '\n';
  out += "</DataArray>\n<DataArray type=\"Float64\" Name=\"scaled_jacobian\" format=\"ascii\">\n";
  for (double j : cells.scaled_jacobian) {
    append_shortest(out, j);
    out += '\n';
  }
  out += "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

}  // namespace autoblock
