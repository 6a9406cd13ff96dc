#include "core/sac/cut_proposer.h"

#include <algorithm>
#include <cmath>

#include "core/sac/squashed_gaussian.h"

namespace autoblock {

ProposalInput proposal_input(const Observation& observation, Point2 next_edge, Point2 direction) {
  ProposalInput input{};
  std::copy(observation.begin(), observation.end(), input.begin());
  const double angle = std::atan2(direction.y, direction.x) - std::atan2(next_edge.y, next_edge.x);
  input[kObservationSize] = static_cast<float>(std::cos(angle));
  input[kObservationSize + 1] = static_cast<float>(std::sin(angle));
  return input;
}

RegionCut turned_cut(const RegionCut& cut, double u) {
  const double turn = std::clamp(u, -1.0, 1.0) * kProposalTilt;
  RegionCut turned = cut;
  turned.direction = Point2{cut.direction.x * std::cos(turn) - cut.direction.y * std::sin(turn),
                            cut.direction.x * std::sin(turn) + cut.direction.y * std::cos(turn)};
  turned.forced = false;
  return turned;
}

CutProposer::CutProposer(const SacConfig& config)
    : config_(config), actor_(Mlp(int64_t{kProposalInputs}, std::vector<int64_t>{128, 64}, int64_t{2}, false)) {
  log_alpha_ = torch::full({1}, std::log(config.initial_direction_temperature), torch::requires_grad());
  actor_optimizer_ = std::make_unique<torch::optim::Adam>(actor_->parameters(), torch::optim::AdamOptions(config.lr_actor));
  temperature_optimizer_ =
      std::make_unique<torch::optim::Adam>(std::vector<torch::Tensor>{log_alpha_}, torch::optim::AdamOptions(config.lr_temperature));
}

double CutProposer::temperature() const { return std::exp(log_alpha_.item<double>()); }

CutProposer::Draw CutProposer::draw(const ProposalInput& input, std::mt19937_64* rng) {
  return draw(std::vector<const ProposalInput*>{&input}, rng).front();
}

std::vector<CutProposer::Draw> CutProposer::draw(const std::vector<const ProposalInput*>& inputs, std::mt19937_64* rng) {
  std::vector<Draw> draws;
  if (inputs.empty()) return draws;
  torch::NoGradGuard no_grad;
  actor_->eval();
  const torch::Tensor out = actor_->forward(stack_rows(inputs)).contiguous();
  const float* data = out.data_ptr<float>();
  for (size_t k = 0; k < inputs.size(); ++k) {
    Draw d;
    d.z = data[2 * k];
    if (rng) {
      const double log_std = std::clamp(static_cast<double>(data[2 * k + 1]), kLogStdMin, kLogStdMax);
      // From the caller's generator, not torch's: seeded runs repeat exactly.
      d.z += std::exp(log_std) * std::normal_distribution<double>(0.0, 1.0)(*rng);
    }
    d.u = std::tanh(d.z);
    draws.push_back(d);
  }
  return draws;
}

std::map<std::string, double> CutProposer::update(const std::vector<Sample>& samples) {
  std::vector<const ProposalInput*> inputs;
  std::vector<float> z, advantage;
  for (const Sample& s : samples) {
    inputs.push_back(&s.input);
    z.push_back(static_cast<float>(s.z));
    advantage.push_back(static_cast<float>(s.advantage));
  }
  actor_->train();
  const torch::Tensor out = actor_->forward(stack_rows(inputs));
  const torch::Tensor mu = out.select(1, 0);
  const torch::Tensor log_std = clamped_log_std(out);
  const torch::Tensor zt = torch::tensor(z);
  const torch::Tensor u = torch::tanh(zt);
  const torch::Tensor logp = squashed_log_density((zt - mu) / log_std.exp(), log_std, u);
  const double alpha = temperature();
  const torch::Tensor weight = (torch::tensor(advantage) - alpha * logp).detach();
  const torch::Tensor loss = -(weight * logp).mean();
  actor_optimizer_->zero_grad();
  loss.backward();
  torch::nn::utils::clip_grad_norm_(actor_->parameters(), 10.0);
  actor_optimizer_->step();

  const torch::Tensor entropy = -logp.detach().mean();
  const torch::Tensor temperature_loss = log_alpha_ * (entropy - config_.angle_target_entropy);
  temperature_optimizer_->zero_grad();
  temperature_loss.backward();
  temperature_optimizer_->step();
  return {{"proposal_loss", loss.item<double>()},
          {"proposal_alpha", temperature()},
          {"proposal_entropy", entropy.item<double>()},
          {"proposal_advantage", torch::tensor(advantage).mean().item<double>()}};
}

void CutProposer::save(torch::serialize::OutputArchive& archive, bool training) const {
  torch::serialize::OutputArchive actor;
  actor_->save(actor);
  archive.write("proposal_actor", actor);
  archive.write("proposal_log_alpha", log_alpha_.detach());
  if (!training) return;
  torch::serialize::OutputArchive actor_optimizer, temperature_optimizer;
  actor_optimizer_->save(actor_optimizer);
  archive.write("proposal_optimizer", actor_optimizer);
  temperature_optimizer_->save(temperature_optimizer);
  archive.write("proposal_temperature_optimizer", temperature_optimizer);
}

bool CutProposer::load(torch::serialize::InputArchive& archive, bool training) {
  torch::serialize::InputArchive actor;
  if (!archive.try_read("proposal_actor", actor)) return false;
  actor_->load(actor);
  torch::Tensor log_alpha;
  archive.read("proposal_log_alpha", log_alpha);
  {
    torch::NoGradGuard no_grad;
    log_alpha_.copy_(log_alpha);
  }
  if (!training) return true;
  torch::serialize::InputArchive actor_optimizer, temperature_optimizer;
  archive.read("proposal_optimizer", actor_optimizer);
  actor_optimizer_->load(actor_optimizer);
  archive.read("proposal_temperature_optimizer", temperature_optimizer);
  temperature_optimizer_->load(temperature_optimizer);
  return true;
}

}  // namespace autoblock
