#include "python/native/python_run.h"

#include <new>
#include <streambuf>
#include <string>

#include "cli/dem_note_text.h"
#include "cli/interrupt.h"
#include "cli/options.h"
#include "core/base/errors.h"

namespace tsk::python {
namespace {

// The package's exception `name` (terrain_sketch/_errors.py), looked up when raised: no Python
// object outlives the interpreter in a static.
py::object package_exception(const char* name) {
  return py::module_::import("terrain_sketch._errors").attr(name);
}

// Hands each whole line written to it to a Python callable, taking the interpreter's lock.
class LineLog : public std::streambuf {
 public:
  explicit LineLog(const py::object& log) : log_(log) {}
  ~LineLog() override { flush_line(); }
  void flush_line() {
    if (line_.empty()) return;
    py::gil_scoped_acquire lock;
    try {
      if (!log_.is_none()) log_(line_);
    } catch (py::error_already_set& e) {
      e.discard_as_unraisable("terrain_sketch: logging a note");
    }
    line_.clear();
  }

 protected:
  int_type overflow(int_type c) override {
    if (c == traits_type::eof()) return traits_type::not_eof(c);
    if (c == '\n') {
      flush_line();
    } else {
      line_.push_back(static_cast<char>(c));
    }
    return c;
  }

 private:
  const py::object& log_;
  std::string line_;
};

[[noreturn]] void raise(PyObject* type, const std::string& message) {
  PyErr_SetString(type, message.c_str());
  throw py::error_already_set();
}

[[noreturn]] void raise(const char* package_type, const std::string& message) {
  const py::object type = package_exception(package_type);
  raise(type.ptr(), message);
}

// Raises `failure` as Python's (see run_from_python).
[[noreturn]] void raise_failure(std::exception_ptr failure,
                                std::optional<py::error_already_set>& callback_error,
                                bool interrupted) {
  try {
    std::rethrow_exception(failure);
  } catch (const Cancelled&) {
    if (callback_error) throw *callback_error;
    if (interrupted)
      raise(PyExc_KeyboardInterrupt, "terrain_sketch: interrupted; no output written");
    raise("Cancelled", "the progress callable asked to stop; no output written");
  } catch (const cli::UsageError& e) {
    raise(PyExc_ValueError, e.what());
  } catch (const io::DemRefused& e) {
    raise("Error", cli::refusal_text(e));
  } catch (const Error& e) {
    raise("Error", e.what());
  } catch (const std::bad_alloc&) {
    raise(PyExc_MemoryError, "out of memory");
  } catch (py::error_already_set&) {
    throw;  // a Python callable's own exception
  } catch (const std::exception& e) {
    raise(PyExc_RuntimeError, std::string("unexpected failure: ") + e.what());
  }
}

}  // namespace

void run_from_python(const RunHooks& hooks,
                     const std::function<void(const ProgressFn&, std::ostream&)>& work) {
  std::optional<cli::InterruptScope> interrupts;
  if (hooks.catch_interrupts) interrupts.emplace();
  std::optional<py::error_already_set> callback_error;
  const ProgressFn progress = [&](double fraction) {
    if (cli::interrupted()) return false;
    if (hooks.progress.is_none()) return true;
    py::gil_scoped_acquire lock;
    if (callback_error) return false;
    try {
      const py::object answer = hooks.progress(fraction);
      const int truth = answer.is_none() ? 1 : PyObject_IsTrue(answer.ptr());
      if (truth < 0) throw py::error_already_set();
      return truth == 1;
    } catch (py::error_already_set& e) {
      callback_error = e;
      return false;
    }
  };
  LineLog lines(hooks.log);
  std::ostream err(&lines);
  std::exception_ptr failure;
  {
    py::gil_scoped_release released;
    try {
      work(progress, err);
    } catch (...) {
      failure = std::current_exception();
    }
    lines.flush_line();
  }
  if (failure) raise_failure(failure, callback_error, interrupts && cli::interrupted());
}

}  // namespace tsk::python
