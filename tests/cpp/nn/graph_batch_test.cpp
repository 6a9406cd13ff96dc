#include "support/catch_torch.h"


#include "core/env/observation.h"
#include "core/geometry/part_boundary.h"
#include "core/graph/part_graph.h"
#include "core/nn/graph_batch.h"
#include "core/nn/tensor_convert.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("batch_graphs concatenates graphs and shifts their node indices", "[nn][batch]") {
  const GridFace l = test::grid_face_of(test::l_shape());
  const GridFace holed = test::grid_face_of(test::square3(), {test::centre_hole()});
  const PartGraph a = part_graph(l.whole), b = part_graph(holed.whole);
  const GraphBatch batch = batch_graphs({&a, &b, &a});
  const int64_t na = a.node_count(), nb = b.node_count(), ea = a.edge_count(), eb = b.edge_count();
  CHECK(batch.graph_count() == 3);
  CHECK((batch.node_offsets == std::vector<int64_t>{0, na, na + nb, 2 * na + nb}));
  CHECK((batch.vertex_offsets == std::vector<int64_t>{0, 6, 14, 20}));
  REQUIRE(batch.x.sizes() == torch::IntArrayRef({2 * na + nb, 3}));
  REQUIRE(batch.edge_index.sizes() == torch::IntArrayRef({2, 2 * ea + eb}));
  REQUIRE(batch.pseudo.sizes() == torch::IntArrayRef({2 * ea + eb, 2}));
  CHECK(batch.x.scalar_type() == torch::kFloat);
  CHECK(batch.edge_index.scalar_type() == torch::kLong);
  CHECK(batch.vertex_nodes.scalar_type() == torch::kLong);
  // Graph b's first edge and its features, shifted by a's nodes.
  CHECK(batch.edge_index[0][ea].item<int64_t>() == na + b.edges[0][0]);
  CHECK(batch.edge_index[1][ea].item<int64_t>() == na + b.edges[0][1]);
  CHECK(batch.pseudo[ea][1].item<float>() == b.pseudo[0][1]);
  for (int k = 0; k < 3; ++k) CHECK(batch.x[na + 5][k].item<float>() == b.features[5][static_cast<size_t>(k)]);
  // Vertex nodes, graph by graph.
  for (int64_t v = 0; v < 8; ++v) CHECK(batch.vertex_nodes[6 + v].item<int64_t>() == na + b.vertex_nodes[static_cast<size_t>(v)]);
  CHECK(batch.vertex_nodes[14].item<int64_t>() == na + nb + a.vertex_nodes[0]);
  // Every model-vertex node carries the feature (0,0,1).
  CHECK(batch.x.index_select(0, batch.vertex_nodes).select(1, 2).eq(1).all().item<bool>());
  CHECK_THROWS_AS(batch_graphs({}), std::invalid_argument);
}

TEST_CASE("observations_tensor stacks observations as rows", "[nn][batch]") {
  const GridFace face = test::grid_face_of(test::l_shape());
  const auto loops = part_boundary(face.whole);
  std::vector<Observation> observations;
  for (int k = 0; k < 6; ++k) observations.push_back(observe_vertex(face.whole, loops, 0, k));
  const torch::Tensor t = observations_tensor(observations);
  REQUIRE(t.sizes() == torch::IntArrayRef({6, 9}));
  for (int k = 0; k < 6; ++k) {
    for (int c = 0; c < 9; ++c) CHECK(t[k][c].item<float>() == observations[static_cast<size_t>(k)][static_cast<size_t>(c)]);
  }
  CHECK(observations_tensor({}).sizes() == torch::IntArrayRef({0, 9}));
}
