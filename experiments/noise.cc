#include "experiments/noise.h"

namespace lpd::experiments {

void AddGaussianNoise(double sigma, std::mt19937_64* rng, energy::PointList* points) {
  std::normal_distribution<double> normal(0.0, sigma);
  for (energy::Point3& p : *points) {
    for (int c = 0; c < 3; ++c) p[c] += normal(*rng);
  }
}

void AddUniformOutliers(int count, double margin, std::mt19937_64* rng,
                        energy::PointList* points) {
  if (points->empty() || count <= 0) return;
  energy::Point3 lo = points->front();
  energy::Point3 hi = points->front();
  for (const energy::Point3& p : *points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double pad = margin * (hi - lo).norm();
  lo.array() -= pad;
  hi.array() += pad;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n = 0; n < count; ++n) {
    energy::Point3 p;
    for (int c = 0; c < 3; ++c) p[c] = lo[c] + unit(*rng) * (hi[c] - lo[c]);
    points->push_back(p);
  }
}

}  // namespace lpd::experiments
