#include "experiments/cli/denoise_flags.h"

#include <stdexcept>
#include <thread>

#include "experiments/sweep/denoise_parameters.h"
#include "solvers/presets.h"

DEFINE_string(preset, "default",
              "default (k, eta, lambda, mu_l from the data; run to convergence; sphere "
              "projection) or paper (the paper's literal Table 2 setting: k = 20, lambda = 1, "
              "eta = 5000, mu_l = 5e-9, 5 iterations, plane projection); flags given with it "
              "override its values");
// ---- neighbourhoods and energy (Eq. 5, Table 2) ----
DEFINE_string(k, "auto",
              "number of nearest neighbours |N(i)| (paper: 20; 50-150 for heavy noise), or "
              "auto: the points within k_radius_sigmas noise deviations, from the noise and "
              "point spacing estimated on the input, within [12, max_k]");
DEFINE_double(k_radius_sigmas, 4.15,
              "with --k=auto, k = pi (this x noise sigma / point spacing)^2: the neighbourhood "
              "radius in estimated noise deviations");
DEFINE_int32(max_k, 150, "with --k=auto, the largest k chosen");
DEFINE_double(max_problem_size, 1e7,
              "with --k=auto, the largest problem solved, in neighbour entries n x k (1e7: "
              "about 0.6 GB); past it a random subsample is denoised and every point is "
              "projected onto the subsample's surfaces");
DEFINE_double(lambda, 1.0, "weight of the piecewise-smoothness term (paper: 1-2)");
DEFINE_double(eta, 5000.0, "weight of the stitching term |h_i - t_i|^2 (paper: 5000)");
DEFINE_double(mu_l, 5e-9,
              "selectivity of the fitting line processes, a squared distance in the frame "
              "normalized to bounding-box diagonal 1 (paper: 5e-9)");
DEFINE_double(mu_m, 0.06030737921409157,
              "selectivity of the smoothness line processes (1 - cos 20deg; paper: 0.13)");
DEFINE_double(fit_balance, 0.5,
              "sets eta = this x (k + 1) x median alpha_i: the stitching weight against the "
              "fitting term's (1: a tilt of h_i away from its data costs as much as one away "
              "from t_i); 0 keeps --eta");
DEFINE_double(smoothing_balance, 4.0,
              "sets lambda so that the smoothness share of the T system's diagonal is this "
              "many times the stitching share (median over the points; about the squared "
              "smoothing radius in neighbour hops); 0 keeps --lambda");
DEFINE_double(mu_m_deg, 0.0,
              "if > 0, sets mu_m = 1 - cos(angle) from an angle in degrees (30 gives 0.134); "
              "cannot be combined with --mu_m");
// ---- solver ----
DEFINE_string(solver, "alternating",
              "alternating (Alg. 1, the paper's method) or ceres (the joint solve, the validation solver: "
              "Eq. 5 minimized over H, T, S at once by Ceres)");
DEFINE_string(initialization, "auto",
              "start of the minimization: zero (Alg. 1: H = T = 0), plane_fit (PCA planes, "
              "T = H), random (uniform h_i, as the reference implementation), input_normals "
              "(planes through the points with the normals of a PLY input), or auto (zero for "
              "alternating, plane_fit for ceres)");
DEFINE_int32(initialization_seed, 1, "random seed of --initialization=random");
// ---- schedule (Alg. 1) ----
DEFINE_int32(max_iters, 100,
             "maximum outer iterations of Alg. 1 (paper preset: 5, as the reference "
             "implementation; the default converges after 20-60)");
DEFINE_int32(inner_iters, 2, "(T, M, S) passes per outer iteration (paper: 2)");
DEFINE_double(energy_tolerance, 1e-3,
              "stop when the energy changes by less than this fraction over three "
              "iterations (paper: 0.01); 0 with --progress_tolerance=0 runs all iterations");
DEFINE_double(progress_tolerance, 1e-3,
              "also stop when the last three iterations lowered the energy by less than this "
              "fraction of its fall since the first iteration (paper preset: 0, off)");
DEFINE_bool(optimize_orientations, true,
            "update the orientations s_ij (Eq. 8); false holds them at 1 (ablation of Fig. 4)");
DEFINE_double(mu_l_noise_sigmas, 4.0,
              "if > 0, replaces --mu_l by (c sigma)^2 with c this value and sigma = 1.4826 "
              "median |h_i.q_j| after the first local fit (a robust noise estimate); 0 keeps "
              "--mu_l");
// ---- graduated non-convexity ----
DEFINE_string(gnc, "none",
              "continue mu_l, mu_m or both from a convex start down to their targets (none, "
              "mu_l, mu_m, both); the stages count toward --max_iters");
DEFINE_double(gnc_start_ratio, 0.0,
              "first-stage mu as a multiple of its target; 0 starts where the Geman-McClure "
              "cost is convex over all current residuals (3 max r^2)");
DEFINE_double(gnc_factor, 1.4, "divide the continued mu by this after every stage");
DEFINE_int32(gnc_stage_iters, 1, "outer iterations per GNC stage");
DEFINE_double(linear_tolerance, 1e-4, "relative residual at which the T solve (Eq. 9) stops");
DEFINE_int32(max_cg_iterations, 2000, "conjugate-gradient iterations per T solve, at most");
DEFINE_string(preconditioner, "multilevel",
              "of the T solve's conjugate gradients: jacobi (1/K_ii) or multilevel (a multigrid "
              "V-cycle on runs of 8 points along the Morton curve, block-Jacobi sweeps)");
// ---- joint solve (--solver=ceres) ----
DEFINE_string(ceres_linear_solver, "sparse_schur",
              "sparse_schur, iterative_schur, sparse_normal_cholesky or cgnr");
DEFINE_int32(ceres_max_iters, 100, "Levenberg-Marquardt iterations at most");
DEFINE_double(ceres_function_tolerance, 1e-6, "stop when the cost changes by less (relative)");
DEFINE_double(ceres_gradient_tolerance, 1e-10, "stop when the max-norm gradient is below this");
DEFINE_double(ceres_parameter_tolerance, 1e-8, "stop when the step is below this (relative)");
DEFINE_double(ceres_max_seconds, 1e6, "wall-time budget of the joint solve");
DEFINE_string(ceres_orientations, "blocks",
              "s_ij as parameter blocks (blocks) or held at their optimum t_i.t_j/|t_j|^2, "
              "Eq. 8 (closed_form)");
DEFINE_int32(threads, static_cast<int>(std::max(1u, std::thread::hardware_concurrency())),
             "worker threads (default: all cores)");
// ---- final denoising (Sec. 3.4) ----
DEFINE_string(projection, "sphere",
              "final projection of each point: plane (onto t_i, Sec. 3.4) or sphere (onto the "
              "algebraic sphere fitted to its neighbours' planes, weighted by m_ij)");
DEFINE_int32(blended_surfaces, 30,
             "a point moves to the mean of its projections onto the surfaces of itself and its "
             "nearest neighbours, this many in all (at most k + 1; paper preset: 1, its own)");
DEFINE_double(outlier_fraction, 0.65,
              "outlier score (1 - the support-weighted fitting line processes the planes of "
              "N(i) u {i} give q_i) at which i is an outlier (paper preset: 0.9)");
DEFINE_double(feature_threshold, 0.5, "m_ij below this counts as a feature vote");
DEFINE_double(feature_fraction, 0.3,
              "share of feature votes above which i is a feature point (paper preset: 0.7)");
DEFINE_bool(remove_outliers, true, "drop points flagged as outliers from the output");
DEFINE_double(max_removed_fraction, 0.5,
              "keep all points (and say so) if more than this share is flagged as outliers");
DEFINE_int32(outlier_passes, 2,
             "denoising passes at most: while a pass removes more than "
             "--outlier_rerun_fraction of its points, the kept points are denoised again from "
             "their input coordinates (paper preset: 1)");
DEFINE_double(outlier_rerun_fraction, 0.05,
              "share of removed points above which another pass runs");
DEFINE_double(isolation_factor, 3.0,
              "after the passes, a kept point whose --isolation_neighbors-th nearest kept "
              "point is farther than this many times the median such distance, over all kept "
              "points and over its own neighbours, is an outlier (0: off; paper preset: off)");
DEFINE_int32(isolation_neighbors, 40, "the neighbour rank of --isolation_factor's test");
DEFINE_bool(snap_features, false,
            "feature improvement (Sec. 3.4): move feature points onto the intersection line "
            "of the two DBSCAN clusters of their neighbours' planes t_j");
DEFINE_double(snap_cluster_angle_deg, 10.0,
              "DBSCAN radius of --snap_features: neighbouring planes whose normals are at most "
              "this many degrees apart are close");
DEFINE_int32(snap_min_cluster_planes, 4,
             "DBSCAN density of --snap_features: planes within the radius (itself included) "
             "that make a core plane");

namespace lpd::experiments {

bool FlagGiven(const char* name) { return !gflags::GetCommandLineFlagInfoOrDie(name).is_default; }

solvers::DenoiseOptions DenoiseOptionsFromFlags(
    const std::vector<std::pair<std::string, std::string>>* saved) {
  solvers::Preset preset;
  if (!solvers::ParsePreset(FLAGS_preset, &preset)) {
    throw std::invalid_argument("--preset must be default or paper, got '" + FLAGS_preset + "'");
  }
  solvers::DenoiseOptions options = solvers::PresetOptions(preset);
  if (!solvers::ParseSolver(FLAGS_solver, &options.solver)) {
    throw std::invalid_argument("--solver must be alternating or ceres, got '" + FLAGS_solver +
                                "'");
  }
  if (saved) {
    for (const auto& [name, value] : *saved) SetDenoiseParameter(name, value, &options);
  }
  for (const std::string& name : DenoiseParameterNames()) {
    const gflags::CommandLineFlagInfo flag = gflags::GetCommandLineFlagInfoOrDie(name.c_str());
    if (!flag.is_default && !DenoiseParameterApplies(name, options.solver)) {
      throw std::invalid_argument("--" + name + " has no effect with --solver=" + FLAGS_solver);
    }
    if (!flag.is_default) SetDenoiseParameter(name, flag.current_value, &options);
  }
  if (FlagGiven("mu_m_deg")) {
    if (FlagGiven("mu_m")) {
      throw std::invalid_argument("give either --mu_m or --mu_m_deg, not both");
    }
    SetDenoiseParameter("mu_m_deg", std::to_string(FLAGS_mu_m_deg), &options);
  }
  options.settings.num_threads = FLAGS_threads;
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);
  return options;
}

}  // namespace lpd::experiments
