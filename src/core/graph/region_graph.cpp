#include "core/graph/region_graph.h"

#include <stdexcept>

namespace autoblock {

PartGraph region_graph(const Region& region, const GraphOptions& options) {
  if (region.is_empty()) throw std::invalid_argument("region_graph: the region is empty");
  return loops_graph(region.loops(), region.bbox().longer_side(), options);
}

}  // namespace autoblock
