// lpd: a sparse matrix in compressed rows, multiplied by four right-hand sides at once.
//
// The T system of Eq. (9) has one matrix and four right-hand sides (the plane coordinates),
// so every product here takes X as n x 4, row-major: the four values of a row sit together
// and each stored entry is read once for all four columns.
#ifndef LPD_SOLVERS_LINEAR_COMPRESSED_ROWS_H_
#define LPD_SOLVERS_LINEAR_COMPRESSED_ROWS_H_

#include <vector>

#include "energy/large_vector.h"

namespace lpd::solvers {

struct CompressedRows {
  std::vector<int> row_offsets;  // row i's entries are [row_offsets[i], row_offsets[i + 1])
  // Sorted within each row. Resizing leaves both arrays unwritten: whoever sizes them fills
  // them.
  energy::LargeVector<int> columns;
  energy::LargeVector<double> values;

  int num_rows() const { return static_cast<int>(row_offsets.size()) - 1; }

  // y = row i of A X.
  void RowTimes(const double* x, int i, double* y) const {
    double sum[4] = {0.0, 0.0, 0.0, 0.0};
    for (int e = row_offsets[i]; e < row_offsets[i + 1]; ++e) {
      const double value = values[e];
      const double* x_j = x + 4 * columns[e];
      for (int c = 0; c < 4; ++c) sum[c] += value * x_j[c];
    }
    for (int c = 0; c < 4; ++c) y[c] = sum[c];
  }
};

// Threads for a parallel pass over `rows` rows: one below 4096, where opening a parallel
// region costs more than the work.
inline int ThreadsForRows(int rows, int num_threads) { return rows >= 4096 ? num_threads : 1; }

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_LINEAR_COMPRESSED_ROWS_H_
