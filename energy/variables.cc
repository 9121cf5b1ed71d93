#include "energy/variables.h"

#include "energy/large_vector.h"

namespace lpd::energy {

Variables InitialVariables(const Problem& problem, int num_threads) {
  const int n = problem.num_points();
  const int num_pairs = problem.graph.num_pairs();
  Variables v;
  v.h.resize(n, 4);
  v.t.resize(n, 4);
  v.l.resize(n, problem.k() + 1);
  v.m.resize(num_pairs);
  v.s.resize(num_pairs);
  // Written in parallel, on huge pages where the kernel gives them (energy/large_vector.h):
  // the first touch of these tables (over 100 MB at 50,000 points and k = 130) is most of
  // their cost.
  AdviseHugePages(v.l.data(), sizeof(double) * v.l.size());
  AdviseHugePages(v.m.data(), sizeof(double) * v.m.size());
  AdviseHugePages(v.s.data(), sizeof(double) * v.s.size());
#pragma omp parallel num_threads(num_threads)
  {
#pragma omp for schedule(static) nowait
    for (int i = 0; i < n; ++i) {
      v.h.row(i).setZero();
      v.t.row(i).setZero();
      v.l.row(i).setOnes();
    }
#pragma omp for schedule(static)
    for (int p = 0; p < num_pairs; ++p) {
      v.m[p] = 1.0;
      v.s[p] = 1.0;
    }
  }
  return v;
}

}  // namespace lpd::energy
