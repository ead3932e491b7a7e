#include "vector_writer.h"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>

#include "gdal_util.h"
#include "gpkg_spatial_index.h"
#include "output_files.h"

namespace tsk::io {
namespace {

void check(OGRErr err, const std::string& what, const GdalErrorCapture& capture) {
  if (err != OGRERR_NONE) throw Error(what + " failed: " + capture.message());
}

}  // namespace

std::string vector_driver_for(const std::string& path, const std::string& format) {
  if (!format.empty()) return format;
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  static const std::map<std::string, std::string> drivers = {
      {".gpkg", "GPKG"},    {".shp", "ESRI Shapefile"}, {".geojson", "GeoJSON"},
      {".json", "GeoJSON"}, {".fgb", "FlatGeobuf"},     {".gml", "GML"},
      {".kml", "KML"},      {".sqlite", "SQLite"},      {".csv", "CSV"}};
  const auto it = drivers.find(ext);
  if (it == drivers.end()) {
    throw Error("cannot tell the vector format of '" + path +
                "' from its extension; use .gpkg, .shp, .geojson, .fgb, .gml, .kml, .sqlite or "
                ".csv, or name an OGR driver with --format");
  }
  return it->second;
}

namespace {

// Creates `path` with one line layer, lets add_fields define its fields and add_features fill it,
// all inside a transaction; whole or not at all.
void write_line_layer(const std::string& path, const std::string& format,
                      const std::string& srs_wkt, const std::string& layer_name,
                      const std::function<void(OGRLayer&, const GdalErrorCapture&)>& add_fields,
                      const std::function<void(OGRLayer&, const GdalErrorCapture&)>& add_features) {
  GdalErrorCapture capture;
  const std::string driver_name = vector_driver_for(path, format);
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driver_name.c_str());
  if (!driver || !driver->GetMetadataItem(GDAL_DCAP_VECTOR) ||
      !driver->GetMetadataItem(GDAL_DCAP_CREATE)) {
    throw Error("'" + driver_name + "' is not an OGR vector driver that can create files");
  }
  OGRSpatialReference srs;
  const bool has_srs = !srs_wkt.empty() && srs.importFromWkt(srs_wkt.c_str()) == OGRERR_NONE;
  srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  // A GeoPackage gets its spatial index in bulk once the features are in.
  const bool bulk_index = driver_name == "GPKG";
  CPLStringList layer_options;
  if (bulk_index) layer_options.SetNameValue("SPATIAL_INDEX", "NO");

  write_atomically(path, [&](const std::filesystem::path& staged) {
    DatasetPtr ds(driver->Create(staged.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!ds) throw Error("cannot create '" + path + "': " + capture.message());
    OGRLayer* layer = ds->CreateLayer(layer_name.c_str(), has_srs ? &srs : nullptr, wkbLineString,
                                      layer_options.List());
    if (!layer) throw Error("cannot create layer in '" + path + "': " + capture.message());
    add_fields(*layer, capture);
    const bool transaction = ds->StartTransaction() == OGRERR_NONE;
    add_features(*layer, capture);
    if (bulk_index) add_gpkg_spatial_index(*ds, layer->GetName());
    if (transaction) check(ds->CommitTransaction(), "committing '" + path + "'", capture);
    CPLErrorReset();
    ds.reset();  // closing flushes: a failure here means an incomplete file
    if (CPLGetLastErrorType() >= CE_Failure) {
      throw Error("closing '" + path + "' failed: " + capture.message());
    }
  });
}

void add_field(OGRLayer& layer, const char* name, OGRFieldType type,
               const GdalErrorCapture& capture) {
  OGRFieldDefn defn(name, type);
  check(layer.CreateField(&defn), std::string("creating field '") + name + "'", capture);
}

// Writes one line feature whose attributes `set` has filled.
void add_line(OGRLayer& layer, OGRFeature& feature, const std::vector<StrokePoint>& points,
              const std::string& path, const GdalErrorCapture& capture) {
  OGRLineString line;
  line.setNumPoints(static_cast<int>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k) {
    line.setPoint(static_cast<int>(k), points[k].x, points[k].y);
  }
  feature.SetGeometry(&line);
  check(layer.CreateFeature(&feature), "writing a line to '" + path + "'", capture);
}

}  // namespace

void write_strokes(const std::string& path, const std::string& format, const std::string& srs_wkt,
                   const std::function<void(const StrokeWriter& write)>& produce,
                   const std::string& layer_name) {
  write_line_layer(
      path, format, srs_wkt, layer_name,
      [](OGRLayer& layer, const GdalErrorCapture& capture) {
        add_field(layer, "class", OFTString, capture);
        add_field(layer, "cells", OFTInteger, capture);
        for (const StrokeRealField& f : stroke_real_fields())
          add_field(layer, f.name, OFTReal, capture);
      },
      [&](OGRLayer& layer, const GdalErrorCapture& capture) {
        // Fields by position: drivers may shorten names (shapefile: 10 characters).
        produce([&](const Stroke& s) {
          OGRFeature feature(layer.GetLayerDefn());
          feature.SetField(0, stroke_class_name(s.cls));
          feature.SetField(1, s.cells);
          int index = 2;
          for (const StrokeRealField& f : stroke_real_fields()) {
            const double value = s.*(f.member);
            if (std::isfinite(value)) {
              feature.SetField(index, value);
            } else {
              feature.SetFieldNull(index);
            }
            ++index;
          }
          add_line(layer, feature, s.points, path, capture);
        });
      });
}

void write_strokes(const std::string& path, const std::string& format,
                   const std::vector<Stroke>& strokes, const std::string& srs_wkt,
                   const std::string& layer_name) {
  write_strokes(
      path, format, srs_wkt,
      [&](const StrokeWriter& write) {
        for (const Stroke& s : strokes) write(s);
      },
      layer_name);
}

void write_profile_lines(const std::string& path, const std::string& format,
                         const std::vector<ProfileLine>& lines, const std::string& srs_wkt) {
  write_line_layer(
      path, format, srs_wkt, "profiles",
      [](OGRLayer& layer, const GdalErrorCapture& capture) {
        add_field(layer, "section", OFTInteger, capture);
        add_field(layer, "distance", OFTReal, capture);
      },
      [&](OGRLayer& layer, const GdalErrorCapture& capture) {
        for (const ProfileLine& line : lines) {
          OGRFeature feature(layer.GetLayerDefn());
          feature.SetField(0, static_cast<int>(line.cross_section));
          feature.SetField(1, line.distance);
          add_line(layer, feature, line.points, path, capture);
        }
      });
}

void write_pstrokes(const std::string& path, const std::string& format,
                    const std::vector<PStroke>& strokes, const std::string& srs_wkt) {
  write_line_layer(
      path, format, srs_wkt, "pstrokes",
      [](OGRLayer& layer, const GdalErrorCapture& capture) {
        add_field(layer, "class", OFTString, capture);
        add_field(layer, "score_m2", OFTReal, capture);
      },
      [&](OGRLayer& layer, const GdalErrorCapture& capture) {
        for (const PStroke& s : strokes) {
          OGRFeature feature(layer.GetLayerDefn());
          feature.SetField(0, pstroke_class_name(s.cls));
          feature.SetField(1, s.score_m2);
          add_line(layer, feature, s.points, path, capture);
        }
      });
}

}  // namespace tsk::io
