// lpd: k chosen from the data: from a noise estimate and the sampling density.
//
// The neighbourhood is made a fixed multiple of the noise wide: its radius r = c sigma, with
// c = radius_in_sigmas, holds k = pi r^2 / spacing^2 points, so
//   k = pi (radius_in_sigmas sigma / spacing)^2,
// clamped to [min_k, max_k]. The same cloud sampled 4x denser gets 4x the k and the same
// neighbourhoods. c = 4.2 was read off the best k of the four inputs with a clean mesh
// (FANDISK and JOINT at two noise levels: best k 16-24, 54, 36-54, >= 80; docs/method.md)
// with the 4-vector residuals of the first local fit; this probe's metric residuals read
// 1.2% higher, and c = 4.15 gives the same k on three of the four (89 for 88 on the fourth).
// sigma and the spacing come from a probe: a k-d tree over the points and 3D PCA planes
// through probe_k + 1 nearest points, around at most 131,072 evenly strided points. sigma is
// 1.4826 times the median distance of the points to their planes, corrected for the three
// degrees of freedom a fitted plane absorbs, sqrt((probe_k + 1) / (probe_k - 2)); the
// spacing is sqrt(2 pi median alpha_i / probe_k) (alpha_i, the mean squared distance to the
// probe_k nearest neighbours, is probe_k spacing^2 / (2 pi) for a uniform disk). alpha_i
// also carries the noise, 2 sigma^2 per pair, so at noise near the spacing this reads high
// (10% at sigma = 0.85 spacing); c was calibrated with this reading. With noise wider than
// a few spacings the probe reads low (thinning.h).
//
// Noise near the spacing. The probe's 41 points span about 3.6 spacings; as the noise grows
// towards that, their plane tilts into the noise and the reading falls ever faster: on a
// plane, the read sigma is 0.83 of the true one where it reads 1.0 spacing, 0.70 at 1.15,
// 0.54 at 1.26, 0.41 at 1.31. c was calibrated up to kCalibratedReadRatio (FANDISK 0.03 reads
// 1.07; the learned denoisers' benchmark at 50,000 points and 2% noise, 1.03-1.23, where 4.15
// was about best). Past it, c grows by the plane's further fall (WideNoiseFactor): JOINT 0.03
// (1.28) and the benchmark's meshes at 3% come out closer. A thin part whose sides are under
// about 3 noise deviations apart reads as one sheet with wide noise, and a wider k merges its
// sides further; the merged sides' step tells them apart afterwards (merged_sides.h), and
// reads them best off a smooth mid-surface. Such a part shows in the probe's regions as many
// that nearly split (the share passing kThinRegionGrowthSeparation, sheet_split.h: 1-6% of
// the probes on the benchmark's meshes at 50,000 points, 6-14% on plates, sheets, thin
// cylinders and thin-walled boxes whose sides are 1.4-2.8 deviations apart). k widens on
// every cloud, but only where the plane's readings hold, on few such regions, is the
// smoothing scaled back with it (smoothing_scale below; docs/method.md, "The fade moved to
// the smoothing"). Sides too close to split read as that one sheet: there k keeps the spread
// the probe reads (read_sigma) and noise_sigma is each side's noise, from the offsets'
// moments over regions of 1,500 probed points (merged_sides.h; docs/method.md, "Thin parts").
#ifndef LPD_SOLVERS_NEIGHBORHOOD_SIZE_H_
#define LPD_SOLVERS_NEIGHBORHOOD_SIZE_H_

#include <memory>
#include <string>

#include "energy/point3.h"
#include "energy/split_search.h"

namespace lpd::solvers {

struct NeighborhoodSizeOptions {
  int probe_k = 40;
  double radius_in_sigmas = 4.15;
  int min_k = 12;
  // Past about 130 the output drifts as iterations go on (JOINT 0.03 at k = 150: 2.4% farther
  // after 100 iterations than at the stop; docs/method.md, "Noise near the spacing").
  int max_k = 130;
  // c x WideNoiseFactor instead of c (docs/method.md, "Noise near the spacing"; paper: no).
  bool wide_noise = true;
  // Measure each side of a thin part from its own plane (energy/sheet_split.h; paper: no).
  bool split_sheets = true;
  // The largest problem solved, in neighbour entries n k; past it a subsample is solved
  // (thinning.h). 1e7 is about 0.6 GB and 20 s on 2 cores.
  double max_problem_size = 1e7;
  static constexpr double kSmallestProblemSize = 1e3;  // the least max_problem_size allowed

  bool IsValid(std::string* error) const;
};

// The fraction of the true sigma the probe reads on a plane with Gaussian noise where it
// reads this sigma / spacing (linear between the measured readings, held past their ends:
// 1 below 0.145, 0.83 at 1.0, 0.41 from 1.305 on).
double PlaneReadFraction(double read_ratio);

// The largest read sigma / spacing of the plane readings: there the probe reads 0.41 of the
// true sigma, and less ever faster past it, so a reading past it no longer tells how wide the
// noise is, only that it spans more than about 3 spacings (thinning.h).
double LastPlaneReadRatio();

// The probe's read sigma / spacing up to which c holds.
constexpr double kCalibratedReadRatio = 1.15;

// The share of the probe's regions that nearly split (thin_candidate_fraction below) up to
// which the plane's readings hold, and from which a cloud reads as thin parts whose sides
// are too close to split.
constexpr double kThinShareForPlaneReadings = 0.05;
constexpr double kThinCloudShare = 0.09;

// How far the plane's readings hold for a cloud with this share of nearly split regions: 1 up
// to kThinShareForPlaneReadings, falling linearly to 0 at kThinCloudShare. Sides too close to
// split read as one sheet with wider noise, not as noise the plane under-reads.
double PlaneReadingWeight(double thin_candidate_fraction);

// c's factor at this read sigma / spacing: 1 up to kCalibratedReadRatio; past it, the
// fraction of the true sigma the probe reads on a plane there over the fraction it reads at
// kCalibratedReadRatio (1.09 at 1.2, 1.30 at 1.26, held at 1.68 from 1.31 on).
double WideNoiseFactor(double read_ratio);

// The noise's deviation from the probe's reading: read_sigma over the fraction of the true
// sigma the probe reads on a plane at read_sigma / spacing, that fraction's shortfall from 1
// weighted by PlaneReadingWeight (docs/method.md, "The noise estimate").
double NoiseEstimate(double read_sigma, double spacing, double thin_candidate_fraction);

struct NeighborhoodSize {
  // The noise's deviation, in the normalized frame (bounding-box diagonal 1): of each side
  // where the probe finds the merged sides of a thin part (merged_sides.h); else NoiseEstimate
  // of read_sigma (past LastPlaneReadRatio a lower bound).
  double noise_sigma = 0.0;
  // The probe's reading, which k and the rules on sigma / spacing are calibrated on: on
  // merged sides their spread, one sheet with wider noise, as the solve sees them.
  double read_sigma = 0.0;
  bool merged_sides = false;  // noise_sigma is each merged side's
  double spacing = 0.0;  // likewise
  double radius_in_sigmas = 0.0;  // the radius k was chosen for: c, or c x WideNoiseFactor
  int k = 0;
  // The k that radius c gives over k, its shortfall from 1 weighted by PlaneReadingWeight:
  // below 1 where WideNoiseFactor widened k on a cloud of few thin parts. The smoothing
  // balance (energy/data_scaled_weights.h), a squared radius in neighbour hops, is scaled by
  // it, so that the smoothing reaches as far as the hops of radius c took it: with B at 4 over
  // the widened hops, curved parts flatten as the iterations go on past the stop (JOINT 0.03:
  // 2.6% farther from the mesh after 100 iterations; docs/method.md, "Smoothing over widened
  // neighbourhoods"). Thin parts' merged sides keep the full balance: the merged sides' step
  // reads them off a smoother mid-surface (docs/method.md, "The fade moved to the smoothing").
  // 1 for a resumed state, whose saved balance is already scaled.
  double smoothing_scale = 1.0;
  double two_sheet_fraction = 0.0;  // of the probe neighbourhoods (energy/sheet_split.h)
  // Of the probe neighbourhoods, those whose region passes the growth bar
  // (kThinRegionGrowthSeparation): sides too close to split, read as one sheet.
  double thin_candidate_fraction = 0.0;
  // With split_sheets and every point probed (at most 131,072 points): each point's wider
  // search and its split, for BuildProblem to reuse on the same points; else null.
  std::shared_ptr<const energy::SplitSearch> split_search;
};

// Throws std::invalid_argument (as energy::BuildProblem) when most points coincide with their
// probe_k nearest neighbours (no spacing), or when `points` has fewer than
// probe_k + 1 points or no extent.
NeighborhoodSize ChooseNeighborhoodSize(const energy::PointList& points,
                                        const NeighborhoodSizeOptions& options,
                                        int num_threads);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_NEIGHBORHOOD_SIZE_H_
