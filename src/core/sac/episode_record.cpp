#include "core/sac/episode_record.h"

namespace autoblock {

namespace {

EpisodeRecord record_of(double ret, int blocks, int steps, EpisodeStatus status,
                        const std::map<std::string, double>& metric_sums, int updates) {
  EpisodeRecord record;
  record.ret = ret;
  record.blocks = blocks;
  record.steps = steps;
  record.complete = status == EpisodeStatus::Complete;
  for (const auto& [name, sum] : metric_sums) record.metrics[name] = sum / updates;
  return record;
}

}  // namespace

EpisodeRecord episode_record_of(const Episode& episode, const std::map<std::string, double>& metric_sums, int updates) {
  return record_of(episode.total_return(), static_cast<int>(episode.blocks().size()), episode.steps(), episode.status(),
                   metric_sums, updates);
}

EpisodeRecord region_episode_record_of(const RegionEpisode& episode, const std::map<std::string, double>& metric_sums,
                                       int updates) {
  return record_of(episode.total_return(), static_cast<int>(episode.finished().size()), episode.steps(), episode.status(),
                   metric_sums, updates);
}

nlohmann::json episode_record_json(const EpisodeRecord& r) {
  nlohmann::json j = {{"episode", r.episode}, {"shape", r.shape},   {"return", r.ret},
                      {"blocks", r.blocks},   {"steps", r.steps},   {"complete", r.complete},
                      {"metrics", r.metrics}, {"alpha", r.alpha},   {"tau", r.tau},
                      {"evaluated", r.evaluated}, {"test_return", r.test_return}, {"wall_seconds", r.wall_seconds}};
  return j;
}

EpisodeRecord episode_record_from_json(const nlohmann::json& j) {
  EpisodeRecord r;
  r.episode = j.at("episode").get<int>();
  r.shape = j.at("shape").get<std::string>();
  r.ret = j.at("return").get<double>();
  r.blocks = j.at("blocks").get<int>();
  r.steps = j.at("steps").get<int>();
  r.complete = j.at("complete").get<bool>();
  r.metrics = j.at("metrics").get<std::map<std::string, double>>();
  r.alpha = j.at("alpha").get<double>();
  r.tau = j.at("tau").get<double>();
  r.evaluated = j.at("evaluated").get<bool>();
  r.test_return = j.at("test_return").get<double>();
  r.wall_seconds = j.at("wall_seconds").get<double>();
  return r;
}

}  // namespace autoblock
