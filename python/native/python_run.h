// What a run called from Python needs around it: the interpreter's lock released while the core
// works, progress and notes handed to Python callables (under the lock), Ctrl-C caught as
// KeyboardInterrupt, and the run's exceptions raised as Python's, with the command line's words.
#pragma once

#include <pybind11/pybind11.h>

#include <exception>
#include <functional>
#include <optional>
#include <ostream>

#include "core/base/parallel.h"

namespace tsk::python {

namespace py = pybind11;

// The Python side of a run: `progress(fraction)` (None, or a callable whose False stops the run),
// `log(line)` (a callable taking each line of notes), and whether to catch SIGINT (only from
// Python's main thread, where the interpreter's own handler would wait for the run to end).
struct RunHooks {
  py::object progress;
  py::object log;
  bool catch_interrupts = false;
};

// Runs `work(progress, err)` with the interpreter's lock released, and raises its failure as
// Python's: UsageError as ValueError, the run's Errors as terrain_sketch.Error (an OSError,
// terrain_sketch/_errors.py),
// Cancelled as KeyboardInterrupt (SIGINT), as the progress callable's own exception, or as
// terrain_sketch.Cancelled (the callable's False).
void run_from_python(const RunHooks& hooks,
                     const std::function<void(const ProgressFn&, std::ostream&)>& work);

}  // namespace tsk::python
