#include "io/machine_info.h"

#include <unistd.h>

#include <fstream>
#include <thread>

namespace lpd::io {

std::string MachineDescription() {
  char host[256] = "unknown-host";
  gethostname(host, sizeof(host) - 1);
  std::string cpu = "unknown CPU";
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  }
  return std::string(host) + ", " + cpu + ", " +
         std::to_string(std::thread::hardware_concurrency()) + " cores";
}

}  // namespace lpd::io
