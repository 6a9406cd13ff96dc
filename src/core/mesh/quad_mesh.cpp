#include "core/mesh/quad_mesh.h"

#include <algorithm>
#include <cstdint>

namespace autoblock {

std::vector<MeshEdge> mesh_edges(const QuadMesh& mesh) {
  std::vector<std::uint64_t> keys;
  keys.reserve(mesh.quads.size() * 4);
  for (const auto& quad : mesh.quads) {
    for (size_t k = 0; k < 4; ++k) {
      const auto a = static_cast<std::uint32_t>(quad[k]), b = static_cast<std::uint32_t>(quad[(k + 1) % 4]);
      keys.push_back(static_cast<std::uint64_t>(std::min(a, b)) << 32 | std::max(a, b));
    }
  }
  std::sort(keys.begin(), keys.end());
  std::vector<MeshEdge> edges;
  for (size_t k = 0; k < keys.size();) {
    size_t e = k;
    while (e < keys.size() && keys[e] == keys[k]) ++e;
    edges.push_back(MeshEdge{static_cast<int>(keys[k] >> 32), static_cast<int>(keys[k] & 0xffffffffu), static_cast<int>(e - k)});
    k = e;
  }
  return edges;
}

}  // namespace autoblock
