// The terrain-sketch command line, callable in-process for tests.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/base/parallel.h"

namespace tsk::cli {

// Runs the command `name` (as typed: "row-slope") on `args` (without the names of the program and
// the command): what every front end of the commands calls (the program, and the Python
// package). Its outputs go in place together when it has done (io/write/output_set.h), and what
// it says of them goes on `out` only then; its notes go on `err` as they come (a run that must
// wait for another writing one of its outputs says so, and a signal ends the wait). Returns the
// run's stage statistics as JSON (empty from the commands that count none). Throws Error (bad
// options or input, named; io::DemRefused for a DEM that cannot be taken as it is) and Cancelled
// (a signal, interrupt.h, or `progress`'s no), with nothing written.
std::string run_command(const std::string& name, const std::vector<std::string>& args,
                        std::ostream& out, std::ostream& err, const ProgressFn& progress = {});

// Runs `terrain-sketch ARGS...` (args without the program name). Returns the exit code:
// 0 success, 1 failure (message on err), 2 bad usage, 130 interrupted (see interrupt.h; nothing
// written). With show_progress, the work done goes on err as GDAL's tools show it.
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
        bool show_progress = false);

}  // namespace tsk::cli
