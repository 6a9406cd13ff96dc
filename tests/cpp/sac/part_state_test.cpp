#include "support/catch_torch.h"

#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "core/geometry/part_symmetry.h"
#include "core/sac/lookahead_agent.h"
#include "core/sac/part_state.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

// Positions matched to a micrometre: an edge point is computed from either end, depending on the
// direction the transformed loop runs in, so it can differ in the last bit.
using Key = std::pair<long long, long long>;

Key key_of(const Point2& p) { return {std::llround(p.x * 1e6), std::llround(p.y * 1e6)}; }

}  // namespace

TEST_CASE("a symmetric view of a bounded graph is the transformed part's own state", "[sac][state]") {
  // An L with irregular coordinates (no four of its graph's points on one circle, so the
  // triangulation has no ties to break): in each of the eight symmetries, the view made from the
  // untransformed state and the state of the transformed part have the same nodes (matched by
  // position), node features, edges and pseudo-coordinates.
  const GridFace face = test::grid_face_of({{0, 0}, {3.7, 0}, {3.7, 2.1}, {1.3, 2.1}, {1.3, 5.9}, {0, 5.9}});
  PartStateOptions options;
  options.lookahead = true;
  options.face_size = face.size;
  const auto base = make_part_state(face.whole, options);
  REQUIRE(base->graph.node_count() > 6);  // edge points too
  for (int s = 0; s < 8; ++s) {
    INFO("symmetry " << s);
    const auto view = symmetric_view(*base, s);
    const auto own = make_part_state(transform_part(face.whole, s), options);
    REQUIRE(view->graph.node_count() == own->graph.node_count());
    std::map<Key, int> own_node;
    for (int n = 0; n < own->graph.node_count(); ++n) own_node[key_of(own->graph.positions[static_cast<size_t>(n)])] = n;
    std::vector<int> to_own(static_cast<size_t>(view->graph.node_count()));
    for (int n = 0; n < view->graph.node_count(); ++n) {
      const auto found = own_node.find(key_of(view->graph.positions[static_cast<size_t>(n)]));
      REQUIRE(found != own_node.end());
      to_own[static_cast<size_t>(n)] = found->second;
      for (int f = 0; f < kLookaheadFeatures; ++f) {
        CHECK(view->features[static_cast<size_t>(n * kLookaheadFeatures + f)] ==
              Approx(own->features[static_cast<size_t>(found->second * kLookaheadFeatures + f)]).margin(1e-6));
      }
    }
    std::map<std::pair<int, int>, std::array<float, 2>> own_edges;
    for (size_t e = 0; e < own->graph.edges.size(); ++e) {
      own_edges[{own->graph.edges[e][0], own->graph.edges[e][1]}] = own->graph.pseudo[e];
    }
    REQUIRE(view->graph.edges.size() == own_edges.size());
    for (size_t e = 0; e < view->graph.edges.size(); ++e) {
      const auto found = own_edges.find({to_own[static_cast<size_t>(view->graph.edges[e][0])],
                                         to_own[static_cast<size_t>(view->graph.edges[e][1])]});
      REQUIRE(found != own_edges.end());
      CHECK(view->graph.pseudo[e][0] == Approx(found->second[0]).margin(1e-6));
      CHECK(view->graph.pseudo[e][1] == Approx(found->second[1]).margin(1e-6));
    }
    // The model vertices are the same set of nodes.
    std::set<int> view_vertices, own_vertices(own->graph.vertex_nodes.begin(), own->graph.vertex_nodes.end());
    for (int v : view->graph.vertex_nodes) view_vertices.insert(to_own[static_cast<size_t>(v)]);
    CHECK(view_vertices == own_vertices);
  }
  CHECK_THROWS(symmetric_view(*base, 8));
}
