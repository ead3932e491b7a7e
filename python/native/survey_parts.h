// The adaptive filter's survey of a run in bands, as a reduction over a cluster's workers
// (terrain_sketch.dask): each worker reads some of the survey's windows (slope_survey.h) from the
// DEM's file, and the client sums their parts into the report one machine's survey makes. Parts
// travel as bytes.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace tsk::python {

// A window of the survey: its first row and column, its rows and columns.
using SurveyWindow = std::array<std::size_t, 4>;

// The windows the survey of the DEM reads.
std::vector<SurveyWindow> survey_windows_of(const std::string& input,
                                            const std::vector<std::string>& options);
// The step of the heights in `windows`, as bytes.
std::string survey_heights_part(const std::string& input, const std::vector<std::string>& options,
                                const std::vector<SurveyWindow>& windows);
// The steps of all the windows, summed.
std::string merge_height_parts(const std::vector<std::string>& parts);
// The slopes in `windows`, measured with the tolerance of `heights` (all the windows' step).
std::string survey_slopes_part(const std::string& input, const std::vector<std::string>& options,
                               const std::vector<SurveyWindow>& windows,
                               const std::string& heights);
// The filter's report (as the plan's bytes) from the heights' step and the slopes' parts.
std::string filter_of_survey(const std::vector<std::string>& options, const std::string& heights,
                             const std::vector<std::string>& slope_parts);

}  // namespace tsk::python
