// Denoises a noisy unit square through the installed lpd/denoise.h and checks the result:
// exit 0 when the points came closer to their plane and a bad option was refused.
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include <lpd/denoise.h>

int main() {
  std::mt19937 random(1);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.01);
  lpd::PointList points;
  for (int i = 0; i < 4000; ++i) points.emplace_back(uniform(random), uniform(random), noise(random));

  lpd::Options options;
  options.Set("max_iters", 30).Set("snap_features", false);
  options.num_threads = 1;
  const lpd::Result result = lpd::Denoise(points, options);

  double before = 0.0, after = 0.0;
  for (const Eigen::Vector3d& p : points) before += std::abs(p.z());
  for (const Eigen::Vector3d& p : result.points) after += std::abs(p.z());
  before /= points.size();
  after /= result.points.size();
  std::printf("lpd %s: %lld of %lld points kept, k %d, %s after %d iterations; mean |z| %.3g -> %.3g\n",
              lpd::Version().c_str(), static_cast<long long>(result.summary.output_points),
              static_cast<long long>(result.summary.input_points), result.summary.k,
              result.summary.termination.c_str(), result.summary.iterations, before, after);
  bool refused = false;
  try {
    options.Set("lambda", "-1");
  } catch (const std::invalid_argument& error) {
    std::printf("refused: %s\n", error.what());
    refused = true;
  }
  return after < 0.5 * before && refused && result.points.size() == result.source_index.size() ? 0 : 1;
}
