#include "test_problems.h"

namespace lpd::testing {

energy::PointList NoisySphere(int n, double sigma, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  energy::PointList points;
  for (int i = 0; i < n; ++i) {
    energy::Point3 p(normal(rng), normal(rng), normal(rng));
    p.normalize();
    for (int c = 0; c < 3; ++c) p[c] += sigma * normal(rng);
    points.push_back(p);
  }
  return points;
}

energy::PointList NoisyPlane(int n, double sigma, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, sigma);
  energy::PointList points;
  for (int i = 0; i < n; ++i) points.emplace_back(unit(rng), unit(rng), normal(rng));
  return points;
}

energy::Variables RandomVariables(const energy::Problem& problem, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.01, 0.99);
  std::normal_distribution<double> normal(0.0, 1.0);
  energy::Variables v = energy::InitialVariables(problem);
  for (int i = 0; i < v.h.rows(); ++i) {
    for (int c = 0; c < 4; ++c) {
      v.h(i, c) = normal(rng);
      v.t(i, c) = normal(rng);
    }
    v.h.row(i).normalize();
  }
  for (int i = 0; i < v.l.size(); ++i) v.l.data()[i] = unit(rng);
  for (int p = 0; p < v.m.size(); ++p) {
    v.m[p] = unit(rng);
    v.s[p] = 4.0 * unit(rng) - 2.0;
  }
  return v;
}

energy::EnergyParameters BalancedParameters() {
  energy::EnergyParameters parameters;
  parameters.lambda = 0.7;
  parameters.eta = 3.0;
  parameters.mu_l = 0.02;
  parameters.mu_m = 0.3;
  return parameters;
}

}  // namespace lpd::testing
