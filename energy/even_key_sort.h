// lpd: a sort in linear expected time for lists whose keys spread about evenly over their
// range, as the squared distances of a surface neighbourhood's points from its centre (the
// area within a radius grows as its square) or the points' offsets from a fitted plane. Each
// value goes to one of `count` equal-width buckets of the key's range, in order; each bucket
// is then sorted by `less`. The result is std::sort's order under `less` where `less` is a
// strict total order, and costs about half of it at 128 values (docs/performance.md, "The
// neighbours sorted by bucket"): std::sort's comparisons are branches the processor cannot
// predict, a bucket's index is arithmetic.
#ifndef LPD_ENERGY_EVEN_KEY_SORT_H_
#define LPD_ENERGY_EVEN_KEY_SORT_H_

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace lpd::energy {

// Buckets holding more values than this (keys bunched, or one far key that leaves the rest
// in a few buckets) are sorted by std::sort, so no list costs much more than std::sort.
constexpr size_t kMaxInsertionSortedBucket = 16;

// Sorts values[0, count) by `less`. `key(value)` is a double with less(a, b) implying
// key(a) <= key(b); keys that are all equal, or not finite, fall back to std::sort.
template <typename T, typename Key, typename Less>
void SortByEvenKeys(T* values, size_t count, const Key& key, const Less& less) {
  if (count < 2) return;
  double low = HUGE_VAL, high = -HUGE_VAL;
  bool finite = true;
  for (size_t a = 0; a < count; ++a) {
    const double k = key(values[a]);
    finite = finite && std::isfinite(k);
    low = std::min(low, k);
    high = std::max(high, k);
  }
  const double scale = static_cast<double>(count) / (high - low);
  if (!finite || !(high > low) || !(scale < HUGE_VAL)) {
    std::sort(values, values + count, less);
    return;
  }
  // (k - low) * scale is non-decreasing in k, so the buckets come in the keys' order.
  auto bucket_of = [&](const T& value) {
    return std::min(count - 1, static_cast<size_t>((key(value) - low) * scale));
  };
  thread_local std::vector<uint32_t> starts;
  thread_local std::vector<T> scattered;
  starts.assign(count + 1, 0);
  for (size_t a = 0; a < count; ++a) ++starts[bucket_of(values[a]) + 1];
  for (size_t b = 0; b < count; ++b) starts[b + 1] += starts[b];
  scattered.resize(count);
  for (size_t a = 0; a < count; ++a) scattered[starts[bucket_of(values[a])]++] = values[a];
  // starts[b] is now the end of bucket b.
  size_t begin = 0;
  for (size_t b = 0; b < count; ++b) {
    const size_t end = starts[b];
    if (end - begin > kMaxInsertionSortedBucket) {
      std::sort(scattered.begin() + begin, scattered.begin() + end, less);
    } else {
      for (size_t a = begin + 1; a < end; ++a) {
        T value = scattered[a];
        size_t c = a;
        for (; c > begin && less(value, scattered[c - 1]); --c) scattered[c] = scattered[c - 1];
        scattered[c] = value;
      }
    }
    begin = end;
  }
  std::copy(scattered.begin(), scattered.end(), values);
}

// Sorts values[0, count) ascending: the values are their own keys.
inline void SortByEvenKeys(double* values, size_t count) {
  SortByEvenKeys(values, count, [](double v) { return v; }, std::less<double>());
}

}  // namespace lpd::energy

#endif  // LPD_ENERGY_EVEN_KEY_SORT_H_
