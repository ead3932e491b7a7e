// The commands of the command line, one file each. Each takes its arguments (without its own
// name), writes what it did on `out` and notes on `err`, and returns the exit code; it throws
// Error for the user and Cancelled when interrupted.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/base/parallel.h"

namespace tsk::cli {

using Args = std::vector<std::string>;

int silhouettes(const Args& args, std::ostream& out, std::ostream& err, const ProgressFn& progress);
int classify(const Args& args, std::ostream& out, std::ostream& err, const ProgressFn& progress);
int row_slope(const Args& args, std::ostream& out, std::ostream& err, const ProgressFn& progress);
int profiles(const Args& args, std::ostream& out, std::ostream& err, const ProgressFn& progress);
int pstrokes(const Args& args, std::ostream& out, std::ostream& err, const ProgressFn& progress);
int drape(const Args& args, std::ostream& out, std::ostream& err, const ProgressFn& progress);
int panorama(const Args& args, std::ostream& out, std::ostream& err, const ProgressFn& progress);
int filter_plot(const Args& args, std::ostream& out, std::ostream& err, const ProgressFn& progress);

}  // namespace tsk::cli
