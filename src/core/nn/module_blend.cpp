#include "core/nn/module_blend.h"

namespace autoblock {

void blend_module(torch::nn::Module& target, const torch::nn::Module& source, double fraction, BufferBlend buffers) {
  torch::NoGradGuard no_grad;
  const bool copy = fraction >= 1.0;
  const auto source_parameters = source.named_parameters(true);
  for (auto& item : target.named_parameters(true)) {
    const torch::Tensor& s = source_parameters[item.key()];
    if (copy) {
      item.value().copy_(s);
    } else {
      item.value().mul_(1.0 - fraction).add_(s, fraction);
    }
  }
  const auto source_buffers = source.named_buffers(true);
  for (auto& item : target.named_buffers(true)) {
    const torch::Tensor& s = source_buffers[item.key()];
    if (!copy && buffers == BufferBlend::Average && item.value().is_floating_point()) {
      item.value().mul_(1.0 - fraction).add_(s, fraction);
    } else {
      item.value().copy_(s);
    }
  }
}

}  // namespace autoblock
