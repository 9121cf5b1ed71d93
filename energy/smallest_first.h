// lpd: the `count` smallest of a list, in order, at its front: a selection then a sort of
// those `count` (faster than std::partial_sort's heap at the sizes here, docs/performance.md),
// the rest of the list in no order. The k-nearest search, the layers' reading and the merged
// sides' reference share it.
#ifndef LPD_ENERGY_SMALLEST_FIRST_H_
#define LPD_ENERGY_SMALLEST_FIRST_H_

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

namespace lpd::energy {

// Requires count <= values->size(); count == 0 leaves the list as it is.
template <typename T, typename Less = std::less<T>>
void PlaceSmallestFirst(std::vector<T>* values, size_t count, Less less = Less()) {
  if (count == 0) return;
  std::nth_element(values->begin(), values->begin() + (count - 1), values->end(), less);
  std::sort(values->begin(), values->begin() + count, less);
}

}  // namespace lpd::energy

#endif  // LPD_ENERGY_SMALLEST_FIRST_H_
