#include "core/sac/training_curves.h"

#include <cstdio>

namespace autoblock {

TrainingSpeed training_speed(const std::vector<EpisodeRecord>& history) {
  TrainingSpeed speed;
  std::vector<const EpisodeRecord*> evaluated;
  for (const EpisodeRecord& r : history) {
    if (r.evaluated) evaluated.push_back(&r);
  }
  if (evaluated.empty()) return speed;
  const size_t tail = std::min<size_t>(3, evaluated.size());
  for (size_t k = evaluated.size() - tail; k < evaluated.size(); ++k) speed.final_test_return += evaluated[k]->test_return;
  speed.final_test_return /= static_cast<double>(tail);
  speed.initial_test_return = evaluated.front()->test_return;
  double mark;
  if (speed.final_test_return > 0) {
    mark = 0.95 * speed.final_test_return;
    speed.rule = "0.95 x final test return (mean of the last 3 evaluations)";
  } else {
    mark = speed.initial_test_return + 0.95 * (speed.final_test_return - speed.initial_test_return);
    speed.rule = "first evaluation + 0.95 x (final - first), final = mean of the last 3 evaluations";
  }
  for (const EpisodeRecord* r : evaluated) {
    if (r->test_return >= mark) {
      speed.episodes_to_95 = r->episode;
      speed.seconds_to_95 = r->wall_seconds;
      break;
    }
  }
  return speed;
}

std::string training_curves_svg(const std::vector<EpisodeRecord>& history, const std::vector<ChartReference>& references,
                                const std::string& title) {
  ChartPanel train{"Training episodes: return, moving average over 10", "episode", "return", {}, {}};
  ChartPanel test{"Test set: mean deterministic return", "episode", "return", {}, references};
  ChartSeries average{"training (10-episode average)", "#1f77b4", {}};
  ChartSeries raw{"training episode", "#c6dbef", {}};
  ChartSeries tested{"test", "#d62728", {}};
  double window = 0.0;
  for (size_t k = 0; k < history.size(); ++k) {
    window += history[k].ret;
    if (k >= 10) window -= history[k - 10].ret;
    const double n = static_cast<double>(std::min<size_t>(k + 1, 10));
    raw.points.emplace_back(history[k].episode, history[k].ret);
    average.points.emplace_back(history[k].episode, window / n);
    if (history[k].evaluated) tested.points.emplace_back(history[k].episode, history[k].test_return);
  }
  train.series = {raw, average};
  test.series = {tested};
  return line_chart_svg({train, test}, title);
}

std::string training_csv_header() {
  return "episode,shape,return,blocks,steps,complete,value_loss,critic_loss,actor_loss,alpha,tau,test_return,wall_seconds,"
         "proposal_better\n";
}

std::string training_csv_row(const EpisodeRecord& r) {
  auto metric = [&r](const char* name) {
    const auto found = r.metrics.find(name);
    if (found == r.metrics.end()) return std::string();
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", found->second);
    return std::string(buf);
  };
  char head[256];
  std::snprintf(head, sizeof head, "%d,%s,%.6f,%d,%d,%d,", r.episode, r.shape.c_str(), r.ret, r.blocks, r.steps,
                r.complete ? 1 : 0);
  char tail[128];
  std::snprintf(tail, sizeof tail, "%.6g,%.6g,", r.alpha, r.tau);
  std::string test;
  if (r.evaluated) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6f", r.test_return);
    test = buf;
  }
  char wall[32];
  std::snprintf(wall, sizeof wall, "%.3f", r.wall_seconds);
  // The lookahead agent has no actor of its own: with actor-proposed cuts (cut_proposer.h) the actor
  // column holds its proposal actor's loss, and the last column the share of turned cuts that beat
  // the listed ones.
  const std::string actor = r.metrics.count("actor_loss") ? metric("actor_loss") : metric("proposal_loss");
  return std::string(head) + metric("value_loss") + "," + metric("critic_loss") + "," + actor + "," + tail + test + "," +
         wall + "," + metric("proposal_better") + "\n";
}

}  // namespace autoblock
