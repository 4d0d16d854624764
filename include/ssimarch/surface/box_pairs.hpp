#pragma once
// Which boxes of one set meet which of another: sweep and prune along the axis on which the boxes
// spread most (Cohen, Lin, Manocha and Ponamgi, "I-COLLIDE", 1995, §4.2: sort the intervals'
// starts, keep the intervals still open, test the other two axes only against those). The work is
// n log n for the sort plus the pairs whose intervals overlap on the sweep axis, not every pair:
// `ssimarch intersect` culls the face pairs of two CAD parts with it (issue 28 item 4).

#include <utility>
#include <vector>

#include "ssimarch/surface/domain.hpp"

namespace ssimarch {

/// The pairs (i, j), a[i] and b[j] within `slack` (model units, >= 0) of each other on every
/// axis, ordered by i then j. With `same_set` (b is a), each unordered pair once with i < j and
/// no box with itself.
std::vector<std::pair<int, int>> overlapping_boxes(const std::vector<Box>& a, const std::vector<Box>& b, double slack,
                                                   bool same_set = false);

}  // namespace ssimarch
