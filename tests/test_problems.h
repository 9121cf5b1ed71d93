// lpd tests: small random problems and states shared by the test files.
#ifndef LPD_TESTS_TEST_PROBLEMS_H_
#define LPD_TESTS_TEST_PROBLEMS_H_

#include <random>

#include "energy/energy_parameters.h"
#include "energy/problem.h"
#include "energy/variables.h"

namespace lpd::testing {

// `n` points on a unit sphere with Gaussian noise of `sigma`, seeded.
energy::PointList NoisySphere(int n, double sigma, uint64_t seed);

// `n` points in the unit square of the z = 0 plane with Gaussian noise `sigma` along z.
energy::PointList NoisyPlane(int n, double sigma, uint64_t seed);

// A random state: unit H, random T, L and M in (0, 1), S in [-2, 2].
energy::Variables RandomVariables(const energy::Problem& problem, uint64_t seed);

// Energy parameters with weights of comparable magnitude, so that every term matters.
energy::EnergyParameters BalancedParameters();

}  // namespace lpd::testing

#endif  // LPD_TESTS_TEST_PROBLEMS_H_
