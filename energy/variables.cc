#include "energy/variables.h"

namespace lpd::energy {

Variables InitialVariables(const Problem& problem) {
  const int n = problem.num_points();
  const int num_pairs = problem.graph.num_pairs();
  Variables v;
  v.h = PlaneField::Zero(n, 4);
  v.t = PlaneField::Zero(n, 4);
  v.l = LineProcessTable::Ones(n, problem.k() + 1);
  v.m = Eigen::VectorXd::Ones(num_pairs);
  v.s = Eigen::VectorXd::Ones(num_pairs);
  return v;
}

}  // namespace lpd::energy
