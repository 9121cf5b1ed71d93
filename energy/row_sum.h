// lpd: deterministic parallel sums over the rows of a point-indexed array.
//
// OpenMP's reduction clause combines thread partials in an unspecified order, so the last
// bits of a sum may change from run to run. Iterative solvers feed such sums back into the
// state (CG step lengths), which would make runs irreproducible. SumOverRows gives every
// thread one contiguous block of rows (static schedule) and adds the partials in thread
// order: for a fixed thread count the result is the same bit for bit on every run.
#ifndef LPD_ENERGY_ROW_SUM_H_
#define LPD_ENERGY_ROW_SUM_H_

#include <vector>

#include <omp.h>

namespace lpd::energy {

// Returns the sum over rows i < n of what add_row(i, &sum) adds to sum, starting from `zero`.
template <typename Sum, typename AddRow>
Sum SumOverRows(int n, int num_threads, const Sum& zero, AddRow&& add_row) {
  std::vector<Sum> partials(num_threads, zero);
#pragma omp parallel num_threads(num_threads)
  {
    Sum local = zero;
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) add_row(i, &local);
    partials[omp_get_thread_num()] = local;
  }
  Sum total = zero;
  for (const Sum& partial : partials) total += partial;
  return total;
}

}  // namespace lpd::energy

#endif  // LPD_ENERGY_ROW_SUM_H_
