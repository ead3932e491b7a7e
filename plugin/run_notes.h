// What the plugin's outputs record of the run that made them, in the user's language: the words
// of core's run_note.h for the layers' metadata, their names and a GeoPackage's layer description.
#pragma once

#include <QString>
#include <cstddef>

#include "core/method/adaptive_filter.h"
#include "core/method/params.h"
#include "core/panorama/panorama_rays.h"
#include "plugin/layer_style.h"

namespace tsk::plugin {

// "the slope filter adapted to the DEM: row 20 %, column 12 %, control point 8.73 %"
QString filterPhrase(const FilterReport& filter);

// "from 250°": the view, for a layer's name.
QString fromAzimuth(const ViewParams& view);

// The silhouettes' note: "jacksboro_utm16n, band 1. Seen from 250° (azimuth), vertical
// exaggeration 2.5, base slope 40 %; <filterPhrase>; drawn strokes [for 1:250 000] [from the DEM
// averaged 5 x 5 cells]. Terrain Sketch 0.1.0." (`averaged`: SilhouetteResult::averaged)
QString sketchNote(const QString& dem, const ViewParams& view, const FilterReport& filter,
                   const DrawnParams& strokes, std::size_t averaged = 1);

// A panorama's note: "<dem>. Seen from 749008, 4009478, 2 m above the ground, from 300° to 30°
// (azimuths from grid north); elevation angles drawn 3 times as tall as azimuths are wide.
// Terrain Sketch 0.1.0." (`exaggeration`: the panorama layer's).
QString panoramaNote(const QString& dem, const PanoramaView& view, double exaggeration);

// Another product of the view: titled "<product>, from 250°", with the note "<dem>. <product>
// seen from 250° (azimuth), vertical exaggeration 2.5, base slope 40 %[; <filterPhrase>].
// Terrain Sketch 0.1.0." (the filter where one ran).
RunNote productNote(const QString& dem, const QString& product, const ViewParams& view,
                    const FilterReport* filter = nullptr);

}  // namespace tsk::plugin
