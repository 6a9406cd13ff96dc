// The thin-feature kind of generated faces (issue 8): rectangle unions drawn on a bounded grid with
// long sides, so that features one grid unit wide are common (a 1:32 strip is typical). Up to 10
// rectangles: a 32 x 32 grid with sides 3-18; more: a 64 x 64 grid with sides 4-24.
#pragma once

#include "core/data/shape_generator.h"

namespace autoblock {

// Inputs:  min_rects <= max_rects; holes. Output: generator options of the thin-feature kind.
inline GeneratorOptions thin_feature_options(int min_rects, int max_rects, bool holes = false) {
  GeneratorOptions options;
  options.min_rects = min_rects;
  options.max_rects = max_rects;
  options.holes = holes;
  const bool small = max_rects <= 10;
  options.grid = small ? 32 : 64;
  options.min_side = small ? 3 : 4;
  options.max_side = small ? 18 : 24;
  return options;
}

// Inputs: as above; thin. Output: thin_feature_options when thin, else today's default kind with
//         that many rectangles.
inline GeneratorOptions generator_kind_options(bool thin, int min_rects, int max_rects, bool holes = false) {
  if (thin) return thin_feature_options(min_rects, max_rects, holes);
  GeneratorOptions options;
  options.min_rects = min_rects;
  options.max_rects = max_rects;
  options.holes = holes;
  return options;
}

}  // namespace autoblock
