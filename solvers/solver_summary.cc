#include "solvers/solver_summary.h"

#include <cstdio>
#include <sstream>

namespace lpd::solvers {

const char* TerminationTypeName(TerminationType type) {
  switch (type) {
    case TerminationType::kConvergence: return "CONVERGENCE";
    case TerminationType::kNoConvergence: return "NO_CONVERGENCE";
    case TerminationType::kUserAbort: return "USER_ABORT";
    case TerminationType::kFailure: return "FAILURE";
  }
  return "UNKNOWN";
}

bool SolverSummary::IsSolutionUsable() const {
  return termination == TerminationType::kConvergence ||
         termination == TerminationType::kNoConvergence ||
         termination == TerminationType::kUserAbort;
}

std::string SolverSummary::BriefReport() const {
  char line[256];
  std::snprintf(line, sizeof(line), "%s after %d iterations, energy %.6e, %.3f s (%s)",
                TerminationTypeName(termination), num_iterations, final_energy.total(),
                total_seconds, message.c_str());
  return line;
}

std::string SolverSummary::FullReport() const {
  std::ostringstream out;
  out << BriefReport() << "\n";
  if (steps.empty()) {
    out << "iter       fitting    smoothness     stitching         total   seconds  elapsed  cg\n";
    for (const IterationRecord& record : iterations) {
      char line[256];
      std::snprintf(line, sizeof(line), "%4d %13.6e %13.6e %13.6e %13.6e %9.4f %8.3f %3d\n",
                    record.iteration, record.energy.fitting, record.energy.smoothness,
                    record.energy.stitching, record.energy.total(), record.seconds,
                    record.elapsed_seconds, record.cg_iterations);
      out << line;
    }
    return out.str();
  }
  out << "iter inner block       fitting    smoothness     stitching         total   seconds  cg\n";
  for (const StepRecord& step : steps) {
    char line[256];
    std::snprintf(line, sizeof(line), "%4d %5d %5s %13.6e %13.6e %13.6e %13.6e %9.4f %3d\n",
                  step.iteration, step.inner_iteration, step.block.c_str(),
                  step.energy.fitting, step.energy.smoothness, step.energy.stitching,
                  step.energy.total(), step.seconds, step.cg_iterations);
    out << line;
  }
  return out.str();
}

}  // namespace lpd::solvers
