// The adaptive slope filter (docs/ADAPTIVE_FILTER.md): the thesis's cut-offs scaled by how steep
// the DEM's own terrain is, measured at its own cell size, against the terrain the thesis tuned
// them on; and slope tests that treat steps within the DEM's height quantum as flat.
#pragma once

#include <limits>
#include <utility>

#include "core/method/dem_windows.h"
#include "core/method/frame.h"
#include "core/method/params.h"
#include "core/method/slope_survey.h"

namespace tsk {

// The median slope of the terrain the thesis's cut-offs were tuned on: a dissected upland at
// 75 m cells. Measured on the sample DEM (the Jacksboro fault's plateau at 75 m, 23.9 %), the
// closest analogue of the thesis's South Wales DEM that we have.
inline constexpr double kReferenceSlopePct = 24.0;
// The scale is held within these: beyond them a DEM is all but flat, or all cliffs.
inline constexpr double kLowestScale = 1.0 / 16, kHighestScale = 4.0;

// The cut-offs' scale for terrain whose median slope is `median_slope_pct`.
double filter_scale(double median_slope_pct);

// What the filter of a run used, for the front ends to report.
struct FilterReport {
  AdaptiveParams choice;
  FilterParams cutoffs;  // the cut-offs used; with local adaptivity, the whole DEM's
  double scale = 1.0;    // cut-offs used over the cut-offs asked for
  double median_slope_pct = std::numeric_limits<double>::quiet_NaN();
  HeightStep heights;                              // fixed filter: none, SPEC's strict tests
  double local_lowest = 1.0, local_highest = 1.0;  // the range of the local scales
};

// The parameters one run of the stages takes, the filter resolved to the cut-offs the stages
// use, with the report of how. Only resolving makes them: adapt_filter() from any choice on the
// DEM, or the constructor from a fixed filter's (which refuses an adaptive one), so that no run
// starts with a filter it would not apply.
class ResolvedParams {
 public:
  ResolvedParams() : ResolvedParams(SilhouetteParams()) {}
  // Throws Error when `fixed` asks for an adaptive filter: that needs the DEM (adapt_filter).
  explicit ResolvedParams(const SilhouetteParams& fixed);
  const SilhouetteParams& params() const { return params_; }
  const SilhouetteParams* operator->() const { return &params_; }
  const FilterReport& filter() const { return filter_; }

 private:
  ResolvedParams(SilhouetteParams params, FilterReport filter)
      : params_(std::move(params)), filter_(std::move(filter)) {}
  friend ResolvedParams adapt_filter(const SilhouetteParams& choice, const DemGrid& grid,
                                     const WindowReader& read, const WindowReader& alongside);
  friend ResolvedParams resolve_as_reported(const SilhouetteParams& choice,
                                            const FilterReport& report);
  SilhouetteParams params_;
  FilterReport filter_;
};

// Resolves the user's choice for one run: an adaptive filter's cut-offs scaled to the DEM read
// through `read` on its own `grid`, its height tolerance and, with local adaptivity, the map of
// local scales (which reads the whole DEM once); a fixed filter as it is (`read` is not called).
// `alongside`, when given, reads half the survey's windows alongside `read` (survey_slopes).
// Throws Error on bad parameters, and what `read` throws.
ResolvedParams adapt_filter(const SilhouetteParams& choice, const DemGrid& grid,
                            const WindowReader& read, const WindowReader& alongside = {});

// What an adaptive filter adapted to the whole DEM makes of `survey` (adapt_filter's report, for a
// survey made in parts on a cluster: slope_survey.h).
FilterReport report_of_survey(const SilhouetteParams& choice, const SlopeSurvey& survey);

// The choice resolved as adapt_filter resolved it on the same DEM, which `report` tells: a run
// split among machines surveys the DEM once (bands.h). Throws Error when the report is another
// choice's, or for local adaptivity, whose map of scales a report does not hold.
ResolvedParams resolve_as_reported(const SilhouetteParams& choice, const FilterReport& report);

}  // namespace tsk
