#include "support/catch_torch.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "core/common/error.h"
#include "core/region/block.h"
#include "core/region/region_observation.h"
#include "core/region/region_policy.h"
#include "core/sac/continuous_sac_agent.h"
#include "core/sac/cut_proposer.h"
#include "core/sac/deploy_profile.h"
#include "core/sac/lookahead_agent.h"
#include "core/sac/policy_file.h"
#include "core/sac/region_lookahead.h"
#include "core/sac/region_lookahead_policy.h"
#include "core/sac/sac_config.h"
#include "core/sac/training_curves.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

SacConfig proposing_config(int candidates) {
  SacConfig config = default_sac_config("lookahead");
  config.reward = RewardPreset::Mesh;
  config.train_top_k = 5;
  config.actor_candidates = candidates;
  return config;
}

// The deterministic turn the proposer gives at an input.
double mean_angle(CutProposer& proposer, const ProposalInput& o) { return proposer.draw(o, nullptr).u; }

}  // namespace

TEST_CASE("the cut proposer learns the best angle of a bandit from exact values", "[sac][proposals]") {
  // Two inputs whose best turns differ (u* = 0.6 and -0.5); the value of a draw is -(u - u*)^2,
  // known exactly, as a proposal's Q is. Score-function steps move each mean towards its optimum.
  torch::manual_seed(31);
  SacConfig config = proposing_config(1);
  config.lr_actor = 3e-3;
  CutProposer proposer(config);
  ProposalInput a{}, b{};
  a.fill(0.1f);
  b.fill(-0.2f);
  b[6] = 0.75f;
  const double best_a = 0.6, best_b = -0.5;
  const double before = std::fabs(mean_angle(proposer, a) - best_a) + std::fabs(mean_angle(proposer, b) - best_b);
  std::mt19937_64 rng(7);
  for (int step = 0; step < 600; ++step) {
    std::vector<CutProposer::Sample> samples;
    for (int k = 0; k < 8; ++k) {
      for (const auto& [o, best] : {std::make_pair(&a, best_a), std::make_pair(&b, best_b)}) {
        const CutProposer::Draw d = proposer.draw(*o, &rng);
        samples.push_back({*o, d.z, -(d.u - best) * (d.u - best) + 0.05});  // baseline independent of u
      }
    }
    const auto metrics = proposer.update(samples);
    REQUIRE(std::isfinite(metrics.at("proposal_loss")));
  }
  const double after = std::fabs(mean_angle(proposer, a) - best_a) + std::fabs(mean_angle(proposer, b) - best_b);
  INFO("distance to the best angles: " << before << " before, " << after << " after");
  CHECK(before > 0.5);
  CHECK(after < 0.15);
}

TEST_CASE("the cut proposer's weights survive a save and load, an archive without them is told", "[sac][proposals]") {
  torch::manual_seed(32);
  CutProposer first(proposing_config(2));
  torch::manual_seed(33);
  CutProposer second(proposing_config(2));
  ProposalInput o{};
  o.fill(0.3f);
  REQUIRE(mean_angle(first, o) != mean_angle(second, o));
  std::stringstream bytes;
  {
    torch::serialize::OutputArchive out;
    first.save(out, true);
    out.save_to(bytes);
  }
  torch::serialize::InputArchive in;
  in.load_from(bytes);
  CHECK(second.load(in, true));
  CHECK(mean_angle(first, o) == mean_angle(second, o));
  CHECK(second.temperature() == Approx(first.temperature()));
  std::stringstream empty_bytes;
  {
    torch::serialize::OutputArchive out;
    out.write("something_else", torch::zeros({1}));
    out.save_to(empty_bytes);
  }
  torch::serialize::InputArchive empty;
  empty.load_from(empty_bytes);
  CHECK_FALSE(second.load(empty, false));
  CHECK(mean_angle(first, o) == mean_angle(second, o));  // unchanged
}

TEST_CASE("a checkpoint without the proposal actor is refused by an agent with proposals, as an initial policy it is not",
          "[sac][proposals]") {
  torch::manual_seed(39);
  LookaheadAgent plain(proposing_config(0));
  REQUIRE_FALSE(plain.proposes());
  std::stringstream bytes;
  {
    torch::serialize::OutputArchive out;
    plain.save(out, true);
    out.save_to(bytes);
  }
  torch::manual_seed(40);
  LookaheadAgent proposing(proposing_config(2));
  REQUIRE(proposing.proposes());
  {
    torch::serialize::InputArchive in;
    in.load_from(bytes);
    CHECK_THROWS_WITH(proposing.load(in, true), Catch::Matchers::Contains("holds no proposal actor"));
  }
  bytes.clear();
  bytes.seekg(0);
  torch::serialize::InputArchive in;
  in.load_from(bytes);
  CHECK_NOTHROW(proposing.load(in, false));  // --init: the value network loads, the actor stays as it was
}

TEST_CASE("region_candidate: a listed cut made again gives the listed candidate, no progress gives nothing",
          "[sac][proposals][region]") {
  const auto lock = lock_general_engine();
  const Region part = test::region_of(test::general_polygon(1310, GeneralKind::Polygon, true));
  RegionEpisodeOptions options;
  options.reward = RewardPreset::Mesh;
  options.rules = mesh_block_rules(part.loops());
  const double face_size = part.bbox().longer_side();
  const RegionLookahead look = region_look_ahead(part, face_size, options);
  int cuts = 0;
  for (const RegionCandidate& listed : look.candidates) {
    if (listed.action.kind != RegionAction::Kind::Cut) continue;
    const auto made = region_candidate(part, listed.action, face_size, options);
    REQUIRE(made);
    CHECK(made->reward == Approx(listed.reward));
    CHECK(made->pieces == listed.pieces);
    CHECK(made->blocks == listed.blocks);
    CHECK((made->to_cut == listed.to_cut));
    CHECK(made->vertex == listed.vertex);
    ++cuts;
  }
  CHECK(cuts > 5);
  // A cut along an edge from its vertex (u -> -1 runs along the edge to the next vertex) separates
  // nothing.
  RegionAction along;
  along.cut = cut_of_angle(part, 0, -1.0);
  CHECK_FALSE(region_candidate(part, along, face_size, options));
  RegionAction finish;
  finish.kind = RegionAction::Kind::Template;
  CHECK_FALSE(region_candidate(part, finish, face_size, options));
  // The vertices of the best candidates, distinct, best first, each with its best cut.
  const std::vector<size_t> at = best_at_vertices(look.candidates, 3);
  std::vector<int> vertices;
  for (const size_t k : at) {
    vertices.push_back(look.candidates[k].vertex);
    for (const RegionCandidate& c : look.candidates) {
      if (c.vertex == look.candidates[k].vertex) CHECK(c.reward <= look.candidates[k].reward);
    }
  }
  REQUIRE(vertices.size() == 3);
  CHECK(vertices[0] != vertices[1]);
  CHECK(vertices[1] != vertices[2]);
  CHECK(vertices[0] != vertices[2]);
  double best = -1e300;
  for (const RegionCandidate& c : look.candidates) {
    if (c.vertex >= 0) best = std::max(best, c.reward);
  }
  bool found = false;
  for (const RegionCandidate& c : look.candidates) found = found || (c.vertex == vertices[0] && c.reward == best);
  CHECK(found);
}

TEST_CASE("a lookahead agent with proposals: they are the actor's cuts at the best vertices, deployed among the candidates",
          "[sac][proposals][region]") {
  torch::manual_seed(34);
  auto agent = std::make_shared<LookaheadAgent>(proposing_config(2));
  REQUIRE(agent->proposes());
  const Region face = test::region_of(test::general_polygon(1311, GeneralKind::Polygon, false));
  const double face_size = face.bbox().longer_side();
  const BlockRules rules = mesh_block_rules(face.loops());
  {
    const auto lock = lock_general_engine();
    const auto state = make_region_state(face, agent->region_state_options(face_size, rules));
    const auto proposals = agent->propose_cuts(face, *state, face_size, rules, nullptr);
    const std::vector<size_t> at = best_at_vertices(state->candidates, 2);
    std::vector<int> vertices;
    for (const size_t k : at) vertices.push_back(state->candidates[k].vertex);
    REQUIRE(proposals.size() == vertices.size());
    for (size_t k = 0; k < proposals.size(); ++k) {
      CHECK(proposals[k].vertex == vertices[k]);
      // It turns the best listed cut from its vertex.
      const RegionCandidate& base = state->candidates[proposals[k].base];
      CHECK(base.vertex == vertices[k]);
      for (const RegionCandidate& c : state->candidates) {
        if (c.vertex == vertices[k]) CHECK(c.reward <= base.reward);
      }
      const double u = agent->proposer()->draw(proposals[k].input, nullptr).u;
      CHECK(proposals[k].draw.u == u);
      for (int j = 0; j < kObservationSize; ++j) {
        CHECK(proposals[k].input[static_cast<size_t>(j)] == state->observations[static_cast<size_t>(vertices[k])][static_cast<size_t>(j)]);
      }
      RegionAction action;
      action.cut = turned_cut(base.action.cut, u);
      const double turn = std::atan2(action.cut.direction.y, action.cut.direction.x) -
                          std::atan2(base.action.cut.direction.y, base.action.cut.direction.x);
      CHECK(std::remainder(turn, 2.0 * M_PI) == Approx(u * kProposalTilt).margin(1e-9));
      const auto expected = region_candidate(face, action, face_size, agent->region_state_options(face_size, rules).episode);
      CHECK(proposals[k].candidate.has_value() == expected.has_value());
      if (expected) CHECK(proposals[k].candidate->reward == Approx(expected->reward));
    }
  }
  // Deployed: every face ends in blocks, and the proposals were made and counted.
  deploy_profile() = {};
  {
    const auto lock = lock_general_engine();
    for (int i = 0; i < 4; ++i) {
      RegionLookaheadPolicy policy(agent, "sac-mesh");
      RegionEpisodeOptions options;
      options.reward = RewardPreset::Mesh;
      const Region f = test::region_of(test::general_polygon(1320 + i, GeneralKind::Polygon, i == 3));
      const RegionDecomposition d = decompose_region(f, policy, options);
      CHECK(d.status == EpisodeStatus::Complete);
      CHECK(d.unfinished.empty());
    }
  }
  CHECK(deploy_profile().proposals > 0);
  CHECK(deploy_profile().proposals_progress <= deploy_profile().proposals);
  CHECK(deploy_profile().proposals_chosen <= deploy_profile().proposals_progress);
  // Without proposals the agent has none to make.
  auto plain = std::make_shared<LookaheadAgent>(proposing_config(0));
  CHECK_FALSE(plain->proposes());
}

TEST_CASE("training the proposals alone: the value network stays as it was, the actor learns, seeded runs repeat",
          "[sac][proposals][region]") {
  std::vector<double> losses[2];
  std::vector<double> values[2];
  for (int run = 0; run < 2; ++run) {
    torch::manual_seed(35);
    SacConfig config = proposing_config(2);
    config.learn_value = false;
    config.warmup_steps = 0;
    auto agent = std::make_shared<LookaheadAgent>(config);
    const Region probe = test::region_of(test::general_polygon(1330, GeneralKind::Polygon, false));
    const double probe_size = probe.bbox().longer_side();
    auto value_of_probe = [&] {
      const auto lock = lock_general_engine();
      const auto state = make_region_state(probe, agent->region_state_options(probe_size, mesh_block_rules(probe.loops())));
      return agent->state_values({state.get()})[0];
    };
    const double before = value_of_probe();
    std::mt19937_64 rng(36);
    for (int i = 0; i < 3; ++i) {
      const EpisodeRecord r =
          agent->train_region_episode(test::region_of(test::general_polygon(1331 + i, GeneralKind::Polygon, true)), rng, 200);
      CHECK(r.complete);
      INFO("steps " << r.steps << " metrics " << r.metrics.size());
      REQUIRE(r.metrics.count("proposal_loss"));
      CHECK_FALSE(r.metrics.count("value_loss"));
      losses[run].push_back(r.metrics.at("proposal_loss"));
    }
    CHECK(value_of_probe() == before);
    values[run].push_back(before);
  }
  CHECK(losses[0] == losses[1]);
  CHECK(values[0] == values[1]);
}

TEST_CASE("actor_candidates and learn_value: defaults, files without them, ranges", "[sac][proposals]") {
  const SacConfig defaults = default_sac_config("lookahead");
  CHECK(defaults.actor_candidates == 0);
  CHECK(defaults.learn_value);
  nlohmann::json j = sac_config_json(defaults);
  j.erase("actor_candidates");
  j.erase("learn_value");
  const SacConfig old = sac_config_from_json(j);
  CHECK(old.actor_candidates == 0);
  CHECK(old.learn_value);
  CHECK(with_settings(defaults, {"actor_candidates=3"}).actor_candidates == 3);
  CHECK_FALSE(with_settings(defaults, {"learn_value=false"}).learn_value);
  CHECK_THROWS_AS(with_settings(defaults, {"actor_candidates=9"}), InputError);
  CHECK_THROWS_AS(with_settings(defaults, {"actor_candidates=-1"}), InputError);
}

TEST_CASE("a policy file with proposals rebuilds them, the same decisions after loading", "[sac][proposals][region]") {
  torch::manual_seed(37);
  auto agent = std::make_shared<LookaheadAgent>(proposing_config(2));
  std::mt19937_64 rng(38);
  for (int i = 0; i < 2; ++i) {  // some training, so the actor is not at its initial weights
    agent->train_region_episode(test::region_of(test::general_polygon(1340 + i, GeneralKind::Polygon, true)), rng, 200);
  }
  const std::string path = test::temporary_folder("proposals-file") + "/p.pt";
  save_policy_file(path, *agent, nlohmann::json::object(), false);
  const LoadedPolicy loaded = load_policy_file(path, false);
  auto copy = std::dynamic_pointer_cast<LookaheadAgent>(loaded.agent);
  REQUIRE(copy);
  CHECK(copy->config().actor_candidates == 2);
  REQUIRE(copy->proposes());
  const auto lock = lock_general_engine();
  for (int i = 0; i < 3; ++i) {
    const Region face = test::region_of(test::general_polygon(1350 + i, GeneralKind::Polygon, i == 2));
    RegionEpisodeOptions options;
    options.reward = RewardPreset::Mesh;
    RegionLookaheadPolicy a(agent, "a"), b(copy, "b");
    const RegionDecomposition da = decompose_region(face, a, options), db = decompose_region(face, b, options);
    CHECK(da.total_return == db.total_return);
    CHECK(da.finished.size() == db.finished.size());
  }
}

TEST_CASE("the training log shows the proposal actor's loss and how often its cuts beat the list", "[sac][proposals]") {
  const std::string header = training_csv_header();
  CHECK(header.rfind("episode,", 0) == 0);
  CHECK(header.find(",wall_seconds,proposal_better\n") != std::string::npos);
  EpisodeRecord r;
  r.episode = 3;
  r.shape = "s";
  r.metrics = {{"value_loss", 1.5}, {"proposal_loss", -0.25}, {"proposal_better", 0.125}};
  const std::string row = training_csv_row(r);
  CHECK(row.find(",1.5,,-0.25,") != std::string::npos);  // value, critic (none), actor: the proposal actor's
  CHECK(row.substr(row.size() - 7) == ",0.125\n");
  r.metrics = {{"value_loss", 1.5}};
  const std::string plain = training_csv_row(r);
  CHECK(plain.find(",1.5,,,") != std::string::npos);
  CHECK(plain.substr(plain.size() - 2) == ",\n");
  // Every row has as many columns as the header.
  auto columns = [](const std::string& line) { return std::count(line.begin(), line.end(), ','); };
  CHECK(columns(row) == columns(header));
  CHECK(columns(plain) == columns(header));
}
