#include "core/region/region_policy.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <cmath>
#include <random>
#include <thread>

#include <catch2/catch.hpp>

#include "core/data/general_generator.h"
#include "core/env/region_replay.h"
#include "core/geometry/occt_face.h"
#include "core/geometry/occt_properties.h"
#include "core/geometry/tolerance.h"
#include "core/region/region_candidates.h"
#include "core/region/region_reward.h"
#include "core/region/region_search.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

Region face_region(const GeneralShape& shape) {
  const Box box = ring_bbox(shape.outer);
  return Region(shape.outer, shape.holes, tolerance_for_size(box.longer_side()));
}

bool inside(const Region& r, Point2 p) {
  if (!point_in_ring(p, r.outer())) return false;
  for (const Ring& h : r.holes()) {
    if (point_in_ring(p, h)) return false;
  }
  return true;
}

// Every finished part is a block (four corners within the rules) or a convex template; their areas
// add up to the face's; sampled points of the face lie in exactly one part (no overlap, no gap).
std::string describe(const Region& r) {
  std::string s;
  for (int k = 0; k < r.loop_count(); ++k) {
    s += k == 0 ? "outer:" : " hole:";
    for (const Point2& p : r.loop(k)) {
      char buffer[80];
      std::snprintf(buffer, sizeof buffer, " (%.17g, %.17g)", p.x, p.y);
      s += buffer;
    }
  }
  return s;
}

void check_decomposition(const Region& face, const RegionDecomposition& d, std::mt19937_64& rng) {
  INFO("policy " << d.policy << ", face " << describe(face) << (d.unfinished.empty() ? "" : "; left " + describe(d.unfinished[0])));
  REQUIRE(d.complete());
  double area = 0.0;
  const double perimeter = region_perimeter(face);
  for (const FinishedRegion& f : d.finished) {
    area += f.region.area();
    if (f.is_template) {
      CHECK(template_applies(f.region));
    } else {
      CHECK(is_block(f.region, d.rules));  // by the rules the decomposition ran with (face-adaptive for the mesh preset)
    }
  }
  // Each cut moves its new points by at most q / sqrt(2) (region.h).
  CHECK(std::fabs(area - face.area()) <= face.quantum() * perimeter * (1.0 + d.cuts.size()));
  const Box box = face.bbox();
  std::uniform_real_distribution<double> ux(box.xmin, box.xmax), uy(box.ymin, box.ymax);
  for (int s = 0; s < 30; ++s) {
    const Point2 p{ux(rng), uy(rng)};
    if (!inside(face, p)) continue;
    int count = 0;
    for (const FinishedRegion& f : d.finished) count += inside(f.region, p) ? 1 : 0;
    CHECK(count == 1);
  }
}

}  // namespace

TEST_CASE("greedy on general faces: a square is one block, an L two, a triangle a template", "[region][policy]") {
  const double q = 1e-7;
  RegionGreedyPolicy greedy;
  const auto square = decompose_region(Region(Ring{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}, q), greedy);
  CHECK(square.complete());
  CHECK(square.blocks == 1);
  CHECK(square.cuts.empty());
  const auto l = decompose_region(Region(Ring{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}, q), greedy);
  CHECK(l.complete());
  CHECK(l.blocks == 2);
  CHECK(l.templates == 0);
  const auto triangle = decompose_region(Region(Ring{{0, 0}, {4, 0}, {2, 3}}, {}, q), greedy);
  CHECK(triangle.complete());
  CHECK(triangle.blocks + triangle.templates >= 1);
  // A parallelogram at 60 degrees is a block as it is.
  const auto slanted = decompose_region(Region(Ring{{0, 0}, {4, 0}, {5, std::sqrt(3.0)}, {1, std::sqrt(3.0)}}, {}, q), greedy);
  CHECK(slanted.blocks == 1);
  CHECK(slanted.cuts.empty());
}

TEST_CASE("a reflex fillet: its open ends count as reflex corners, cut square to the arc", "[region][policy][arc]") {
  // An L (legs 4 wide, arms reaching 10) whose reflex corner is filleted with radius 2 (arc samples
  // every 15 degrees: side vertices). Its complexity counts the arc's two open ends as reflex corners.
  const double q = 1e-7;
  Ring ring{{0, 0}, {10, 0}, {10, 4}};
  for (int k = 0; k <= 6; ++k) ring.push_back({6 - 2 * std::sin(k * M_PI / 12), 6 - 2 * std::cos(k * M_PI / 12)});
  ring.push_back({4, 10});
  ring.push_back({0, 10});
  const Region l(ring, {}, q);
  const Complexity before = part_complexity(l);
  CHECK(before.reflex == 2);
  // Cut square to the boundary at the arc's end (6, 4), down to the bottom: progress (the corner part
  // keeps one open end, the arm is a rectangle).
  const RegionCut square{CutKind::Partial, {6, 4}, {0, -1}};
  const std::vector<Region> pieces = cut_region(l, square).pieces;
  REQUIRE(pieces.size() == 2);
  CHECK(makes_progress(l, pieces));
  // (A cut from one of the arc's samples, along its chord or across the part, makes progress too by
  // this rule when it starts at the part's own vertex: the piece beyond it loses a corner. No rule
  // forbids the fan of slivers along the arc that the search once made; its values keep it away, as
  // the decomposition below shows: two cuts, three parts.)
  // progress_action cuts at an open end, square to the edge there.
  const RegionAction action = progress_action(l);
  REQUIRE(action.kind == RegionAction::Kind::Cut);
  CHECK(((action.cut.origin.x == Approx(6) && action.cut.origin.y == Approx(4)) ||
         (action.cut.origin.x == Approx(4) && action.cut.origin.y == Approx(6))));
  CHECK(std::fabs(action.cut.direction.x * action.cut.direction.y) < 1e-12);
  // Under the mesh preset's rules (no block corner under about 58 degrees: the diagonal from the
  // outer corner to the arc's middle leaves 45), the search finishes it in three parts: two arms and
  // the corner piece (the template: five quads around the five-valent vertex such a part needs), no
  // slivers along the arc; greedy (no lookahead) finishes it too.
  RegionEpisodeOptions options;
  options.reward = RewardPreset::Mesh;
  RegionSearchPolicy search;
  const RegionDecomposition d = decompose_region(l, search, options);
  CHECK(d.complete());
  CHECK(std::count_if(d.cuts.begin(), d.cuts.end(), [](const RegionCutRecord& c) { return c.action.kind == RegionAction::Kind::Cut; }) == 2);
  REQUIRE(d.finished.size() == 3);
  CHECK(d.templates == 1);
  for (const FinishedRegion& f : d.finished) CHECK(f.region.area() > 0.1 * l.area());
  RegionGreedyPolicy greedy;
  CHECK(decompose_region(l, greedy, options).complete());
}

TEST_CASE("every general face ends in blocks, whatever the policy (property test)", "[region][policy][property]") {
  // 3000 generated faces (polygons, turned and chamfered unions; a quarter with holes; 10 or 20
  // vertices; sizes 0.01 to 10000): random on each, greedy on every third, the search on every
  // hundredth; every 20th random decomposition replayed by OpenCASCADE (the same pieces, areas within
  // the lattice's rounding, or replay_region_cuts_occt throws).
  std::mt19937_64 rng(2026);
  const GeneralKind kinds[] = {GeneralKind::Polygon, GeneralKind::Turned, GeneralKind::Chamfered};
  int faces = 0, replayed = 0;
  for (int i = 0; i < 3000; ++i) {
    GeneralOptions options;
    options.kind = kinds[i % 3];
    options.holes = i % 4 == 0;
    options.max_vertices = i % 5 == 0 ? 20 : 10;
    options.size = std::pow(10.0, static_cast<double>(i % 7) - 2.0);  // 0.01 to 10000
    const GeneralShape shape = generate_general_shape(rng, options);
    const Region face = face_region(shape);
    REQUIRE_FALSE(face.is_empty());
    INFO("face " << i);
    RegionRandomPolicy random(static_cast<std::uint64_t>(i));
    const RegionDecomposition d = decompose_region(face, random);
    check_decomposition(face, d, rng);
    if (i % 20 == 0) {
      const TopoDS_Face occt = occt_face_from_polygon(RectilinearPolygon{shape.outer, shape.holes}, 0.0, true);
      const std::vector<TopoDS_Face> blocks = replay_region_cuts_occt(occt, face, d, RegionEpisodeOptions{});
      CHECK(blocks.size() == d.finished.size());
      double area = 0.0;
      for (const TopoDS_Face& b : blocks) area += occt_area(b);
      CHECK(area == Approx(occt_area(occt)).epsilon(1e-6));
      ++replayed;
    }
    RegionEpisodeOptions mesh;
    mesh.reward = RewardPreset::Mesh;
    if (i % 3 == 0) {
      RegionGreedyPolicy greedy;
      check_decomposition(face, decompose_region(face, greedy, mesh), rng);
    }
    if (i % 100 == 0) {
      RegionSearchOptions quick;
      quick.time_limit = 0.2;
      RegionSearchPolicy search(quick);
      check_decomposition(face, decompose_region(face, search, mesh), rng);
    }
    ++faces;
  }
  CHECK(faces == 3000);
  CHECK(replayed == 150);
}

TEST_CASE("score_candidates keeping the best k: the same k best as scoring every candidate", "[region][policy]") {
  // Generated faces and the pieces of their first cuts, with and without holes: sorted by reward
  // (stable, as the search and greedy take them), the first k of score_candidates(..., k) are the
  // first k of score_candidates(..., 0), which scores every candidate; what it returns is in the
  // candidates' order, a subsequence of the whole list. The same with the search's taper charge
  // (mesh preset), whose rewards are the plain ones less the taper costs of the blocks left.
  std::mt19937_64 rng(909);
  const GeneralKind kinds[] = {GeneralKind::Polygon, GeneralKind::Chamfered};
  long compared = 0, left_out = 0, tapered = 0;
  for (int i = 0; i < 24; ++i) {
    GeneralOptions options;
    options.kind = kinds[i % 2];
    options.holes = i % 4 == 0;
    options.max_vertices = i % 3 == 0 ? 24 : 12;
    const Region face = face_region(generate_general_shape(rng, options));
    const std::vector<Region> parts = test::face_and_first_pieces(face, 5);
    for (const RewardPreset preset : {RewardPreset::Mesh, RewardPreset::Paper}) {
      RegionEpisodeOptions episode;
      episode.reward = preset;
      for (const Region& part : parts) {
        if (is_block(part, episode.rules)) continue;
        for (const bool taper : {false, true}) {
          if (taper && preset != RewardPreset::Mesh) continue;
          auto by_reward = [](std::vector<ScoredAction> s) {
            std::stable_sort(s.begin(), s.end(), [](const ScoredAction& a, const ScoredAction& b) { return a.reward > b.reward; });
            return s;
          };
          const std::vector<ScoredAction> all = score_candidates(part, face.bbox().longer_side(), episode, nullptr, 0, taper);
          const std::vector<ScoredAction> sorted_all = by_reward(all);
          if (taper) {
            const std::vector<ScoredAction> plain = score_candidates(part, face.bbox().longer_side(), episode);
            REQUIRE(plain.size() == all.size());
            for (size_t j = 0; j < all.size(); ++j) {
              CHECK(all[j].reward == Approx(plain[j].reward - pieces_taper_cost(plain[j].outcome->pieces, episode.rules)));
              tapered += all[j].reward < plain[j].reward;
            }
          }
          for (const size_t k : {size_t{1}, size_t{4}, size_t{8}}) {
            const std::vector<ScoredAction> kept =
                score_candidates(part, face.bbox().longer_side(), episode, nullptr, k, taper);
            REQUIRE(kept.size() >= std::min(k, all.size()));
            size_t at = 0;  // a subsequence of all, in order
            for (const ScoredAction& s : kept) {
              while (at < all.size() && !(all[at].action.cut.origin == s.action.cut.origin &&
                                          all[at].action.cut.direction == s.action.cut.direction &&
                                          all[at].action.kind == s.action.kind && all[at].action.cut.kind == s.action.cut.kind)) {
                ++at;
              }
              REQUIRE(at < all.size());
              CHECK(all[at].reward == s.reward);
              ++at;
            }
            const std::vector<ScoredAction> sorted_kept = by_reward(kept);
            for (size_t j = 0; j < std::min(k, all.size()); ++j) {
              CHECK(sorted_kept[j].reward == sorted_all[j].reward);
              CHECK(sorted_kept[j].action.cut.origin == sorted_all[j].action.cut.origin);
              CHECK(sorted_kept[j].action.cut.direction == sorted_all[j].action.cut.direction);
              CHECK(sorted_kept[j].action.kind == sorted_all[j].action.kind);
            }
            ++compared;
            left_out += static_cast<long>(all.size() - kept.size());
          }
        }
      }
    }
  }
  CHECK(compared > 200);
  CHECK(left_out > 0);  // the bound leaves candidates out (mesh preset, parts without holes)
  CHECK(tapered > 0);   // some cuts leave blocks that taper more than kMeshTaperFrom
}

TEST_CASE("a convex fillet: its open ends count as corners, cut square to the edges, its sector takes the template",
          "[region][policy][arc]") {
  // A 10 x 6 rectangle whose top-right corner is rounded with radius 2 (centre (8, 4); samples every 15
  // degrees). Three corners and the fillet's two open ends: complexity 5.
  const double q = 1e-7;
  Ring ring{{0, 0}, {10, 0}};
  for (int k = 0; k <= 6; ++k) ring.push_back({8 + 2 * std::cos(k * M_PI / 12), 4 + 2 * std::sin(k * M_PI / 12)});
  ring.push_back({0, 6});
  const Region part(ring, {}, q);
  CHECK(part_complexity(part).corners == 5);
  // The usual template would take the fillet into a side: not a candidate.
  for (const RegionAction& a : region_candidates(part)) CHECK(a.kind == RegionAction::Kind::Cut);
  // The cut square to the top edge at the fillet's end (8, 6), down to the bottom: progress (the strip
  // keeps one open end, the rest is a rectangle).
  CHECK(makes_progress(part, cut_region(part, RegionCut{CutKind::Partial, {8, 6}, {0, -1}}).pieces));
  // (A cut from a sample in the middle of the arc, from the part's own vertex there, makes progress
  // too: the two pieces have four and three corners. The search's values, not a rule, keep the
  // fillet whole: its sector is one template below.)
  const RegionAction action = progress_action(part);
  REQUIRE(action.kind == RegionAction::Kind::Cut);
  CHECK(((action.cut.origin.x == Approx(10) && action.cut.origin.y == Approx(4)) ||
         (action.cut.origin.x == Approx(8) && action.cut.origin.y == Approx(6))));
  CHECK(std::fabs(action.cut.direction.x * action.cut.direction.y) < 1e-12);
  // The search (mesh preset) finishes it with the fillet's sector as a template (within the square of
  // the fillet's circle, [6, 10] x [2, 6]: cut at the arc's ends, square to the edge or to the arc's
  // first chord, 7.5 degrees apart) and the rest in blocks; greedy finishes it too.
  RegionEpisodeOptions options;
  options.reward = RewardPreset::Mesh;
  RegionSearchPolicy search;
  const RegionDecomposition d = decompose_region(part, search, options);
  REQUIRE(d.complete());
  REQUIRE(d.templates == 1);
  for (const FinishedRegion& f : d.finished) {
    if (!f.is_template) continue;
    CHECK(f.region.area() > 0.9 * M_PI);
    for (const Point2& p : f.region.outer()) CHECK((p.x >= 6 && p.y >= 2));
  }
  RegionGreedyPolicy greedy;
  CHECK(decompose_region(part, greedy, options).complete());
}

TEST_CASE("a part with two corners that the smooth template does not take: cut under cut_smooth_parts",
          "[region][policy][arc]") {
  // Face 150 of the arc benchmark (`autoblock generate --kind arcs --seed 20261202`), as the engine
  // sees it: a long wedge whose wide end and two lower corners are rounded (arcs: side vertices) and
  // whose tip is rounded by an arc shorter than an element (one chord: the tip's two corners, at
  // (1.50, 0.78) and (1.41, 0.85)). Two corners, and the smooth template folds on it.
  const Ring ring{{-0.37844218365095117, -1.1406757156707579}, {-0.26552926929177695, -1.1388855796092732},
                  {-0.1561577305675237, -1.110770599640451},   {-0.0563789634072447, -1.0578869344899777},
                  {1.261896022265787, -0.14582233528558106},   {1.3211706796063507, -0.09483651954811072},
                  {1.3684999262635262, -0.032603335485842135}, {1.4017995088854331, 0.03813710892009884},
                  {1.41960302987265, 0.1142692049770431},      {1.5023609930667456, 0.775009233121149},
                  {1.4092766107033339, 0.854257835482025},     {1.2472131964350608, 0.8068080097118997},
                  {1.1440432539244783, 0.7650032611726001},    {-1.43252683683233, -0.5932764632543575},
                  {-1.4550796190102449, -0.6091722611046821},  {-1.472837960230575, -0.6302897628736145},
                  {-1.4846298793880495, -0.6552346790664999},  {-1.4896765491104398, -0.6823610898313867},
                  {-1.4876455540268099, -0.7098779614955276},  {-1.478670339011541, -0.7359691272708211},
                  {-1.4633436267017383, -0.75891237034799},    {-1.442677024990412, -0.7771934205269384},
                  {-1.4180346037930407, -0.789605289863152},   {-0.48864969766448874, -1.1160425697897673}};
  const Region part(ring, {}, tolerance_for_size(ring_bbox(ring).longer_side()));
  const BlockRules plain;
  BlockRules cutting;
  cutting.cut_smooth_parts = true;
  REQUIRE(part_complexity(part, plain).corners == 2);
  REQUIRE_FALSE(smooth_template(part, plain));
  CHECK(part_complexity(part, cutting).corners == 2 + kSmoothPartCorners);
  // Under the plain rules no candidate cut makes progress (every piece has at least the part's two
  // corners): the template's fallback is all a policy may do. Under cut_smooth_parts some cuts do.
  int plain_progress = 0, cutting_progress = 0;
  for (const RegionAction& a : region_candidates(part)) {
    if (a.kind != RegionAction::Kind::Cut) continue;
    const std::vector<Region> pieces = cut_region(part, a.cut).pieces;
    plain_progress += makes_progress(part, pieces, plain);
    cutting_progress += makes_progress(part, pieces, cutting);
  }
  CHECK(plain_progress == 0);
  CHECK(cutting_progress > 0);
  CHECK(progress_action(part, plain).kind == RegionAction::Kind::Template);
  // The search (mesh preset) takes the template under the plain rules; with the flag it cuts, and
  // every piece it finishes has four corners or is a template of a simpler part.
  RegionEpisodeOptions options;
  options.reward = RewardPreset::Mesh;
  RegionSearchPolicy search;
  const RegionDecomposition before = decompose_region(part, search, options);
  REQUIRE(before.complete());
  CHECK(before.finished.size() == 1);
  options.cut_smooth_parts = true;
  const RegionDecomposition after = decompose_region(part, search, options);
  REQUIRE(after.complete());
  CHECK(after.finished.size() >= 2);
  CHECK(after.rules.cut_smooth_parts);
  double area = 0.0;
  for (const FinishedRegion& f : after.finished) area += f.region.area();
  CHECK(area == Approx(part.area()).epsilon(1e-6));  // the cuts end on the face's lattice
  // A disk, which the smooth template takes, is no more complex under the flag.
  Ring disk;
  for (int k = 0; k < 24; ++k) disk.push_back({std::cos(k * M_PI / 12), std::sin(k * M_PI / 12)});
  const Region round(disk, {}, 1e-7);
  REQUIRE(smooth_template(round, plain));
  CHECK(part_complexity(round, cutting).corners == part_complexity(round, plain).corners);
}

namespace {

// A policy that counts its choices and takes 2 ms over each, or 1-5 ms at random (a slow learned
// policy's stand-in), each counted as 1000 units of work.
class SlowGreedy : public RegionPolicy {
 public:
  explicit SlowGreedy(bool random_sleep = false) : random_sleep_(random_sleep) {}
  std::string name() const override { return "slow"; }
  RegionAction choose(const RegionEpisode& episode) override {
    ++calls;
    std::this_thread::sleep_for(std::chrono::milliseconds(random_sleep_ ? 1 + std::rand() % 5 : 2));
    return greedy.choose(episode);
  }
  long long work() const override { return 1000LL * calls; }
  int calls = 0;
  RegionGreedyPolicy greedy;

 private:
  bool random_sleep_;
};

}  // namespace

TEST_CASE("a timed policy: past its budget greedy finishes the face, and a new face starts the clock again",
          "[region][policy]") {
  std::mt19937_64 rng(20261204);
  GeneralOptions generate;
  generate.min_vertices = generate.max_vertices = 16;
  const Region face = face_region(generate_general_shape(rng, generate));
  RegionEpisodeOptions options;
  options.reward = RewardPreset::Mesh;
  // No budget: the wrapped policy makes every choice.
  {
    auto slow = std::make_unique<SlowGreedy>();
    SlowGreedy* inner = slow.get();
    TimedRegionPolicy timed(std::move(slow), 0.0);
    const RegionDecomposition d = decompose_region(face, timed, options);
    REQUIRE(d.complete());
    CHECK(d.policy_steps >= 3);
    CHECK(inner->calls == d.policy_steps);
    CHECK_FALSE(d.time_capped);
  }
  // A budget of a microsecond: the first choice is the policy's, the others greedy's; the same
  // decomposition (the stand-in is greedy), complete, and reported as capped.
  auto slow = std::make_unique<SlowGreedy>();
  SlowGreedy* inner = slow.get();
  TimedRegionPolicy timed(std::move(slow), 1e-6);
  const RegionDecomposition d = decompose_region(face, timed, options);
  REQUIRE(d.complete());
  CHECK(inner->calls == 1);
  CHECK(d.time_capped);
  RegionGreedyPolicy greedy;
  CHECK(decompose_region(face, greedy, options).finished.size() == d.finished.size());
  // The next face (an episode at its first step) gets the policy again.
  const RegionDecomposition again = decompose_region(face, timed, options);
  CHECK(inner->calls == 2);
  CHECK(again.time_capped);
}

TEST_CASE("a timed policy's budget is its counted work: the same choices however long they take", "[region][policy]") {
  std::mt19937_64 rng(20261206);
  GeneralOptions generate;
  generate.min_vertices = generate.max_vertices = 24;
  const Region face = face_region(generate_general_shape(rng, generate));
  RegionEpisodeOptions options;
  options.reward = RewardPreset::Mesh;
  // 3 500 units: the policy's first four choices (0, 1 000, 2 000 and 3 000 units spent before them),
  // then greedy's, whatever each choice's wall time.
  const double seconds = 3500.0 / kSearchWorkPerSecond;
  for (int run = 0; run < 3; ++run) {
    auto slow = std::make_unique<SlowGreedy>(true);
    SlowGreedy* inner = slow.get();
    TimedRegionPolicy timed(std::move(slow), seconds);
    const RegionDecomposition d = decompose_region(face, timed, options);
    REQUIRE(d.complete());
    REQUIRE(d.cuts.size() > 4);
    CHECK(inner->calls == 4);
    CHECK(d.time_capped);
    CHECK(d.work == 4000);
  }
}
