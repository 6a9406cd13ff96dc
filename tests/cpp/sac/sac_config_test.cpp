#include "support/catch_torch.h"

#include "core/common/error.h"
#include "core/sac/sac_config.h"

#include <string>
#include <vector>

using namespace autoblock;
using Catch::Matchers::Contains;

TEST_CASE("the deployment options round-trip, default for older files and are checked", "[sac][config]") {
  SacConfig config = default_sac_config("lookahead");
  CHECK(config.weight_average_decay == 0.998);
  CHECK(config.deploy_views == 2);
  CHECK(config.lr_final_fraction == 1.0);
  CHECK(config.deploy_top_k == 6);
  CHECK(default_sac_config("paper").deploy_views == 1);
  CHECK(default_sac_config("paper").deploy_top_k == 0);
  config.lr_final_fraction = 0.25;
  config.deploy_top_k = 5;
  const SacConfig back = sac_config_from_json(sac_config_json(config));
  CHECK(back.weight_average_decay == 0.998);
  CHECK(back.deploy_views == 2);
  CHECK(back.lr_final_fraction == 0.25);
  CHECK(back.deploy_top_k == 5);

  // A file written before these options existed deploys as it was trained: no average, one view,
  // constant learning rate, every cut valued.
  nlohmann::json old = sac_config_json(config);
  old.erase("deploy_top_k");
  old.erase("weight_average_decay");
  old.erase("deploy_views");
  old.erase("lr_final_fraction");
  const SacConfig legacy = sac_config_from_json(old);
  CHECK(legacy.weight_average_decay == 0.0);
  CHECK(legacy.deploy_views == 1);
  CHECK(legacy.lr_final_fraction == 1.0);
  CHECK(legacy.deploy_top_k == 0);

  for (const auto& [key, value] : std::vector<std::pair<std::string, nlohmann::json>>{
           {"deploy_views", 0}, {"deploy_views", 9}, {"weight_average_decay", 1.0}, {"weight_average_decay", -0.1},
           {"lr_final_fraction", 0.0}, {"lr_final_fraction", 1.5}, {"deploy_top_k", -1}}) {
    nlohmann::json bad = sac_config_json(config);
    bad[key] = value;
    INFO(key << " = " << value);
    CHECK_THROWS_AS(sac_config_from_json(bad), InputError);
    CHECK_THROWS_WITH(sac_config_from_json(bad), Contains(key));
  }
}

TEST_CASE("the graph method round-trips, is refined for older files and is checked", "[sac][config]") {
  SacConfig config = default_sac_config("lookahead");
  CHECK(config.graph.method == GraphMethod::Bounded);  // new policies learn on bounded graphs
  CHECK(sac_config_from_json(sac_config_json(config)).graph.method == GraphMethod::Bounded);
  config.graph.method = GraphMethod::Refined;
  CHECK(sac_config_from_json(sac_config_json(config)).graph.method == GraphMethod::Refined);
  // A file written before issue 8 names no method: its network learned on refined graphs.
  nlohmann::json old = sac_config_json(default_sac_config("lookahead"));
  old["graph"].erase("method");
  CHECK(sac_config_from_json(old).graph.method == GraphMethod::Refined);
  nlohmann::json bad = sac_config_json(default_sac_config("lookahead"));
  bad["graph"]["method"] = "fine";
  CHECK_THROWS_AS(sac_config_from_json(bad), InputError);
  CHECK_THROWS_WITH(sac_config_from_json(bad), Contains("graph method"));
}

TEST_CASE("settings change named fields of the configuration and are checked", "[sac][config]") {
  const SacConfig base = default_sac_config("paper");
  const SacConfig changed = with_settings(base, {"initial_direction_temperature=2.5", "actor_output_relu=false",
                                                 "bootstrap=critics", "graph.size_fraction=0.5", "gamma=1"});
  CHECK(changed.initial_direction_temperature == 2.5);
  CHECK_FALSE(changed.actor_output_relu);
  CHECK(changed.bootstrap == Bootstrap::Critics);
  CHECK(changed.graph.size_fraction == 0.5);
  CHECK(changed.gamma == 1.0);
  // Everything else is left as it was.
  nlohmann::json expected = sac_config_json(base);
  expected["initial_direction_temperature"] = 2.5;
  expected["actor_output_relu"] = false;
  expected["bootstrap"] = "critics";
  expected["graph"]["size_fraction"] = 0.5;
  expected["gamma"] = 1.0;
  CHECK(sac_config_json(changed) == expected);
  // Later settings win.
  CHECK(with_settings(base, {"batch_size=8", "batch_size=16"}).batch_size == 16);

  for (const std::string bad : {"gamma", "=1", "gamma=", "no_such_field=1", "graph.no_such=1", "gamma.x=1", "graph=1",
                                "agent=lookahead", "gamma=1.5", "gamma=0", "batch_size=0", "lr_actor=-1",
                                "actor_output_relu=3", "bootstrap=sideways", "initial_vertex_temperature=0"}) {
    INFO(bad);
    CHECK_THROWS_AS(with_settings(base, {bad}), InputError);
    CHECK_THROWS_WITH(with_settings(base, {bad}), Contains(bad));
  }
}
