// lpd: the `count` smallest of a list, in order, at its front: a selection then a sort of
// those `count` by bucket (even_key_sort.h), the rest of the list in no order. The layers'
// reading and the merged sides' reference share it.
#ifndef LPD_ENERGY_SMALLEST_FIRST_H_
#define LPD_ENERGY_SMALLEST_FIRST_H_

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

#include "energy/even_key_sort.h"

namespace lpd::energy {

// Requires count <= values->size(); count == 0 leaves the list as it is. `key` and `less` as
// SortByEvenKeys takes them.
template <typename T, typename Key, typename Less = std::less<T>>
void PlaceSmallestFirst(std::vector<T>* values, size_t count, const Key& key,
                        const Less& less = Less()) {
  if (count == 0) return;
  if (count < values->size()) {
    std::nth_element(values->begin(), values->begin() + (count - 1), values->end(), less);
  }
  SortByEvenKeys(values->data(), count, key, less);
}

}  // namespace lpd::energy

#endif  // LPD_ENERGY_SMALLEST_FIRST_H_
