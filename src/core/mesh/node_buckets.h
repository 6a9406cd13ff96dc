// Records grouped by a node, the way a mesh's checks group the uses of its edges and faces: one
// bucket per node, counted before the records are made so that each is written in its place, then
// every bucket (a few records) sorted by the records' full order. The result is the records sorted by
// (node, full order), as std::sort by a key that starts with the node would leave them, in
// O(records + nodes) and the buckets' small sorts rather than records x log(records): a hexahedral
// mesh's checks sort millions of uses (12 edges and 6 faces of every hexahedron).
//
// Inputs:  nodes, how many nodes the records' nodes are below; count(node) once per record; close();
//          then place(node) once per record, the index its record goes to.
// Outputs: close(), the number of records (the vector to place them in); sort(records, less) sorts
//          each bucket.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace autoblock {

class NodeBuckets {
 public:
  explicit NodeBuckets(size_t nodes) : start_(nodes + 1, 0) {}

  void count(size_t node) { ++start_[node + 1]; }

  // Ends the counting: the buckets' starts. Output: the number of records counted.
  size_t close() {
    for (size_t k = 0; k + 1 < start_.size(); ++k) start_[k + 1] += start_[k];
    next_.assign(start_.begin(), start_.end() - 1);
    return start_.back();
  }

  size_t place(size_t node) { return next_[node]++; }

  template <class T, class Less>
  void sort(std::vector<T>& records, Less less) const {
    for (size_t k = 0; k + 1 < start_.size(); ++k) {
      const auto first = records.begin() + static_cast<std::ptrdiff_t>(start_[k]);
      const auto last = records.begin() + static_cast<std::ptrdiff_t>(start_[k + 1]);
      if (last - first > 1) std::sort(first, last, less);
    }
  }

 private:
  std::vector<size_t> start_, next_;
};

}  // namespace autoblock
