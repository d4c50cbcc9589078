#include "drivers/app/processor_name.hpp"

#include <fstream>

namespace ffp {

std::string processor_name(std::istream& cpuinfo) {
  const std::string key = "model name";
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind(key, 0) != 0) continue;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    const std::size_t first = line.find_first_not_of(" \t", colon + 1);
    const std::size_t last = line.find_last_not_of(" \t\r");
    if (first == std::string::npos || last < first) continue;
    return line.substr(first, last - first + 1);
  }
  return "unknown processor";
}

std::string this_processor() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  return processor_name(cpuinfo);
}

}  // namespace ffp
