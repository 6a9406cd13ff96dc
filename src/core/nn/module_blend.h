// Moving one network's weights towards another's: hard copies and Polyak / moving averages
// (target networks, averaged weights for deployment).
#pragma once

#include <torch/torch.h>

namespace autoblock {

// How a blend treats buffers (batch norm's running statistics and counters).
enum class BufferBlend { Copy, Average };

// Inputs:  target and source, modules of the same architecture; fraction in (0, 1]: each parameter
//          becomes (1 - fraction) target + fraction source (1: a copy); buffers: Copy takes the
//          source's buffers as they are, Average blends the floating-point ones like the parameters
//          (integer buffers are copied).
// Outputs: target, changed in place (no gradient recorded).
void blend_module(torch::nn::Module& target, const torch::nn::Module& source, double fraction,
                  BufferBlend buffers = BufferBlend::Copy);

}  // namespace autoblock
