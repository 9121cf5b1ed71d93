// lpd: seeded noise and outlier models for synthetic inputs.
#ifndef LPD_EXPERIMENTS_NOISE_H_
#define LPD_EXPERIMENTS_NOISE_H_

#include <random>

#include "energy/normalization.h"

namespace lpd::experiments {

// Adds isotropic Gaussian noise of standard deviation `sigma` (per coordinate) to every point.
void AddGaussianNoise(double sigma, std::mt19937_64* rng, energy::PointList* points);

// Appends `count` points drawn uniformly in the bounding box of `points` enlarged by
// `margin` times its diagonal on every side.
void AddUniformOutliers(int count, double margin, std::mt19937_64* rng,
                        energy::PointList* points);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_NOISE_H_
