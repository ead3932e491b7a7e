// The terrain-sketch command line, callable in-process for tests.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace tsk::cli {

// Runs `terrain-sketch ARGS...` (args without the program name). Returns the exit code:
// 0 success, 1 failure (message on err), 2 bad usage, 130 interrupted (see interrupt.h; nothing
// written). With show_progress, the work done goes on err as GDAL's tools show it.
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
        bool show_progress = false);

}  // namespace tsk::cli
