// Strokes to any OGR vector format, one line layer with the SPEC attribute fields.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/applications/profile_plot.h"
#include "core/applications/pstrokes.h"
#include "core/method/strokes.h"
#include "core/panorama/panorama.h"
#include "core/panorama/panorama_peaks.h"
#include "core/panorama/panorama_strokes.h"

namespace tsk::io {

// The OGR driver for an output path: `format` if given, else by the file's extension.
std::string vector_driver_for(const std::string& path, const std::string& format);

// The layers the command line writes.
inline constexpr const char* kStrokeLayer = "silhouettes";
inline constexpr const char* kProfileLayer = "profiles";
inline constexpr const char* kPStrokeLayer = "pstrokes";
// A panorama's two layers: its strokes on the map and in the panorama (azimuth, elevation).
inline constexpr const char* kPanoramaMapLayer = "map";
inline constexpr const char* kPanoramaLayer = "panorama";
inline constexpr const char* kPanoramaPeakLayer = "peaks";

// Checks, before any work, that a line layer can be written to `path`: a vector format is known
// for it, and no GeoPackage or SQLite file is there that holds more than an earlier output (one
// layer named as ours or as the file): a raster, or other layers as in a project's GeoPackage,
// would be destroyed. Returns the format's OGR driver name (vector_driver_for).
std::string check_vector_output(const std::string& path, const std::string& format);

// Whether OGR driver `driver_name` keeps M values, as a line written to memory and read back shows
// (true when that cannot be told): GeoJSON, GML and KML do not, and drawn strokes' weights written
// there are lost.
bool keeps_m_values(const std::string& driver_name);

// The options a new file of OGR driver `driver_name` is created with (NAME=VALUE). A SQLite file
// is made SpatiaLite where GDAL can: in OGR's own flavour a measured layer is recorded as 3D, and
// GDAL and QGIS read it back so (QGIS then saves it elsewhere without its weights).
std::vector<std::string> new_file_options(const std::string& driver_name);

// Writes one stroke to the layer being filled.
using StrokeWriter = std::function<void(const Stroke& stroke)>;

// Creates `path` with the stroke layer in the CRS given as WKT (may be empty) and calls
// produce(write), which hands every stroke to `write` as it has it: strokes need not be held
// until they are written. Whole or not at all: if produce throws, nothing is left behind.
// weighted: the strokes are drawn ones, written as LineString M with their weights as M.
// describe, when given, is asked once the strokes are all made for the file's description (a
// GeoPackage keeps it as its layer's description, in gpkg_contents; other formats drop it).
void write_strokes(const std::string& path, const std::string& format, const std::string& srs_wkt,
                   const std::function<void(const StrokeWriter& write)>& produce,
                   const std::string& layer_name = kStrokeLayer, bool weighted = false,
                   const std::function<std::string()>& describe = {});

// Writes `strokes` to `path`, whole or not at all; with M values if they are drawn strokes.
void write_strokes(const std::string& path, const std::string& format,
                   const std::vector<Stroke>& strokes, const std::string& srs_wkt,
                   const std::string& layer_name = kStrokeLayer);

// Writes profile-plot lines (fields: section, distance) to `path`, whole or not at all.
void write_profile_lines(const std::string& path, const std::string& format,
                         const std::vector<ProfileLine>& lines, const std::string& srs_wkt,
                         const std::string& description = {});

// Writes P-strokes (fields: class, score_m2) to `path`, whole or not at all.
void write_pstrokes(const std::string& path, const std::string& format,
                    const std::vector<PStroke>& strokes, const std::string& srs_wkt,
                    const std::string& description = {});

// Writes a panorama's strokes to `path`, whole or not at all, in two layers: `map`, in the DEM's
// CRS (WKT, may be empty), and `panorama`, without a CRS, x the azimuth and y the elevation angle
// in degrees. Both have the stroke fields with azimuth_min and azimuth_max; the file must hold
// two layers (a GeoPackage or SQLite file). With `peaks`, a third layer `peaks` holds their
// leaders in the panorama, with name, distance, azimuth and elevation. The panorama's elevation
// angles, and the leaders', are drawn `exaggeration` times as tall as its azimuths are wide.
void write_panorama_strokes(const std::string& path, const std::string& format,
                            const std::vector<PanoramaStroke>& strokes, const std::string& srs_wkt,
                            const std::vector<PeakLeader>* peaks = nullptr,
                            double exaggeration = 1.0, const std::string& description = {});

}  // namespace tsk::io
