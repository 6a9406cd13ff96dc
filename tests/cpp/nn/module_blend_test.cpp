#include "support/catch_torch.h"

#include "core/nn/module_blend.h"

using namespace autoblock;

TEST_CASE("blend_module copies, or moves a fraction of the way, parameters and buffers", "[nn][blend]") {
  torch::manual_seed(3);
  torch::nn::BatchNorm1d source(2), target(2);
  {
    torch::NoGradGuard no_grad;
    source->weight.fill_(3.0);
    source->running_mean.fill_(4.0);
    target->weight.fill_(1.0);
    target->running_mean.fill_(0.0);
  }
  source->num_batches_tracked.fill_(7);

  // A quarter of the way: 0.75 * 1 + 0.25 * 3 = 1.5; buffers copied unless averaged.
  blend_module(*target, *source, 0.25);
  CHECK(target->weight[0].item<double>() == Approx(1.5));
  CHECK(target->running_mean[0].item<double>() == Approx(4.0));
  CHECK(target->num_batches_tracked.item<int64_t>() == 7);

  torch::nn::BatchNorm1d averaged(2);
  {
    torch::NoGradGuard no_grad;
    averaged->weight.fill_(1.0);
    averaged->running_mean.fill_(0.0);
  }
  blend_module(*averaged, *source, 0.25, BufferBlend::Average);
  CHECK(averaged->weight[1].item<double>() == Approx(1.5));
  CHECK(averaged->running_mean[1].item<double>() == Approx(1.0));   // 0.75 * 0 + 0.25 * 4
  CHECK(averaged->num_batches_tracked.item<int64_t>() == 7);        // integers are copied

  // A fraction of 1 is an exact copy, whatever the buffer rule.
  blend_module(*averaged, *source, 1.0, BufferBlend::Average);
  CHECK(torch::equal(averaged->weight, source->weight));
  CHECK(torch::equal(averaged->running_mean, source->running_mean));
  CHECK_FALSE(averaged->weight.grad().defined());
}
