#include "python/native/survey_parts.h"

#include "core/method/adaptive_filter.h"
#include "core/method/slope_survey.h"
#include "io/read/dem_reader.h"
#include "python/native/band_runs.h"

namespace tsk::python {
namespace {

// Reads `w` of the DEM after checking that it lies in it (windows come from another machine).
std::vector<float> read_window(const TaskDem& dem, const SurveyWindow& w) {
  const DemGrid& grid = dem.source().grid;
  const auto [row0, col0, rows, cols] = w;
  if (rows == 0 || cols == 0 || row0 > grid.rows || rows > grid.rows - row0 || col0 > grid.cols ||
      cols > grid.cols - col0)
    throw Error("the survey's window of " + std::to_string(rows) + " x " + std::to_string(cols) +
                " cells at row " + std::to_string(row0) + ", column " + std::to_string(col0) +
                " does not lie in the DEM's " + std::to_string(grid.rows) + " x " +
                std::to_string(grid.cols));
  std::vector<float> heights(rows * cols);
  dem.source().read({row0, col0, rows, cols}, heights.data());
  return heights;
}

}  // namespace

std::vector<SurveyWindow> survey_windows_of(const std::string& input,
                                            const std::vector<std::string>& options) {
  const TaskDem dem(input, band_options(options));
  std::vector<SurveyWindow> windows;
  for (const DemWindow& w : survey_windows(dem.source().grid.rows, dem.source().grid.cols))
    windows.push_back({w.row0, w.col0, w.rows, w.cols});
  return windows;
}

std::string survey_heights_part(const std::string& input, const std::vector<std::string>& options,
                                const std::vector<SurveyWindow>& windows) {
  const TaskDem dem(input, band_options(options));
  HeightStepPart part;
  for (const SurveyWindow& w : windows) {
    const std::vector<float> heights = read_window(dem, w);
    part.add(heights.data(), heights.size());
  }
  return SurveyBytes::of(part);
}

std::string merge_height_parts(const std::vector<std::string>& parts) {
  HeightStepPart merged;
  for (const std::string& part : parts) merged.merge(SurveyBytes::height_step(part));
  return SurveyBytes::of(merged);
}

std::string survey_slopes_part(const std::string& input, const std::vector<std::string>& options,
                               const std::vector<SurveyWindow>& windows,
                               const std::string& heights) {
  const TaskDem dem(input, band_options(options));
  const double tolerance = SurveyBytes::height_step(heights).step().tolerance;
  const DemGrid& grid = dem.source().grid;
  SlopePart part;
  for (const SurveyWindow& w : windows) {
    const std::vector<float> z = read_window(dem, w);
    part.add(z.data(), {w[0], w[1], w[2], w[3]}, grid.dx, grid.dy, tolerance);
  }
  return SurveyBytes::of(part);
}

std::string filter_of_survey(const std::vector<std::string>& options, const std::string& heights,
                             const std::vector<std::string>& slope_parts) {
  const cli::Options o = band_options(options);
  SlopePart slopes;
  for (const std::string& part : slope_parts) slopes.merge(SurveyBytes::slopes(part));
  const SlopeSurvey survey = slopes.survey(SurveyBytes::height_step(heights).step());
  return filter_report_bytes(report_of_survey(o.params, survey));
}

}  // namespace tsk::python
