// The terrain-sketch command line, callable in-process for tests.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace tsk::cli {

// Runs `terrain-sketch ARGS...` (args without the program name). Returns the exit code:
// 0 success, 1 failure (message on err), 2 bad usage.
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace tsk::cli
