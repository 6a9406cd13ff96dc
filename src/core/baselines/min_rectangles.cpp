#include "core/baselines/min_rectangles.h"

#include <functional>
#include <vector>

#include "core/geometry/part_boundary.h"

namespace autoblock {
namespace {

struct Chord {
  int fixed;     // the row (horizontal chord) or column (vertical chord) of grid points
  int from, to;  // grid indices along the chord, from < to
};

// Is grid point (i, j) a re-entrant corner of the part?
bool is_reflex(const Part& part, int i, int j) {
  const int in = part.contains(i - 1, j - 1) + part.contains(i, j - 1) + part.contains(i - 1, j) + part.contains(i, j);
  return in == 3;
}

// Is grid point (i, j) on the part's boundary (some of its four cells missing, some present)?
bool on_boundary(const Part& part, int i, int j) {
  const int in = part.contains(i - 1, j - 1) + part.contains(i, j - 1) + part.contains(i - 1, j) + part.contains(i, j);
  return in > 0 && in < 4;
}

bool augment(int h, const std::vector<std::vector<int>>& conflicts, std::vector<int>& match_of_v,
             std::vector<char>& seen) {
  for (int v : conflicts[static_cast<size_t>(h)]) {
    if (seen[static_cast<size_t>(v)]) continue;
    seen[static_cast<size_t>(v)] = 1;
    if (match_of_v[static_cast<size_t>(v)] < 0 ||
        augment(match_of_v[static_cast<size_t>(v)], conflicts, match_of_v, seen)) {
      match_of_v[static_cast<size_t>(v)] = h;
      return true;
    }
  }
  return false;
}

}  // namespace

int min_rectangles(const Part& part) {
  const auto loops = part_boundary(part);
  const int holes = static_cast<int>(loops.size()) - 1;
  int reflex = 0;
  std::vector<Chord> horizontal, vertical;
  for (const CornerRing& loop : loops) {
    for (const Corner& c : loop) {
      if (!c.reflex) continue;
      ++reflex;
      // Walk right along the row (only from the left end, so each chord is found once) and up
      // along the column, while the segment ahead has part cells on both sides.
      int i = c.i;
      while (part.contains(i, c.j - 1) && part.contains(i, c.j)) {
        ++i;
        if (on_boundary(part, i, c.j)) break;
      }
      if (i != c.i && is_reflex(part, i, c.j)) horizontal.push_back(Chord{c.j, c.i, i});
      int j = c.j;
      while (part.contains(c.i - 1, j) && part.contains(c.i, j)) {
        ++j;
        if (on_boundary(part, c.i, j)) break;
      }
      if (j != c.j && is_reflex(part, c.i, j)) vertical.push_back(Chord{c.i, c.j, j});
    }
  }
  std::vector<std::vector<int>> conflicts(horizontal.size());
  for (size_t h = 0; h < horizontal.size(); ++h) {
    for (size_t v = 0; v < vertical.size(); ++v) {
      const Chord& a = horizontal[h];
      const Chord& b = vertical[v];
      if (a.from <= b.fixed && b.fixed <= a.to && b.from <= a.fixed && a.fixed <= b.to) {
        conflicts[h].push_back(static_cast<int>(v));
      }
    }
  }
  std::vector<int> match_of_v(vertical.size(), -1);
  int matching = 0;
  for (size_t h = 0; h < horizontal.size(); ++h) {
    std::vector<char> seen(vertical.size(), 0);
    if (augment(static_cast<int>(h), conflicts, match_of_v, seen)) ++matching;
  }
  const int chords = static_cast<int>(horizontal.size() + vertical.size()) - matching;
  return reflex - chords - holes + 1;
}

}  // namespace autoblock
