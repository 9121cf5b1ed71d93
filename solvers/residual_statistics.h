// lpd: statistics of the current residuals of Eq. (5) that set the selectivities mu_l and mu_m
// (the scale-aware mu_l and the convex start of graduated non-convexity).
#ifndef LPD_SOLVERS_RESIDUAL_STATISTICS_H_
#define LPD_SOLVERS_RESIDUAL_STATISTICS_H_

#include "energy/problem.h"
#include "energy/variables.h"

namespace lpd::solvers {

// max_{i, j in N(i) u {i}} (h_i^T q_j)^2: the largest squared fitting residual.
double MaxSquaredFittingResidual(const energy::Problem& problem, const energy::Variables& v,
                                 int num_threads);

// max_{(i,j) in M} |t_i - s_ij t_j|^2: the largest squared smoothness residual.
double MaxSquaredSmoothnessResidual(const energy::Problem& problem, const energy::Variables& v,
                                    int num_threads);

// 1.4826 median |h_i^T q_j| over i and j in N(i) u {i}: the normalized median absolute
// residual, a robust estimate of the noise's standard deviation (it equals sigma for
// Gaussian residuals and ignores up to half of the residuals being outliers). Above 2^20
// residuals it takes the median of an evenly strided subset (deterministic). A plane fitted
// to k + 1 points absorbs three degrees of freedom, and with noise comparable to the sample
// spacing the k-NN search favours neighbours near p_i's own offset, so the estimate runs
// low (about 0.9 sigma at sigma = spacing); the multiple c in mu_l = (c sigma)^2 absorbs it.
// Never below the coordinate grid's rounding noise (problem.quantization_noise).
double RobustFittingResidualScale(const energy::Problem& problem, const energy::Variables& v);

// A tenth of the sample spacing: the floor of the sigma behind mu_l. Without noise the
// residuals are the planes' model error, zero on flat faces and the sagitta on curved parts,
// and a mu_l set from their median flags curved parts and edges as outliers (noise-free
// samples of cad_part lost 20-37% of their points, of the bunny 3.9%). At a tenth of the
// spacing noise-free and low-noise samples are flagged at the rate noisy ones are, under 1%;
// the shared noisy models read higher, the real scan 0.097 (docs/robustness.md, "Noise-free
// and low-noise input").
constexpr double kMinMuLNoiseSpacings = 0.1;

// The noise deviation behind the scale-aware mu_l: RobustFittingResidualScale, at least
// kMinMuLNoiseSpacings x SampleSpacing(problem).
double FittingNoiseSigma(const energy::Problem& problem, const energy::Variables& v);

// mu_l = (c sigma)^2 (the scale-aware mu_l), c = noise_sigmas, sigma = noise_sigma.
double NoiseScaledMuL(double noise_sigma, double noise_sigmas);

// sqrt(mean_i |P_new(p_i) - P_old(p_i)|^2), P(p) the projection of p onto the plane t_i of
// `old_t` or `new_t` (Sec. 3.4): how far one iteration moved the output points. Points whose
// plane has no normal in either field count as unmoved. Deterministic in any thread count.
double RmsProjectedPointChange(const energy::Problem& problem, const energy::PlaneField& old_t,
                               const energy::PlaneField& new_t, int num_threads);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_RESIDUAL_STATISTICS_H_
