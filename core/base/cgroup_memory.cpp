#include "core/base/cgroup_memory.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace tsk {
namespace {

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

// The limit a control file states: a number of bytes; "max", an unreadable file or anything else
// is no limit. (cgroup v1 states "none" as a number near 2^63, which is no limit either.)
double limit_in(const std::string& path) {
  std::ifstream file(path);
  std::string text;
  if (!(file >> text) || text.find_first_not_of("0123456789") != std::string::npos) return kNoLimit;
  const double bytes = std::strtod(text.c_str(), nullptr);
  return bytes > 0 ? bytes : kNoLimit;
}

// The least limit of `file` in the group `group` (a path from the hierarchy's root) and its
// ancestors, under `root`.
double least_limit_up(const std::string& root, std::string group, const std::string& file) {
  if (group.find("..") != std::string::npos) return kNoLimit;  // not a path to follow
  double least = kNoLimit;
  while (true) {
    while (!group.empty() && group.back() == '/') group.pop_back();
    least = std::min(least, limit_in(root + group + "/" + file));
    const std::size_t slash = group.rfind('/');
    if (group.empty() || slash == std::string::npos) return least;
    group.erase(slash);
  }
}

// Whether a v1 line's comma-separated controllers name `controller`.
bool names_controller(const std::string& controllers, const std::string& controller) {
  std::istringstream list(controllers);
  for (std::string name; std::getline(list, name, ',');)
    if (name == controller) return true;
  return false;
}

}  // namespace

double cgroup_memory_limit(const std::string& membership, const std::string& mount) {
  double least = kNoLimit;
  std::istringstream lines(membership);
  for (std::string line; std::getline(lines, line);) {
    // hierarchy-id:controllers:path; v2's line is "0::path".
    const std::size_t first = line.find(':');
    const std::size_t second = first == std::string::npos ? first : line.find(':', first + 1);
    if (second == std::string::npos) continue;
    const std::string id = line.substr(0, first);
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const std::string group = line.substr(second + 1);
    if (id == "0" && controllers.empty()) {
      least = std::min(least, least_limit_up(mount, group, "memory.max"));
      least = std::min(least, least_limit_up(mount + "/unified", group, "memory.max"));
    } else if (names_controller(controllers, "memory")) {
      least = std::min(least, least_limit_up(mount + "/memory", group, "memory.limit_in_bytes"));
    }
  }
  return least;
}

double this_process_memory_limit() {
  static const double limit = [] {
    std::ifstream file("/proc/self/cgroup");
    std::ostringstream text;
    text << file.rdbuf();
    return cgroup_memory_limit(text.str(), "/sys/fs/cgroup");
  }();
  return limit;
}

}  // namespace tsk
