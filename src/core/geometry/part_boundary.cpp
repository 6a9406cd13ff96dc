#include "core/geometry/part_boundary.h"

#include <stdexcept>

namespace autoblock {
namespace {

// Directions: 0 = +x, 1 = +y, 2 = -x, 3 = -y (counter-clockwise order).
constexpr int kDx[4] = {1, 0, -1, 0};
constexpr int kDy[4] = {0, 1, 0, -1};

}  // namespace

std::vector<CornerRing> part_boundary(const Part& part) {
  const int w = part.width_cells(), h = part.height_cells();
  const int i0 = part.i0(), j0 = part.j0();
  const int pw = w + 1;  // grid points per row of the window
  std::vector<signed char> out(static_cast<size_t>(pw * (h + 1)), -1);
  auto set_out = [&](int a, int b, int dir) {
    signed char& slot = out[static_cast<size_t>(b * pw + a)];
    if (slot != -1) throw std::logic_error("part_boundary: the boundary touches itself");
    slot = static_cast<signed char>(dir);
  };
  // Boundary edges between a part cell and a non-part cell, directed with the part on the left.
  for (int b = 0; b < h; ++b) {
    for (int a = 0; a < w; ++a) {
      const int i = i0 + a, j = j0 + b;
      if (!part.contains(i, j)) continue;
      if (!part.contains(i, j - 1)) set_out(a, b, 0);
      if (!part.contains(i + 1, j)) set_out(a + 1, b, 1);
      if (!part.contains(i, j + 1)) set_out(a + 1, b + 1, 2);
      if (!part.contains(i - 1, j)) set_out(a, b + 1, 3);
    }
  }
  std::vector<CornerRing> rings;
  std::vector<char> visited(out.size(), 0);
  for (int b = 0; b <= h; ++b) {
    for (int a = 0; a <= w; ++a) {
      const size_t start = static_cast<size_t>(b * pw + a);
      if (out[start] == -1 || visited[start]) continue;
      // The scan meets each loop first at its lowest-leftmost point, a corner. The outer loop
      // (counter-clockwise) leaves it along +x, arriving along -y; a hole (clockwise) leaves it
      // along +y, arriving along -x.
      CornerRing ring;
      int pa = a, pb = b;
      if (out[start] != 0 && out[start] != 1) throw std::logic_error("part_boundary: bad loop start");
      int incoming = out[start] == 0 ? 3 : 2;
      do {
        const size_t k = static_cast<size_t>(pb * pw + pa);
        visited[k] = 1;
        const int d = out[k];
        if (d != incoming) {
          const bool left_turn = d == (incoming + 1) % 4;
          ring.push_back(Corner{i0 + pa, j0 + pb, !left_turn});
        }
        pa += kDx[d];
        pb += kDy[d];
        incoming = d;
      } while (pa != a || pb != b);
      rings.push_back(std::move(ring));
    }
  }
  return rings;
}

}  // namespace autoblock
