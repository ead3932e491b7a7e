// The slope filter's diagram as a self-contained HTML page with inline SVG (thesis figures 5.7
// and 5.8): the scatter of core/applications/filter_diagram.h with the removal region drawn.
#pragma once

#include <string>

#include "core/applications/filter_diagram.h"

namespace tsk {

// The page: scatter (all cells grey, c-set red, f-set black), removal polygon, cut-offs and
// control point, with a legend and the counts.
std::string filter_diagram_html(const SlopeScatter& scatter, const FilterParams& filter,
                                const std::string& title);

}  // namespace tsk
