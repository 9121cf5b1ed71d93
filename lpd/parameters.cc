#include "lpd/parameters.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace lpd {
namespace {

using solvers::DenoiseOptions;
using solvers::Solver;

using Scope = ParameterScope;
using Kind = ParameterKind;

// One declaration: what users see (ParameterInfo) and where the value lives in
// DenoiseOptions. Exactly one kind of accessor is set.
struct Parameter {
  ParameterInfo info;
  std::function<int&(DenoiseOptions&)> integer;
  std::function<double&(DenoiseOptions&)> number;
  std::function<bool&(DenoiseOptions&)> flag;
  // A named choice (or a value with an "auto"): `set_choice` throws std::invalid_argument
  // on a text it does not take.
  std::function<std::string(const DenoiseOptions&)> get_choice;
  std::function<void(const std::string&, DenoiseOptions&)> set_choice;
};

// What --help and the documentation show of a parameter.
struct Text {
  std::string group;
  std::string help;
  std::string auto_rule = {};
  std::string paper_value = {};
};

Parameter Named(std::string name, Kind kind, Scope scope, Text text) {
  Parameter parameter;
  parameter.info = {std::move(name), kind, scope, std::move(text.group), std::move(text.help),
                    std::move(text.auto_rule), std::move(text.paper_value)};
  return parameter;
}

Parameter Integer(std::string name, Scope scope, Text text,
                  std::function<int&(DenoiseOptions&)> field) {
  Parameter parameter = Named(std::move(name), Kind::kInteger, scope, std::move(text));
  parameter.integer = std::move(field);
  return parameter;
}

Parameter Number(std::string name, Scope scope, Text text,
                 std::function<double&(DenoiseOptions&)> field) {
  Parameter parameter = Named(std::move(name), Kind::kNumber, scope, std::move(text));
  parameter.number = std::move(field);
  return parameter;
}

Parameter Flag(std::string name, Scope scope, Text text,
               std::function<bool&(DenoiseOptions&)> field) {
  Parameter parameter = Named(std::move(name), Kind::kFlag, scope, std::move(text));
  parameter.flag = std::move(field);
  return parameter;
}

Parameter Choice(std::string name, Kind kind, Scope scope, Text text,
                 std::function<std::string(const DenoiseOptions&)> get,
                 std::function<void(const std::string&, DenoiseOptions&)> set) {
  Parameter parameter = Named(std::move(name), kind, scope, std::move(text));
  parameter.get_choice = std::move(get);
  parameter.set_choice = std::move(set);
  return parameter;
}

[[noreturn]] void ThrowUnknownChoice(const std::string& name, const std::string& text,
                                     const std::string& choices) {
  throw std::invalid_argument("parameter " + name + ": '" + text + "' is not one of " + choices);
}

// A choice stored as an enum with a name function and a parser (solvers' Name/Parse pairs).
template <typename Enum, typename NameOf>
Parameter EnumChoice(std::string name, Scope scope, Text text,
                     std::function<Enum&(DenoiseOptions&)> field, NameOf name_of,
                     bool (*parse)(const std::string&, Enum*), std::string choices) {
  auto get = [field, name_of](const DenoiseOptions& o) {
    DenoiseOptions copy = o;  // `field` reaches into a mutable DenoiseOptions
    return std::string(name_of(field(copy)));
  };
  auto set = [name, field, parse, choices](const std::string& text, DenoiseOptions& o) {
    if (!parse(text, &field(o))) ThrowUnknownChoice(name, text, choices);
  };
  return Choice(std::move(name), Kind::kChoice, scope, std::move(text), std::move(get),
                std::move(set));
}

// `text` as a finite number; `expected` says what was expected ("a number or auto").
double ParseNumber(const std::string& name, const std::string& text, const char* expected) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value)) {
    throw std::invalid_argument("parameter " + name + ": '" + text + "' is not " + expected);
  }
  return value;
}

int ParseInteger(const std::string& name, const std::string& text, const char* expected) {
  const double value = ParseNumber(name, text, expected);
  if (value != std::floor(value)) {
    throw std::invalid_argument("parameter " + name + ": '" + text + "' is not " + expected);
  }
  if (std::abs(value) > 1e9) {
    throw std::invalid_argument("parameter " + name + ": " + text +
                                " is out of range (at most 1e9 in magnitude)");
  }
  return static_cast<int>(value);
}

// The shortest of 15 or 17 significant digits that reads back as exactly `value` (a saved
// state must resume with the very same doubles).
std::string ExactText(double value) {
  std::ostringstream out;
  out.precision(15);
  out << value;
  if (std::strtod(out.str().c_str(), nullptr) == value) return out.str();
  out.str("");
  out.precision(17);
  out << value;
  return out.str();
}

// Values that take "auto" besides a number: the weights whose data rule is the parameter
// `rule` of DenoiseOptions (0: off). A number switches the rule off, "auto" back on (with
// its default when it was off).
Parameter WeightWithDataRule(std::string name, Text text,
                             std::function<double&(DenoiseOptions&)> weight,
                             std::function<double&(DenoiseOptions&)> rule) {
  auto get = [weight, rule](const DenoiseOptions& o) {
    DenoiseOptions copy = o;
    return rule(copy) > 0.0 ? std::string("auto") : ExactText(weight(copy));
  };
  auto set = [name, weight, rule](const std::string& text, DenoiseOptions& o) {
    if (text == "auto") {
      DenoiseOptions defaults;
      if (!(rule(o) > 0.0)) rule(o) = rule(defaults);
      return;
    }
    weight(o) = ParseNumber(name, text, "a number or auto");
    rule(o) = 0.0;
  };
  return Choice(std::move(name), Kind::kNumber, Scope::kBoth, std::move(text), std::move(get),
                std::move(set));
}

// k, the energy's weights and their data rules, the initial state.
std::vector<Parameter> ProblemAndEnergyParameters() {
  using O = DenoiseOptions;
  constexpr Scope kBoth = Scope::kBoth;
  const std::string kNeighbours = "neighbourhoods";
  const std::string kEnergy = "energy (Eq. 5, Table 2)";
  const std::string kStart = "start of the minimization";
  return {
      Choice(
          "k", Kind::kInteger, kBoth,
          {kNeighbours, "number of nearest neighbours |N(i)| (50-150 for heavy noise)",
           "the points within k_radius_sigmas noise deviations, from the noise and point "
           "spacing estimated on the input, within [12, max_k]",
           "20"},
          [](const O& o) {
            return o.choose_k ? std::string("auto") : std::to_string(o.problem.k);
          },
          [](const std::string& text, O& o) {
            o.choose_k = text == "auto";
            if (!o.choose_k) o.problem.k = ParseInteger("k", text, "an integer or auto");
          }),
      Number("k_radius_sigmas", kBoth,
             {kNeighbours,
              "with k auto, k = pi (this x noise sigma / point spacing)^2: the neighbourhood "
              "radius in estimated noise deviations"},
             [](O& o) -> double& { return o.neighborhood.radius_in_sigmas; }),
      Flag("k_wide_noise", kBoth,
           {kNeighbours,
            "with k auto, where the noise probe reads sigma above 1.15 spacings (where it reads "
            "low, as measured on a noisy plane), widen the radius by the plane's under-reading, "
            "k up to max_k, and scale the smoothing balance back to the radius's k, less and "
            "not at all as 5% to 9% of the probe's regions nearly split into two sides (thin "
            "parts, whose merged sides want the full smoothing). Where it reads past 1.305 "
            "spacings (no longer telling the noise) and over 5% of the regions nearly split, "
            "solve a subsample it reads under 1.27",
            "", "false"},
           [](O& o) -> bool& { return o.neighborhood.wide_noise; }),
      Integer("max_k", kBoth, {kNeighbours, "with k auto, the largest k chosen"},
              [](O& o) -> int& { return o.neighborhood.max_k; }),
      Flag("split_sheets", kBoth,
           {kNeighbours,
            "where a part is thinner than the neighbourhood (a wall, a plate, a petal), take "
            "N(i) from p_i's own side and measure the noise on each side apart",
            "", "false"},
           [](O& o) -> bool& { return o.problem.split_sheets; }),
      Number("max_problem_size", kBoth,
             {kNeighbours,
              "with k auto, the largest problem solved, in neighbour entries n x k (1e7: about "
              "0.6 GB); past it a random subsample is denoised and every point is projected "
              "onto the subsample's surfaces"},
             [](O& o) -> double& { return o.neighborhood.max_problem_size; }),
      WeightWithDataRule(
          "lambda",
          {kEnergy,
           "weight of the piecewise-smoothness term, in the frame normalized to diagonal 1 "
           "(the paper's 1 fits its own setting only: use smoothing_balance to change the "
           "data-derived value)",
           "from smoothing_balance", "1"},
          [](O& o) -> double& { return o.settings.energy.lambda; },
          [](O& o) -> double& { return o.weights.smoothing_balance; }),
      WeightWithDataRule(
          "eta",
          {kEnergy,
           "weight of the stitching term |h_i - t_i|^2 (the paper's 5000 fits its own setting "
           "only: use fit_balance to change the data-derived value)",
           "from fit_balance", "5000"},
          [](O& o) -> double& { return o.settings.energy.eta; },
          [](O& o) -> double& { return o.weights.fit_balance; }),
      WeightWithDataRule(
          "mu_l",
          {kEnergy,
           "selectivity of the fitting line processes, a squared distance in the frame "
           "normalized to diagonal 1",
           "(mu_l_noise_sigmas x the noise estimate)^2, the estimate at least a tenth of the "
           "spacing",
           "5e-9"},
          [](O& o) -> double& { return o.settings.energy.mu_l; },
          [](O& o) -> double& { return o.settings.mu_l_noise_sigmas; }),
      Number("mu_m", kBoth,
             {kEnergy, "selectivity of the smoothness line processes (1 - cos 20 deg)", "",
              "0.13"},
             [](O& o) -> double& { return o.settings.energy.mu_m; }),
      Number("fit_balance", kBoth,
             {kEnergy,
              "eta = this x (k + 1) x median alpha_i: the stitching weight against the "
              "fitting term's (1: a tilt of h_i away from its data costs as much as one away "
              "from t_i); 0 keeps eta",
              "", "0"},
             [](O& o) -> double& { return o.weights.fit_balance; }),
      Number("smoothing_balance", kBoth,
             {kEnergy,
              "lambda such that the smoothness share of the T system's diagonal is this many "
              "times the stitching share (median over the points; about the squared "
              "smoothing radius in neighbour hops, of the radius k_radius_sigmas gives where "
              "k_wide_noise widens k); 0 keeps lambda",
              "", "0"},
             [](O& o) -> double& { return o.weights.smoothing_balance; }),
      Number("mu_l_noise_sigmas", kBoth,
             {kEnergy,
              "mu_l = (c sigma)^2 with c this value and sigma = 1.4826 median |h_i.q_j| "
              "after the first local fit (a robust noise estimate); 0 keeps mu_l",
              "", "0"},
             [](O& o) -> double& { return o.settings.mu_l_noise_sigmas; }),
      Choice(
          "initialization", Kind::kChoice, kBoth,
          {kStart,
           "zero (Alg. 1: H = T = 0), plane_fit (PCA planes, T = H), random (uniform h_i, as "
           "the reference implementation), input_normals (planes through the points with the "
           "input's normals), or auto (plane_fit; for alternating in the paper preset, zero)"},
          [](const O& o) {
            return o.initialization ? solvers::InitializationName(*o.initialization) : "auto";
          },
          [](const std::string& text, O& o) {
            solvers::Initialization initialization;
            if (text == "auto") {
              o.initialization.reset();
            } else if (solvers::ParseInitialization(text, &initialization)) {
              o.initialization = initialization;
            } else {
              ThrowUnknownChoice("initialization", text,
                                 "auto, zero, plane_fit, random, input_normals");
            }
          }),
      Integer("initialization_seed", kBoth, {kStart, "random seed of initialization random"},
              [](O& o) -> int& { return o.initialization_seed; }),
  };
}

// Alg. 1's schedule, stopping rule, GNC and T solver.
std::vector<Parameter> AlternatingParameters() {
  using O = DenoiseOptions;
  constexpr Scope kAlternating = Scope::kAlternating;
  const std::string kSchedule = "schedule of Alg. 1 (solver alternating)";
  const std::string kGnc = "graduated non-convexity (solver alternating)";
  return {
      Integer("max_iters", kAlternating,
              {kSchedule,
               "maximum outer iterations (the default converges after 7-30)", "", "5"},
              [](O& o) -> int& { return o.minimizer.max_iterations; }),
      Integer("inner_iters", kAlternating,
              {kSchedule, "(T, M, S) passes per outer iteration", "", "2"},
              [](O& o) -> int& { return o.minimizer.inner_iterations; }),
      Number("energy_tolerance", kAlternating,
             {kSchedule,
              "stop when the energy changes by less than this fraction over three iterations; "
              "0 with progress_tolerance and motion_tolerance 0 runs all iterations",
              "", "0.01"},
             [](O& o) -> double& { return o.minimizer.energy_tolerance; }),
      Number("progress_tolerance", kAlternating,
             {kSchedule,
              "also stop when the last three iterations lowered the energy by less than this "
              "fraction of its fall since the first iteration (0: off)",
              "", "0"},
             [](O& o) -> double& { return o.minimizer.progress_tolerance; }),
      Number("motion_tolerance", kAlternating,
             {kSchedule,
              "also stop when each of the last three iterations moved the output points by "
              "less than this many noise deviations (RMS; 0: off)",
              "", "0"},
             [](O& o) -> double& { return o.minimizer.motion_tolerance; }),
      Flag("optimize_orientations", kAlternating,
           {kSchedule, "update the orientations s_ij (Eq. 8); false holds them at 1 (Fig. 4)"},
           [](O& o) -> bool& { return o.minimizer.optimize_orientations; }),
      EnumChoice<solvers::GncTarget>(
          "gnc", kAlternating,
          {kGnc,
           "continue mu_l, mu_m or both from a convex start down to their targets (none, "
           "mu_l, mu_m, both); the stages count toward max_iters"},
          [](O& o) -> solvers::GncTarget& { return o.minimizer.gnc.target; },
          solvers::GncTargetName, solvers::ParseGncTarget, "none, mu_l, mu_m, both"),
      Number("gnc_start_ratio", kAlternating,
             {kGnc,
              "first-stage mu as a multiple of its target; 0 starts where the Geman-McClure "
              "cost is convex over all current residuals (3 max r^2)"},
             [](O& o) -> double& { return o.minimizer.gnc.start_ratio; }),
      Number("gnc_factor", kAlternating, {kGnc, "divide the continued mu by this every stage"},
             [](O& o) -> double& { return o.minimizer.gnc.factor; }),
      Integer("gnc_stage_iters", kAlternating, {kGnc, "outer iterations per stage"},
              [](O& o) -> int& { return o.minimizer.gnc.stage_iterations; }),
      Number("linear_tolerance", kAlternating,
             {kSchedule, "relative residual at which the T solve (Eq. 9) stops"},
             [](O& o) -> double& { return o.minimizer.linear_solver.relative_tolerance; }),
      Integer("max_cg_iterations", kAlternating,
              {kSchedule, "conjugate-gradient iterations per T solve, at most"},
              [](O& o) -> int& { return o.minimizer.linear_solver.max_iterations; }),
      EnumChoice<solvers::Preconditioner>(
          "preconditioner", kAlternating,
          {kSchedule,
           "of the T solve's conjugate gradients: jacobi (1/K_ii) or multilevel (a multigrid "
           "V-cycle on runs of 8 points along the Morton curve, block-Jacobi sweeps)"},
          [](O& o) -> solvers::Preconditioner& { return o.minimizer.linear_solver.preconditioner; },
          solvers::PreconditionerName, solvers::ParsePreconditioner, "jacobi, multilevel"),
  };
}

// The Ceres joint solve.
std::vector<Parameter> JointSolveParameters() {
  using O = DenoiseOptions;
  constexpr Scope kCeres = Scope::kCeres;
  const std::string kJoint = "joint solve (solver ceres)";
  return {
      Choice(
          "ceres_orientations", Kind::kChoice, kCeres,
          {kJoint,
           "s_ij as parameter blocks (blocks) or held at their optimum t_i.t_j/|t_j|^2, Eq. 8 "
           "(closed_form)"},
          [](const O& o) {
            return std::string(o.joint.optimize_orientations ? "blocks" : "closed_form");
          },
          [](const std::string& text, O& o) {
            if (text != "blocks" && text != "closed_form") {
              ThrowUnknownChoice("ceres_orientations", text, "blocks, closed_form");
            }
            o.joint.optimize_orientations = text == "blocks";
          }),
      EnumChoice<ceres::LinearSolverType>(
          "ceres_linear_solver", kCeres,
          {kJoint, "sparse_schur, iterative_schur, sparse_normal_cholesky or cgnr"},
          [](O& o) -> ceres::LinearSolverType& { return o.joint.linear_solver_type; },
          solvers::JointLinearSolverName, solvers::ParseJointLinearSolver,
          "sparse_schur, iterative_schur, sparse_normal_cholesky, cgnr"),
      Integer("ceres_max_iters", kCeres, {kJoint, "Levenberg-Marquardt iterations at most"},
              [](O& o) -> int& { return o.joint.max_iterations; }),
      Number("ceres_function_tolerance", kCeres,
             {kJoint, "stop when the cost changes by less (relative)"},
             [](O& o) -> double& { return o.joint.function_tolerance; }),
      Number("ceres_gradient_tolerance", kCeres,
             {kJoint, "stop when the max-norm gradient is below this"},
             [](O& o) -> double& { return o.joint.gradient_tolerance; }),
      Number("ceres_parameter_tolerance", kCeres,
             {kJoint, "stop when the step is below this (relative)"},
             [](O& o) -> double& { return o.joint.parameter_tolerance; }),
      Number("ceres_max_seconds", kCeres, {kJoint, "wall-time budget of the joint solve"},
             [](O& o) -> double& { return o.joint.max_seconds; }),
  };
}

// The final step of Sec. 3.4: projection, indicators, outlier passes, snapping.
std::vector<Parameter> FinalStepParameters() {
  using O = DenoiseOptions;
  constexpr Scope kBoth = Scope::kBoth;
  const std::string kFinal = "final denoising (Sec. 3.4)";
  const std::string kOutliers = "outliers";
  const std::string kSnapping = "feature snapping (Sec. 3.4)";
  return {
      EnumChoice<solvers::Projection>(
          "projection", kBoth,
          {kFinal,
           "final projection of each point: plane (onto t_i, Sec. 3.4) or sphere (onto the "
           "algebraic sphere fitted to its neighbours' planes, weighted by m_ij)",
           "", "plane"},
          [](O& o) -> solvers::Projection& { return o.final_step.projection; },
          solvers::ProjectionName, solvers::ParseProjection, "plane, sphere"),
      Integer("blended_surfaces", kBoth,
              {kFinal,
               "a point moves to the weighted mean of its projections onto the surfaces of "
               "itself and its nearest neighbours, this many in all at least (at most k + 1); "
               "a surface that moves it far from where its own surface does (an edge's other "
               "face, a thin part's other side) counts little",
               "", "1"},
              [](O& o) -> int& { return o.final_step.blended_surfaces; }),
      Number("blended_share", kBoth,
             {kFinal,
              "or this share of the cloud's distinct points, when that is more (at most "
              "k + 1; 0.001: 50 surfaces at 50,000 points): a denser cloud blends the "
              "surfaces of a patch of the same share of its shape",
              "", "0"},
             [](O& o) -> double& { return o.final_step.blended_share; }),
      Flag("settled_blend", kBoth,
           {kFinal,
            "project each point once more onto the blend from where the blend put it, and move "
            "it along the blend's normal by the difference: the first projection, from the "
            "noisy input point, reads each surface where that point's height puts it",
            "", "false"},
           [](O& o) -> bool& { return o.final_step.settled_blend; }),
      Integer("even_spacing", kBoth,
              {kFinal,
               "rounds of Lloyd's relaxation of the output points within their tangent planes, "
               "each point then following its own fitted surface: the output's spacing evens "
               "out instead of keeping the noise along the surface (0: off)",
               "", "0"},
              [](O& o) -> int& { return o.final_step.even_spacing_rounds; }),
      Integer("height_smoothing", kBoth,
              {kFinal,
               "pairs of rounds that move each output point along its normal by the median "
               "height of itself and its 8 nearest outputs within 20 degrees and two noise "
               "deviations of it, times 0.63 then -0.67 (Taubin's smoothing: the point-to-point "
               "jitter of the fitted surfaces goes, the curved shape stays; 0: off)",
               "", "0"},
              [](O& o) -> int& { return o.final_step.height_smoothing_pairs; }),
      Flag("adaptive_heights", kBoth,
           {kFinal,
            "last, where the probe reads the noise narrower than the spacing, move each "
            "output point along its normal to the height of a quadratic fitted to its "
            "nearest outputs (12 to 256 of them, within 20 degrees and the outputs' jitter), "
            "over the widest of them whose estimate agrees with every narrower one's within "
            "two standard errors: flat and gently curved parts take wide fits, edges and fine "
            "detail narrow ones",
            "", "false"},
           [](O& o) -> bool& { return o.final_step.adaptive_heights; }),
      Flag("offset_feedback", kBoth,
           {kFinal,
            "move each output point along its normal by the mean offset of the input points "
            "from their outputs over its 120 nearest, shrunk to the bias's posterior mean "
            "given the means around it (the inward bias of wide neighbourhoods on curved "
            "parts); only where the probe reads sigma at most 1.15 spacings",
            "", "false"},
           [](O& o) -> bool& { return o.final_step.offset_feedback; }),
      Flag("separate_sides", kBoth,
           {kFinal,
            "where the input points' offsets from the output (from the mean of its 60 outputs "
            "nearest across its normal within two deviations of the inputs' offsets along it) "
            "read as two sides of a thin part merged into one (kurtosis under 2.75 over 1,500 "
            "points; where half their points see another output layer beyond that band, "
            "among their 120 nearest outputs or within 5 bands, over the others, 200 or more, "
            "which alone move), "
            "move each output point to the side its offset's sign picks; only where a tenth or "
            "more of these regions read as merged (where 15% do, neighbouring regions under "
            "2.94 join them, then any with 4 merged among its 6 nearest), or where 4.6% do "
            "and all the offsets read a kurtosis 3 standard errors under 3 (then the "
            "neighbours join them too); and where the noise reads "
            "wider than 1.05 spacings, or where the layers lie 4 deviations apart or more "
            "(not at a thin part's rim), move outputs left between two output layers onto the "
            "layer nearer their input",
            "", "false"},
           [](O& o) -> bool& { return o.final_step.separate_merged_sides; }),
      Number("outlier_fraction", kBoth,
             {kOutliers,
              "outlier score (1 - the support-weighted fitting line processes the planes of "
              "N(i) u {i} give q_i) at which i is an outlier",
              "", "0.9"},
             [](O& o) -> double& { return o.final_step.outlier_fraction; }),
      Number("local_noise_ratio", kBoth,
             {kOutliers,
              "each plane scores points against its region's noise: where the region's "
              "residual scale is at least 1.5x the median region's and the region is as dense "
              "as the surface, its line process widens by that ratio, up to this (1: the "
              "global mu_l only)",
              "", "1"},
             [](O& o) -> double& { return o.final_step.local_noise_ratio; }),
      Number("feature_threshold", kBoth, {kFinal, "m_ij below this counts as a feature vote"},
             [](O& o) -> double& { return o.final_step.feature_line_threshold; }),
      Number("feature_fraction", kBoth,
             {kFinal, "share of feature votes above which i is a feature point", "", "0.7"},
             [](O& o) -> double& { return o.final_step.feature_fraction; }),
      Choice(
          "outliers", Kind::kChoice, kBoth,
          {kOutliers,
           "remove (the flagged points are left out of the output) or mark (every point is in "
           "the output; flagged ones keep their input position, with outlier = 1 and their "
           "score, as PDAL's outlier filter marks them)"},
          [](const O& o) { return std::string(o.mark_outliers ? "mark" : "remove"); },
          [](const std::string& text, O& o) {
            if (text != "remove" && text != "mark") {
              ThrowUnknownChoice("outliers", text, "remove, mark");
            }
            o.mark_outliers = text == "mark";
          }),
      Flag("remove_outliers", kBoth,
           {kOutliers,
            "false: nothing is removed or marked, and no further pass or isolation test runs "
            "(the flagged points stay in the output, denoised like the others)"},
           [](O& o) -> bool& { return o.final_step.remove_outliers; }),
      Number("max_removed_fraction", kBoth,
             {kOutliers, "keep all points (and say so) if more than this share is flagged"},
             [](O& o) -> double& { return o.final_step.max_removed_fraction; }),
      Integer("outlier_passes", kBoth,
              {kOutliers,
               "denoising passes at most: while a pass removes more than "
               "outlier_rerun_fraction of its points, the kept points are denoised again from "
               "their input coordinates",
               "", "1"},
              [](O& o) -> int& { return o.final_step.outlier_passes; }),
      Number("outlier_rerun_fraction", kBoth,
             {kOutliers, "share of removed points above which another pass runs"},
             [](O& o) -> double& { return o.final_step.rerun_removed_fraction; }),
      Number("isolation_factor", kBoth,
             {kOutliers,
              "after the passes, a kept point whose isolation_neighbors-th nearest kept point "
              "is farther than this many times the median such distance, over all kept points "
              "and over its own neighbours, is an outlier (0: off)",
              "", "0"},
             [](O& o) -> double& { return o.final_step.isolation.radius_factor; }),
      Number("far_factor", kBoth,
             {kOutliers,
              "before anything else, a point farther from the cloud's median than this many "
              "times the radius that holds 98% of the points is a stray point: an outlier, "
              "kept out of the frame, the noise estimate and k (0: off)",
              "", "0"},
             [](O& o) -> double& { return o.far_points.factor; }),
      Flag("merge_duplicates", kBoth,
           {kOutliers,
            "before anything else, points with identical coordinates are solved as one and "
            "every copy takes its result (a repeated point is no new sample of the surface); "
            "so are points within a tenth of a spacing of an earlier one, where they are 5% "
            "of the cloud or more (each moved along the surface by its offset)",
            "", "false"},
           [](O& o) -> bool& { return o.merge_duplicates; }),
      Integer("isolation_neighbors", kBoth,
              {kOutliers, "the neighbour rank of isolation_factor's test"},
              [](O& o) -> int& { return o.final_step.isolation.neighbors; }),
      Flag("snap_features", kBoth,
           {kSnapping,
            "move feature points onto the intersection line of the two DBSCAN clusters of "
            "their neighbours' planes t_j"},
           [](O& o) -> bool& { return o.final_step.snap_features; }),
      Number("snap_cluster_angle_deg", kBoth,
             {kSnapping,
              "DBSCAN radius: neighbouring planes whose normals are at most this many degrees "
              "apart are close"},
             [](O& o) -> double& { return o.final_step.snapping.cluster_angle_deg; }),
      Integer("snap_min_cluster_planes", kBoth,
              {kSnapping,
               "DBSCAN density: planes within the radius (itself included) that make a core "
               "plane"},
              [](O& o) -> int& { return o.final_step.snapping.min_cluster_planes; }),
  };
}

// mu_m as an angle: a second spelling of mu_m, never saved or listed as a column.
Parameter MuMAngle() {
  return Choice(
      "mu_m_deg", Kind::kNumber, Scope::kBoth,
      {"energy (Eq. 5, Table 2)",
       "mu_m = 1 - cos(angle) from an angle in degrees in (0, 180) (30 gives 0.134); another "
       "spelling of mu_m"},
      [](const DenoiseOptions& o) {
        return ExactText(std::acos(1.0 - o.settings.energy.mu_m) * 180.0 / M_PI);
      },
      [](const std::string& text, DenoiseOptions& o) {
        const double angle = ParseNumber("mu_m_deg", text, "a number");
        if (!(angle > 0.0 && angle < 180.0)) {
          throw std::invalid_argument("parameter mu_m_deg must be in (0, 180), got " + text);
        }
        o.settings.energy.mu_m = 1.0 - std::cos(angle * M_PI / 180.0);
      });
}

const std::vector<Parameter>& Parameters() {
  static const std::vector<Parameter> parameters = [] {
    std::vector<Parameter> all;
    for (auto group : {ProblemAndEnergyParameters, AlternatingParameters,
                       JointSolveParameters, FinalStepParameters}) {
      for (Parameter& parameter : group()) all.push_back(std::move(parameter));
    }
    all.push_back(MuMAngle());
    return all;
  }();
  return parameters;
}

const Parameter& Find(const std::string& name) {
  for (const Parameter& parameter : Parameters()) {
    if (parameter.info.name == name) return parameter;
  }
  throw std::invalid_argument("unknown parameter '" + name + "'");
}

}  // namespace

const std::vector<ParameterInfo>& DenoiseParameters() {
  static const std::vector<ParameterInfo> infos = [] {
    std::vector<ParameterInfo> list;
    for (const Parameter& parameter : Parameters()) list.push_back(parameter.info);
    return list;
  }();
  return infos;
}

const std::vector<std::string>& DenoiseParameterNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const Parameter& parameter : Parameters()) {
      if (parameter.info.name != "mu_m_deg") list.push_back(parameter.info.name);
    }
    return list;
  }();
  return names;
}

const ParameterInfo& FindDenoiseParameter(const std::string& name) { return Find(name).info; }

bool DenoiseParameterApplies(const std::string& name, Solver solver) {
  const Scope scope = Find(name).info.scope;
  return scope == Scope::kBoth ||
         scope == (solver == Solver::kCeres ? Scope::kCeres : Scope::kAlternating);
}

void SetDenoiseParameter(const std::string& name, const std::string& text,
                         DenoiseOptions* options) {
  const Parameter& parameter = Find(name);
  if (parameter.set_choice) {
    parameter.set_choice(text, *options);
  } else if (parameter.flag) {
    if (text == "true" || text == "1") {
      parameter.flag(*options) = true;
    } else if (text == "false" || text == "0") {
      parameter.flag(*options) = false;
    } else {
      throw std::invalid_argument("parameter " + name + ": '" + text + "' is not true or false");
    }
  } else if (parameter.number) {
    parameter.number(*options) = ParseNumber(name, text, "a number");
  } else {
    parameter.integer(*options) = ParseInteger(name, text, "an integer");
  }
}

std::string GetDenoiseParameter(const std::string& name, const DenoiseOptions& options) {
  const Parameter& parameter = Find(name);
  if (parameter.get_choice) return parameter.get_choice(options);
  DenoiseOptions copy = options;  // the accessors hand out mutable references
  if (parameter.flag) return parameter.flag(copy) ? "true" : "false";
  if (parameter.number) return ExactText(parameter.number(copy));
  return std::to_string(parameter.integer(copy));
}

void RefuseConflictingParameters(
    const std::vector<std::pair<std::string, std::string>>& given) {
  static const std::pair<const char*, const char*> kConflicts[] = {
      {"eta", "fit_balance"},         {"lambda", "smoothing_balance"},
      {"mu_l", "mu_l_noise_sigmas"},  {"mu_m", "mu_m_deg"},
      {"k", "k_radius_sigmas"},       {"k", "max_k"},
      {"k", "max_problem_size"},      {"k", "k_wide_noise"},
  };
  // The value of `name` among `given`, or nullptr.
  auto value_of = [&given](const char* name) -> const std::string* {
    for (const auto& [given_name, value] : given) {
      if (given_name == name) return &value;
    }
    return nullptr;
  };
  for (const auto& [first, second] : kConflicts) {
    const std::string* first_value = value_of(first);
    if (first_value && *first_value != "auto" && value_of(second)) {
      throw std::invalid_argument(std::string("give either ") + first + " or " + second +
                                  ", not both (" + second + " only acts when " + first +
                                  " is auto)");
    }
  }
}

}  // namespace lpd
