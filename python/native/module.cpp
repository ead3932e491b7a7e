// terrain_sketch._native: the Python package's door into the commands (cli_app.h) and the sketch
// of an array (array_sketch.h). The package's Python side turns keyword options into the
// command line's, so that both take the same options, defaults, checks and messages.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_app.h"
#include "cli/option_table.h"
#include "python/native/array_sketch.h"
#include "python/native/band_runs.h"
#include "python/native/python_run.h"
#include "python/native/survey_parts.h"

namespace tsk::python {
namespace {

using Strings = std::vector<std::string>;

// Runs a command; returns what it said of its outputs and its statistics as JSON.
std::pair<std::string, std::string> run_command(const std::string& name, const Strings& args,
                                                const RunHooks& hooks) {
  std::ostringstream said;
  std::string statistics;
  run_from_python(hooks, [&](const ProgressFn& progress, std::ostream& err) {
    statistics = cli::run_command(name, args, said, err, progress);
  });
  return {said.str(), statistics};
}

// The GDAL type of a numpy array's values, or GDT_Unknown for one GDAL does not hold as such.
GDALDataType gdal_type(const py::dtype& type) {
  const char kind = type.kind();
  const auto size = type.itemsize();
  if (kind == 'f') return size == 4 ? GDT_Float32 : size == 8 ? GDT_Float64 : GDT_Unknown;
  if (kind == 'i') return size == 2 ? GDT_Int16 : size == 4 ? GDT_Int32 : GDT_Unknown;
  if (kind == 'u') {
    return size == 1 ? GDT_Byte : size == 2 ? GDT_UInt16 : size == 4 ? GDT_UInt32 : GDT_Unknown;
  }
  return GDT_Unknown;
}

io::MemoryBand memory_band(const py::array& heights) {
  if (heights.ndim() != 2) throw py::value_error("heights must be a 2-D array (rows, columns)");
  if (heights.shape(0) == 0 || heights.shape(1) == 0) {
    throw py::value_error("heights must have a row and a column at least, got " +
                          std::to_string(heights.shape(0)) + " x " +
                          std::to_string(heights.shape(1)));
  }
  const GDALDataType type = gdal_type(heights.dtype());
  if (type == GDT_Unknown || heights.strides(0) <= 0 || heights.strides(1) <= 0)
    throw py::value_error("internal: heights must come as a native array of a GDAL type");
  return {heights.data(),
          type,
          static_cast<std::size_t>(heights.shape(0)),
          static_cast<std::size_t>(heights.shape(1)),
          static_cast<std::size_t>(heights.strides(1)),
          static_cast<std::size_t>(heights.strides(0))};
}

template <typename T>
py::array_t<T> numpy_copy(const std::vector<T>& values) {
  return py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
}

py::dict columns_to_python(const StrokeColumns& c) {
  py::dict columns;
  columns["class"] = c.classes;
  columns["cells"] = numpy_copy(c.cells);
  for (std::size_t k = 0; k < c.real_names.size(); ++k)
    columns[py::str(c.real_names[k])] = numpy_copy(c.reals[k]);
  py::dict result;
  result["x"] = numpy_copy(c.x);
  result["y"] = numpy_copy(c.y);
  result["m"] = c.measured ? py::object(numpy_copy(c.m)) : py::none();
  result["offsets"] = numpy_copy(c.offsets);
  result["columns"] = columns;
  result["crs"] = c.crs_wkt;
  result["statistics"] = c.statistics;
  return result;
}

// GDAL's six numbers of an array's transform, checked: a NaN origin drew nothing and blamed
// short chains.
GeoTransform transform_of(const py::object& numbers) {
  const auto values = numbers.cast<std::vector<double>>();
  if (values.size() != 6) throw py::value_error("transform needs 6 numbers (GDAL's order)");
  for (const double v : values)
    if (!std::isfinite(v))
      throw py::value_error("transform holds " + std::to_string(v) +
                            ": its 6 numbers (GDAL's order) must be finite");
  if (values[2] != 0.0 || values[4] != 0.0)
    throw py::value_error(
        "transform is rotated or sheared (its 3rd or 5th number is not 0): resample the array "
        "north-up first");
  if (values[1] == 0.0 || values[5] == 0.0)
    throw py::value_error(
        "transform gives cells of no width or height (its 2nd or 6th number is 0)");
  GeoTransform gt;
  std::copy(values.begin(), values.end(), gt.a.begin());
  return gt;
}

// Sketches `heights` (kept alive by the caller while the run reads it).
py::dict sketch(const py::array& heights, const py::object& geotransform, const std::string& crs,
                const py::object& nodata, const Strings& options, const RunHooks& hooks) {
  const io::MemoryBand band = memory_band(heights);
  io::MemoryRasterInfo info;
  info.crs = crs;
  if (!geotransform.is_none()) info.geotransform = transform_of(geotransform);
  if (!nodata.is_none()) info.nodata = nodata.cast<double>();
  StrokeColumns columns;
  run_from_python(hooks, [&](const ProgressFn& progress, std::ostream& err) {
    columns = sketch_array(band, info, options, progress, err);
  });
  return columns_to_python(columns);
}

// Runs `work` as a run from Python without hooks: the GIL released, errors raised as Python's.
// Returns what `work` returns.
template <typename Work>
auto quietly(Work&& work) {
  decltype(work()) result{};
  run_from_python(RunHooks{py::none(), py::none(), false},
                  [&](const ProgressFn&, std::ostream&) { result = work(); });
  return result;
}

py::dict plan_run_in_bands(const std::string& input, const std::string& output,
                           const Strings& options, const RunHooks& hooks) {
  BandPlan plan;
  run_from_python(hooks, [&](const ProgressFn&, std::ostream& err) {
    plan = tsk::python::plan_bands(input, output, options, err);
  });
  py::dict result;
  result["profiles"] = plan.profiles;
  result["filter"] = py::bytes(plan.filter);
  result["survey"] = plan.survey;
  result["oblique"] = plan.oblique;
  result["dem_rows"] = plan.dem_rows;
  return result;
}

// The adaptive filter's survey in parts (survey_parts.h).
std::vector<SurveyWindow> windows_of_survey(const std::string& input, const Strings& options) {
  return quietly([&] { return survey_windows_of(input, options); });
}

py::bytes heights_of_survey(const std::string& input, const Strings& options,
                            const std::vector<SurveyWindow>& windows) {
  return py::bytes(quietly([&] { return survey_heights_part(input, options, windows); }));
}

py::bytes merge_survey_heights(const Strings& parts) {
  return py::bytes(quietly([&] { return merge_height_parts(parts); }));
}

py::bytes slopes_of_survey(const std::string& input, const Strings& options,
                           const std::vector<SurveyWindow>& windows, const std::string& heights) {
  return py::bytes(quietly([&] { return survey_slopes_part(input, options, windows, heights); }));
}

py::bytes filter_from_survey(const Strings& options, const std::string& heights,
                             const Strings& slopes) {
  return py::bytes(quietly([&] { return filter_of_survey(options, heights, slopes); }));
}

// A band's bytes lent to Python through the buffer protocol: memoryview(band) reads them where
// they lie, and Dask sends a memoryview without copying it.
struct BandBuffer {
  std::string bytes;
};

BandBuffer sketch_one_band(const std::string& input, const Strings& options,
                           const std::string& filter, double z_ref, std::size_t first,
                           std::size_t count, std::size_t halo, const std::string& order) {
  return {quietly(
      [&] { return sketch_band_bytes(input, options, filter, z_ref, first, count, halo, order); })};
}

// A band's bytes where Python holds them (bytes, a memoryview, a BandBuffer), without a copy;
// called with the interpreter's lock held, and the bytes are let go under it.
BandBytes held_band(const py::object& band) {
  auto view = std::make_unique<Py_buffer>();
  if (PyObject_GetBuffer(band.ptr(), view.get(), PyBUF_SIMPLE) != 0) throw py::error_already_set();
  const std::string_view bytes(static_cast<const char*>(view->buf),
                               static_cast<std::size_t>(view->len));
  std::shared_ptr<Py_buffer> owner(view.release(), [](Py_buffer* held) {
    py::gil_scoped_acquire lock;
    PyBuffer_Release(held);
    delete held;
  });
  return {std::move(owner), bytes};
}

// What a band's bytes hold: its strokes, and the pieces of chains crossing its edges with their
// cells and the bytes those take (for the benchmark of runs in bands).
py::dict band_summary(const py::object& bytes) {
  const BandBytes held = held_band(bytes);
  const BandSketch band = quietly([&] { return band_from_bytes(held.bytes); });
  std::size_t cells = 0;
  for (const BandPiece& piece : band.pieces) cells += piece.cells.size();
  std::size_t drawn = 0;
  for (const DrawnGroup& group : band.drawn) drawn += group.strokes.size();
  py::dict summary;
  summary["strokes"] = band.strokes.size();
  summary["drawn_strokes"] = drawn;
  summary["pieces"] = band.pieces.size();
  summary["piece_cells"] = cells;
  // As band_bytes writes them: each piece's class, ends and count of cells, then its cells.
  constexpr std::size_t kPieceHeader = sizeof(StrokeClass) + 3 * sizeof(std::uint64_t);
  summary["piece_bytes"] = cells * sizeof(StrokeCell) + band.pieces.size() * kPieceHeader;
  return summary;
}

double lowest_height(const std::string& input, const Strings& options, std::size_t first_row,
                     std::size_t rows) {
  return quietly([&] { return lowest_height_of(input, options, first_row, rows); });
}

// Stitches the bands that `next()` hands back and writes OUTPUT (band_runs.h).
std::string stitch(const std::string& input, const std::string& output, const Strings& options,
                   const std::string& filter, double z_ref, std::size_t profiles,
                   const py::object& next, const py::object& again, const RunHooks& hooks) {
  // Called from the run, the interpreter's lock released: each call takes it.
  const BandSource bands{[&next] {
                           py::gil_scoped_acquire lock;
                           return held_band(next());
                         },
                         [&again](std::size_t first, std::size_t count, const std::string& order) {
                           py::gil_scoped_acquire lock;
                           return held_band(again(first, count, py::bytes(order)));
                         }};
  std::string statistics;
  run_from_python(hooks, [&](const ProgressFn&, std::ostream& err) {
    statistics = stitch_bands(input, output, options, filter, z_ref, profiles, bands, err);
  });
  return statistics;
}

py::list option_list() {
  py::list options;
  for (const cli::OptionSpec& spec : cli::option_table()) {
    py::list commands;
    for (const cli::CommandSpec& command : cli::command_table())
      if (spec.commands & command.bit) commands.append(command.name);
    options.append(py::dict(
        py::arg("name") = spec.name,
        py::arg("value") = spec.value ? py::object(py::str(spec.value)) : py::object(py::none()),
        py::arg("section") = spec.section, py::arg("help") = spec.help,
        py::arg("commands") = commands));
  }
  return options;
}

py::list command_list() {
  py::list commands;
  for (const cli::CommandSpec& spec : cli::command_table())
    commands.append(py::dict(py::arg("name") = spec.name, py::arg("summary") = spec.summary));
  return commands;
}

}  // namespace
}  // namespace tsk::python

PYBIND11_MODULE(_native, m) {
  namespace py = pybind11;
  using namespace tsk::python;
  m.doc() = "Terrain Sketch's native door: the commands and the sketch of an array.";
  py::class_<RunHooks>(m, "RunHooks")
      .def(py::init<py::object, py::object, bool>(), py::arg("progress"), py::arg("log"),
           py::arg("catch_interrupts"));
  m.def("run_command", &run_command, py::arg("name"), py::arg("args"), py::arg("hooks"));
  m.def("sketch", &sketch, py::arg("heights"), py::arg("transform"), py::arg("crs"),
        py::arg("nodata"), py::arg("options"), py::arg("hooks"));
  m.def("plan_bands", &plan_run_in_bands, py::arg("input"), py::arg("output"), py::arg("options"),
        py::arg("hooks"));
  py::class_<BandBuffer>(m, "BandBuffer", py::buffer_protocol()).def_buffer([](BandBuffer& band) {
    return py::buffer_info(band.bytes.data(), 1, py::format_descriptor<std::uint8_t>::format(),
                           static_cast<py::ssize_t>(band.bytes.size()), true);
  });
  m.def("sketch_band", &sketch_one_band, py::arg("input"), py::arg("options"), py::arg("filter"),
        py::arg("z_ref"), py::arg("first"), py::arg("count"), py::arg("halo"), py::arg("order"));
  m.def("band_summary", &band_summary, py::arg("band"));
  m.def("survey_windows", &windows_of_survey, py::arg("input"), py::arg("options"));
  m.def("survey_heights", &heights_of_survey, py::arg("input"), py::arg("options"),
        py::arg("windows"));
  m.def("merge_heights", &merge_survey_heights, py::arg("parts"));
  m.def("survey_slopes", &slopes_of_survey, py::arg("input"), py::arg("options"),
        py::arg("windows"), py::arg("heights"));
  m.def("survey_filter", &filter_from_survey, py::arg("options"), py::arg("heights"),
        py::arg("slopes"));
  m.def("lowest_height", &lowest_height, py::arg("input"), py::arg("options"), py::arg("first_row"),
        py::arg("rows"));
  m.def("stitch_bands", &stitch, py::arg("input"), py::arg("output"), py::arg("options"),
        py::arg("filter"), py::arg("z_ref"), py::arg("profiles"), py::arg("next"), py::arg("again"),
        py::arg("hooks"));
  m.def("options", &option_list);
  m.def("commands", &command_list);
  m.attr("version") = TSK_VERSION;
}
