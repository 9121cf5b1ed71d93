// lpd: the global step of Alg. 1 (line 14): T from the sparse SPD system of Eq. (9).
//
//   K T = W,  K = eta diag(alpha) + lambda sum_{(i,j) in M} beta_ij m_ij (e_i - s_ij e_j)
//                                                             (e_i - s_ij e_j)^T,
//             W = eta diag(alpha) H      (n x 4: one right-hand side per plane coordinate)
// T is the exact minimizer of E_smooth + E_stitch over T. K's sparsity pattern (compressed
// rows: the diagonal and both entries of every pair of M) is built once; each solve only
// refreshes the values, then runs preconditioned conjugate gradients on the four columns
// together, warm-started from the current T, with every vector pass parallel. CG started
// anywhere decreases the K-norm error monotonically, so even an inexact solve never
// increases the energy.
#ifndef LPD_SOLVERS_TANGENT_PLANE_SMOOTHING_H_
#define LPD_SOLVERS_TANGENT_PLANE_SMOOTHING_H_

#include <optional>
#include <string>
#include <vector>

#include <Eigen/SparseCore>

#include "energy/energy_parameters.h"
#include "energy/problem.h"
#include "energy/variables.h"
#include "solvers/linear/compressed_rows.h"
#include "solvers/linear/multilevel_preconditioner.h"

namespace lpd::solvers {

enum class Preconditioner {
  kJacobi,      // 1 / K_ii
  kMultilevel,  // an aggregation multigrid V-cycle (multilevel_preconditioner.h)
};
const char* PreconditionerName(Preconditioner preconditioner);  // "jacobi", "multilevel"
// Returns false (and leaves *preconditioner) for an unknown name.
bool ParsePreconditioner(const std::string& name, Preconditioner* preconditioner);

struct LinearSolverOptions {
  // Stop when |K t - w| <= relative_tolerance * |w| for every column.
  // 1e-4: the outputs of 1e-4 and 1e-6 agree to five digits in mean distance to the clean
  // surface (FANDISK k=50 at 1% and 3% noise; 1M-point cad_part), with 40% fewer CG steps.
  double relative_tolerance = 1e-4;
  // Upper bound on CG iterations per solve.
  int max_iterations = 2000;
  Preconditioner preconditioner = Preconditioner::kMultilevel;

  bool IsValid(std::string* error) const;
};

struct LinearSolveStats {
  int iterations = 0;               // CG iterations of the slowest column
  double relative_residual = 0.0;   // worst column's |K t - w| / |w|
};

class TangentPlaneSmoother {
 public:
  // Lays out K's pattern from the graph, with `num_threads` threads.
  explicit TangentPlaneSmoother(const energy::Problem& problem, int num_threads = 1);

  // Replaces v->t by the solution of Eq. (9) for the current H, M, S.
  LinearSolveStats Update(const energy::EnergyParameters& parameters,
                          const LinearSolverOptions& options, int num_threads,
                          energy::Variables* v);

  // K of Eq. (9) for the given variables, as an Eigen matrix (for tests and inspection).
  Eigen::SparseMatrix<double, Eigen::RowMajor> SystemMatrix(
      const energy::EnergyParameters& parameters, const energy::Variables& v);

 private:
  // K's values for the line processes m and s (one per pair of M; null: all 1).
  void AssembleValues(const energy::EnergyParameters& parameters, const double* m,
                      const double* s, int num_threads);
  // The other point of the pair incident_pairs[incident] of point i.
  int Partner(int i, int incident) const;
  // z = M^-1 r for the chosen preconditioner; returns r.z per column.
  Eigen::Array4d Precondition(Preconditioner kind, const double* r, int num_threads, double* z);

  const energy::Problem& problem_;
  CompressedRows k_;                    // K: pattern built once, values by AssembleValues
  std::vector<int> diagonal_entry_;     // entry of K_ii per row
  // Built at the first multilevel solve, from K with every m_ij = s_ij = 1: the problem's
  // data, eta and lambda alone decide the hierarchy, so a resumed run builds the same one.
  std::optional<MultilevelPreconditioner> multilevel_;
  // CG work arrays (n x 4 each), kept between solves: residual, preconditioned residual,
  // search direction and K times it.
  std::vector<double> residual_, preconditioned_, direction_, product_;
};

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_TANGENT_PLANE_SMOOTHING_H_
