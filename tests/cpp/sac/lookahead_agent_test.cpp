#include "support/catch_torch.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/data/thin_features.h"
#include "core/env/decomposition.h"
#include "core/geometry/part_boundary.h"
#include "core/geometry/part_symmetry.h"
#include "core/sac/deploy_profile.h"
#include "core/sac/lookahead_agent.h"
#include "core/sac/policy_file.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("the lookahead agent's target is the soft maximum over the cuts, by hand", "[sac][lookahead]") {
  // The U-shape has three splitting cuts: y = 1 (three rectangles, no pieces left), x = 1 and
  // x = 2 (a rectangle and an L each, mirror images). With W the (untrained) network's values:
  //   Q(y = 1) = 9.8364021603, Q(x = k) = 5.5811388301 + W(L_k)
  //   y = alpha * log(sum over the cuts of exp(Q / alpha))   (gamma = 1)
  torch::manual_seed(4);
  auto agent = std::make_shared<LookaheadAgent>(default_sac_config("lookahead"));
  const GridFace u = test::grid_face_of({{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  const auto state = make_part_state(u.whole, agent->state_options(u.size));
  REQUIRE(state->lines.size() == 3);
  const std::vector<double> q = agent->cut_values(*state, u.size);
  int rectangles_only = 0;
  for (size_t k = 0; k < state->lines.size(); ++k) {
    if (state->lines[k].to_cut.empty()) {
      ++rectangles_only;
      CHECK(q[k] == Approx(9.8364021603));
    } else {
      REQUIRE(state->lines[k].to_cut.size() == 1);
      const auto l = make_part_state(state->lines[k].to_cut[0], agent->state_options(u.size));
      CHECK(q[k] == Approx(5.5811388301 + agent->state_values({l.get()})[0]));
    }
  }
  CHECK(rectangles_only == 1);
  const double alpha = agent->temperature();
  double sum = 0;
  for (double v : q) sum += std::exp(v / alpha);
  const double expected = alpha * std::log(sum);
  agent->remember(u.whole, u.size, 0);
  std::mt19937_64 rng(1);
  const auto metrics = agent->update(1, rng);
  CHECK(metrics.at("mean_target") == Approx(expected).epsilon(1e-5));
  CHECK(std::isfinite(metrics.at("value_loss")));
}

TEST_CASE("trained on a part in all eight symmetries, the value network agrees across them", "[sac][lookahead]") {
  // Regressing one part's value, presented in all eight symmetries, brings every presentation's
  // value to about the same number: the augmentation teaches the network the invariance.
  torch::manual_seed(5);
  SacConfig config = default_sac_config("lookahead");
  auto agent = std::make_shared<LookaheadAgent>(config);
  const GridFace u = test::grid_face_of({{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  for (int s = 0; s < 8; ++s) agent->remember(u.whole, u.size, s);
  std::mt19937_64 rng(2);
  double target = 0;
  for (int k = 0; k < 500; ++k) target = agent->update(8, rng).at("mean_target");
  std::vector<std::shared_ptr<const PartState>> shown;
  std::vector<const PartState*> raw;
  for (int s = 0; s < 8; ++s) {
    shown.push_back(make_part_state(transform_part(u.whole, s), agent->state_options(u.size)));
    raw.push_back(shown.back().get());
  }
  const std::vector<double> w = agent->state_values(raw);
  double mean = 0;
  for (double v : w) mean += v / 8;
  for (double v : w) CHECK(v == Approx(mean).margin(1.5));
  // ... and it learnt something: the untrained network's values are near 0, the U's targets above 9.8.
  CHECK(mean > 0.5 * target);
  CHECK(target > 9.8);
}

TEST_CASE("an averaging agent deploys the moving average of its weights, and files keep both", "[sac][lookahead][policy]") {
  torch::manual_seed(6);
  SacConfig config = default_sac_config("lookahead");
  config.weight_average_decay = 0.9;
  auto agent = std::make_shared<LookaheadAgent>(config);
  const GridFace u = test::grid_face_of({{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  const GridFace l = test::grid_face_of({{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}});
  const auto su = make_part_state(u.whole, agent->state_options(u.size));
  const auto sl = make_part_state(l.whole, agent->state_options(l.size));
  const std::vector<const PartState*> states{su.get(), sl.get()};
  // Before any update the average is the trained network.
  CHECK(agent->deployed_values(states) == agent->state_values(states));
  agent->remember(u.whole, u.size, 0);
  agent->remember(l.whole, l.size, 3);
  std::mt19937_64 rng(3);
  for (int k = 0; k < 20; ++k) agent->update(2, rng);
  // The trained network moved; the average lags behind it.
  const std::vector<double> trained = agent->state_values(states), deployed = agent->deployed_values(states);
  CHECK(trained != deployed);

  // A policy file holds the deployed (averaged) network; a checkpoint also the trained one.
  const std::string folder = test::temporary_folder("average");
  save_policy_file(folder + "/p.pt", *agent, nlohmann::json::object(), false);
  save_policy_file(folder + "/p.pt.checkpoint", *agent, nlohmann::json::object(), true);
  auto policy = std::static_pointer_cast<LookaheadAgent>(load_policy_file(folder + "/p.pt", false).agent);
  CHECK(policy->deployed_values(states) == deployed);
  CHECK(policy->state_values(states) == deployed);
  auto checkpoint = std::static_pointer_cast<LookaheadAgent>(load_policy_file(folder + "/p.pt.checkpoint", true).agent);
  CHECK(checkpoint->deployed_values(states) == deployed);
  CHECK(checkpoint->state_values(states) == trained);
  CHECK(checkpoint->config().weight_average_decay == 0.9);
}

TEST_CASE("the learning rate falls along a half cosine to its final fraction", "[sac][lookahead]") {
  SacConfig config = default_sac_config("lookahead");
  config.lr_value = 2e-3;
  config.lr_final_fraction = 0.1;
  auto agent = std::make_shared<LookaheadAgent>(config);
  CHECK(agent->learning_rate() == Approx(2e-3));
  agent->set_training_progress(0.5);  // halfway: the mean of the two ends
  CHECK(agent->learning_rate() == Approx(2e-3 * (0.1 + 0.9 * 0.5)));
  agent->set_training_progress(0.25);  // 0.1 + 0.9 (1 + cos(pi / 4)) / 2 = 0.8681980515
  CHECK(agent->learning_rate() == Approx(2e-3 * 0.8681980515));
  agent->set_training_progress(1.0);
  CHECK(agent->learning_rate() == Approx(2e-4));
  // The default schedule is constant.
  auto constant = std::make_shared<LookaheadAgent>(default_sac_config("lookahead"));
  constant->set_training_progress(0.7);
  CHECK(constant->learning_rate() == Approx(default_sac_config("lookahead").lr_value));
}

TEST_CASE("a batched forward equals the unbatched one", "[sac][lookahead]") {
  // The deployed network (evaluation mode: batch norm uses its running statistics) values each
  // graph of a batch as it values it alone.
  torch::manual_seed(6);
  auto agent = std::make_shared<LookaheadAgent>(default_sac_config("lookahead"));
  const GeneratorOptions options = thin_feature_options(2, 10);
  std::vector<std::shared_ptr<const PartState>> states;
  std::vector<const PartState*> raw;
  for (const GeneratedShape& shape : test::generated_shapes(12, 8, options)) {
    const GridFace face = make_grid_face(shape.polygon);
    states.push_back(make_part_state(face.whole, agent->state_options(face.size)));
    raw.push_back(states.back().get());
  }
  const std::vector<double> together = agent->deployed_values(raw);
  REQUIRE(together.size() == raw.size());
  for (size_t k = 0; k < raw.size(); ++k) {
    const double alone = agent->deployed_values({raw[k]})[0];
    CHECK(together[k] == Approx(alone).epsilon(1e-5).margin(1e-5));
  }
}

TEST_CASE("the deployed policy's cached values are what a fresh evaluation gives", "[sac][lookahead][policy]") {
  // Along whole decompositions, the policy that keeps states and piece values from earlier steps
  // scores every cut as a fresh policy (empty caches) does, and it does reuse values.
  torch::manual_seed(7);
  auto agent = std::make_shared<LookaheadAgent>(default_sac_config("lookahead"));
  const GeneratorOptions options = thin_feature_options(6, 10);
  long reused = 0;
  for (const GeneratedShape& shape : test::generated_shapes(4, 9, options)) {
    const GridFace face = make_grid_face(shape.polygon);
    // Reuse across steps, by a policy that only chooses.
    LookaheadPolicy plain(agent, "plain");
    deploy_profile() = {};
    decompose_face(face, plain);
    reused += deploy_profile().values_reused;

    LookaheadPolicy cached(agent, "cached");
    Episode episode(face);
    while (episode.running()) {
      const auto state = cached.state_of(episode.current_part(), face.size);
      const std::vector<double> q = cached.values(*state, face.size);
      LookaheadPolicy fresh(agent, "fresh");
      const std::vector<double> expected = fresh.values(*fresh.state_of(episode.current_part(), face.size), face.size);
      REQUIRE(q.size() == expected.size());
      for (size_t k = 0; k < q.size(); ++k) {
        if (std::isinf(expected[k])) {
          CHECK(q[k] == expected[k]);  // a cut the default deployment prunes
        } else {
          CHECK(q[k] == Approx(expected[k]).epsilon(1e-5).margin(1e-5));
        }
      }
      episode.step(cached.choose(episode));
    }
  }
  CHECK(reused > 0);
}

namespace {

// A copy of agent's network deployed with deploy_top_k = k (the same weights: a policy file's
// round trip is not needed, the agents share nothing but the configuration).
std::shared_ptr<LookaheadAgent> with_top_k(const std::shared_ptr<LookaheadAgent>& agent, int k) {
  auto copy = std::make_shared<LookaheadAgent>(agent->config());
  torch::serialize::OutputArchive out;
  agent->save(out, false);
  std::ostringstream bytes;
  out.save_to(bytes);
  torch::serialize::InputArchive in;
  std::istringstream read(bytes.str());
  in.load_from(read);
  copy->load(in, false);
  copy->set_deploy_top_k(k);
  return copy;
}

}  // namespace

TEST_CASE("pruning with k at least the number of cuts decides as the unpruned policy", "[sac][lookahead][policy]") {
  torch::manual_seed(8);
  auto agent = std::make_shared<LookaheadAgent>(default_sac_config("lookahead"));
  agent->set_deploy_top_k(0);
  const GeneratorOptions options = thin_feature_options(6, 10);
  for (const GeneratedShape& shape : test::generated_shapes(4, 10, options)) {
    const GridFace face = make_grid_face(shape.polygon);
    LookaheadPolicy all(agent, "all");
    const Decomposition unpruned = decompose_face(face, all);
    LookaheadPolicy probe(agent, "probe");
    const size_t cuts = probe.state_of(face.whole, face.size)->lines.size();
    for (const int k : {static_cast<int>(cuts), 1000}) {
      LookaheadPolicy pruned(with_top_k(agent, k), "pruned");
      const Decomposition d = decompose_face(face, pruned);
      REQUIRE(d.cuts.size() == unpruned.cuts.size());
      for (size_t c = 0; c < d.cuts.size(); ++c) {
        CHECK(d.cuts[c].vertex.i == unpruned.cuts[c].vertex.i);
        CHECK(d.cuts[c].vertex.j == unpruned.cuts[c].vertex.j);
        CHECK(d.cuts[c].direction == unpruned.cuts[c].direction);
      }
      CHECK(d.total_return == unpruned.total_return);
    }
  }
}

TEST_CASE("a pruned policy values the k best cuts by the two-step score and picks the best of them",
          "[sac][lookahead][policy]") {
  torch::manual_seed(9);
  auto agent = std::make_shared<LookaheadAgent>(default_sac_config("lookahead"));
  agent->set_deploy_top_k(0);
  const int k = 2;
  auto pruned_agent = with_top_k(agent, k);
  const GeneratorOptions options = thin_feature_options(6, 10);
  int steps = 0, pruned_steps = 0;
  for (const GeneratedShape& shape : test::generated_shapes(4, 11, options)) {
    const GridFace face = make_grid_face(shape.polygon);
    LookaheadPolicy pruned(pruned_agent, "pruned");
    Episode episode(face);
    while (episode.running()) {
      const auto state = pruned.state_of(episode.current_part(), face.size);
      const std::vector<size_t> shortlist = pruned.shortlist(*state, face.size);
      const std::vector<double> q = pruned.values(*state, face.size);
      LookaheadPolicy fresh(agent, "fresh");  // unpruned, empty caches
      const std::vector<double> full = fresh.values(*fresh.state_of(episode.current_part(), face.size), face.size);
      REQUIRE(q.size() == full.size());
      REQUIRE(shortlist.size() == std::min<size_t>(k, q.size()));
      // The two-step score, by hand: reward + sum over the pieces of their best one-cut reward
      // times max(1, (reflex corners + 1) / 2).
      std::vector<double> score;
      for (const LineCandidate& line : state->lines) {
        double s = line.reward;
        for (const Part& piece : line.to_cut) {
          const std::vector<CornerRing> loops = part_boundary(piece);
          double best = -std::numeric_limits<double>::infinity();
          for (const LineCandidate& next : look_ahead(piece, loops, face.size, RewardPreset::Paper).lines) {
            best = std::max(best, next.reward);
          }
          int reflex = 0;
          for (const CornerRing& loop : loops) {
            for (const auto& corner : loop) reflex += corner.reflex;
          }
          s += agent->config().gamma * best * std::max(1.0, 0.5 * (reflex + 1));
        }
        score.push_back(s);
      }
      size_t best = shortlist.front();
      for (size_t l = 0; l < q.size(); ++l) {
        const bool listed = std::find(shortlist.begin(), shortlist.end(), l) != shortlist.end();
        if (!listed) {
          CHECK(q[l] == -std::numeric_limits<double>::infinity());
          for (const size_t s : shortlist) CHECK(score[s] >= score[l]);
          continue;
        }
        CHECK(q[l] == Approx(full[l]).epsilon(1e-5).margin(1e-5));  // the cache stays exact
        if (q[l] > q[best]) best = l;
      }
      const Action chosen = pruned.choose(episode);
      CHECK(chosen.vertex == state->lines[best].vertex);
      CHECK(chosen.direction == state->lines[best].line.direction);
      episode.step(chosen);
      ++steps;
      pruned_steps += q.size() > shortlist.size();
    }
  }
  CHECK(steps > 8);
  CHECK(pruned_steps > 4);
}

TEST_CASE("the training caches keep a grid part's state apart per face size", "[sac][lookahead]") {
  // The same cells in faces of two sizes: the pieces' states (lookahead rewards, scale features)
  // differ, so an agent that met the part in the small face first must value it in the large one as
  // an agent that never met it does.
  const GridFace u = test::grid_face_of({{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  const double small = u.size, large = 4.0 * u.size;
  torch::manual_seed(5);
  auto seen = std::make_shared<LookaheadAgent>(default_sac_config("lookahead"));
  torch::manual_seed(5);
  auto fresh = std::make_shared<LookaheadAgent>(default_sac_config("lookahead"));
  const auto at_small = make_part_state(u.whole, seen->state_options(small));
  const auto at_large = make_part_state(u.whole, seen->state_options(large));
  const std::vector<double> q_small = seen->cut_values(*at_small, small);
  const std::vector<double> q_large = seen->cut_values(*at_large, large);
  CHECK((q_large == fresh->cut_values(*at_large, large)));
  CHECK(q_large != q_small);
}
