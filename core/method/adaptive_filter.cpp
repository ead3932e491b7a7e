#include "core/method/adaptive_filter.h"

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"
#include "core/method/slope_scale_map.h"

namespace tsk {

double filter_scale(double median_slope_pct) {
  if (!std::isfinite(median_slope_pct)) return kLowestScale;  // every cell flat
  return std::clamp(median_slope_pct / kReferenceSlopePct, kLowestScale, kHighestScale);
}

namespace {

FilterParams scaled(const FilterParams& filter, double scale) {
  FilterParams out = filter;
  out.row_cut_pct *= scale;
  out.col_cut_pct *= scale;
  out.ctrl_col_pct *= scale;
  return out;
}

}  // namespace

ResolvedParams::ResolvedParams(const SilhouetteParams& fixed) : params_(fixed) {
  fixed.validate();
  if (fixed.adaptive.mode != FilterMode::fixed)
    throw Error("an adaptive filter is resolved on the DEM it runs on (adapt_filter)");
  filter_.choice = fixed.adaptive;
  filter_.cutoffs = fixed.filter;
  filter_.heights.tolerance = fixed.height_tolerance;
}

FilterReport report_of_survey(const SilhouetteParams& choice, const SlopeSurvey& survey) {
  FilterReport report;
  report.choice = choice.adaptive;
  report.median_slope_pct = survey.median_slope_pct;
  report.heights = survey.heights;
  report.scale = filter_scale(survey.median_slope_pct);
  report.cutoffs = scaled(choice.filter, report.scale);
  return report;
}

ResolvedParams adapt_filter(const SilhouetteParams& choice, const DemGrid& grid,
                            const WindowReader& read, const WindowReader& alongside) {
  if (choice.adaptive.mode == FilterMode::fixed) return ResolvedParams(choice);
  choice.validate();
  if (!read) throw Error("an adaptive filter needs the DEM to survey");
  const SlopeSurvey survey =
      survey_slopes(grid.rows, grid.cols, grid.dx, grid.dy, read, choice.threads, alongside);
  FilterReport report = report_of_survey(choice, survey);
  SilhouetteParams out = choice;
  out.adaptive.mode = FilterMode::fixed;  // resolved: the stages take the cut-offs as they are
  out.height_tolerance = survey.heights.tolerance;
  if (choice.adaptive.adapt == Adaptivity::whole) {
    out.filter = report.cutoffs;
    return ResolvedParams(std::move(out), std::move(report));
  }
  // Local: the stages divide each cell's slopes by its neighbourhood's scale and keep the
  // cut-offs asked for.
  auto map = std::make_shared<SlopeScaleMap>(map_slope_scales(
      grid.rows, grid.cols, grid.dx, grid.dy, static_cast<std::size_t>(choice.adaptive.window),
      survey.heights.tolerance, filter_scale, report.scale, read));
  report.local_lowest = map->lowest();
  report.local_highest = map->highest();
  out.local_scale = std::move(map);
  return ResolvedParams(std::move(out), std::move(report));
}

ResolvedParams resolve_as_reported(const SilhouetteParams& choice, const FilterReport& report) {
  choice.validate();
  const AdaptiveParams& asked = choice.adaptive;
  if (asked.mode != report.choice.mode || asked.adapt != report.choice.adapt)
    throw Error("the filter's report is of another choice than this run's");
  if (asked.mode == FilterMode::fixed) return ResolvedParams(choice);
  if (asked.adapt == Adaptivity::local)
    throw Error("local adaptivity needs the map of the whole DEM's scales on every machine");
  SilhouetteParams out = choice;
  out.adaptive.mode = FilterMode::fixed;
  out.height_tolerance = report.heights.tolerance;
  out.filter = report.cutoffs;
  return ResolvedParams(std::move(out), report);
}

}  // namespace tsk
