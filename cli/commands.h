// The commands of the command line, one file each. Each takes its arguments (without its own
// name), writes what it did on `out` and notes on `err`, and returns the run's stage statistics
// as JSON (--stats-json's text; empty from the commands that count none); it throws Error for the
// user and Cancelled when interrupted.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/base/parallel.h"

namespace tsk::cli {

using Args = std::vector<std::string>;

std::string silhouettes(const Args& args, std::ostream& out, std::ostream& err,
                        const ProgressFn& progress);
std::string classify(const Args& args, std::ostream& out, std::ostream& err,
                     const ProgressFn& progress);
std::string row_slope(const Args& args, std::ostream& out, std::ostream& err,
                      const ProgressFn& progress);
std::string profiles(const Args& args, std::ostream& out, std::ostream& err,
                     const ProgressFn& progress);
std::string pstrokes(const Args& args, std::ostream& out, std::ostream& err,
                     const ProgressFn& progress);
std::string drape(const Args& args, std::ostream& out, std::ostream& err,
                  const ProgressFn& progress);
std::string panorama(const Args& args, std::ostream& out, std::ostream& err,
                     const ProgressFn& progress);
std::string filter_plot(const Args& args, std::ostream& out, std::ostream& err,
                        const ProgressFn& progress);

}  // namespace tsk::cli
