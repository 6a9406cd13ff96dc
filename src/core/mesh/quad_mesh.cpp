#include "core/mesh/quad_mesh.h"

#include <algorithm>
#include <cstdint>

namespace autoblock {

std::vector<MeshEdge> mesh_edges(const QuadMesh& mesh) {
  // Key: (min, max) in the high bits, direction (1: min -> max) in the lowest.
  std::vector<std::uint64_t> keys;
  keys.reserve(mesh.quads.size() * 4);
  for (const auto& quad : mesh.quads) {
    for (size_t k = 0; k < 4; ++k) {
      const auto a = static_cast<std::uint64_t>(static_cast<std::uint32_t>(quad[k]));
      const auto b = static_cast<std::uint64_t>(static_cast<std::uint32_t>(quad[(k + 1) % 4]));
      keys.push_back((std::min(a, b) << 32 | std::max(a, b)) << 1 | (a < b ? 1u : 0u));
    }
  }
  std::sort(keys.begin(), keys.end());
  std::vector<MeshEdge> edges;
  for (size_t k = 0; k < keys.size();) {
    const std::uint64_t edge = keys[k] >> 1;
    MeshEdge e{static_cast<int>(edge >> 32), static_cast<int>(edge & 0xffffffffu), 0, 0};
    for (; k < keys.size() && keys[k] >> 1 == edge; ++k) {
      ++e.uses;
      e.forward += static_cast<int>(keys[k] & 1u);
    }
    edges.push_back(e);
  }
  return edges;
}

}  // namespace autoblock
