#include "experiments/commands.h"
#include <stdexcept>
namespace lpd::experiments {
int RunSweepCommand(const std::vector<std::string>&) { throw std::runtime_error("todo"); }
}
