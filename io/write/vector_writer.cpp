#include "io/write/vector_writer.h"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>

#include "io/gpkg/gpkg_line_appender.h"
#include "io/read/gdal_util.h"
#include "io/write/checked_writes.h"
#include "io/write/output_files.h"

namespace tsk::io {
namespace {

void check(OGRErr err, const std::string& what, const GdalErrorCapture& capture) {
  if (err != OGRERR_NONE) throw Error(what + " failed: " + capture.message());
}

}  // namespace

// SQLite keeps a journal beside a database, named after it with "-journal": a name that leaves no
// room for it fails deep in GDAL with a message quoting SQL.
void check_journal_fits(const std::string& path) {
  const std::filesystem::path file(path);
  const long most = pathconf(folder_of(file).c_str(), _PC_NAME_MAX);
  const std::size_t name = file.filename().string().size(), journal = name + 8;
  if (most > 0 && journal > static_cast<std::size_t>(most)) {
    throw Error("the name of '" + path + "' is " + std::to_string(name) +
                " bytes long: SQLite keeps a journal beside a GeoPackage named NAME-journal, "
                "which must fit the file system's " +
                std::to_string(most) + " bytes; shorten the name by " +
                std::to_string(journal - static_cast<std::size_t>(most)) + " byte(s)");
  }
}

std::string vector_driver_for(const std::string& path, const std::string& format) {
  const std::string ext = lowercase_extension(path);
  static const std::map<std::string, std::string> drivers = {
      {".gpkg", "GPKG"},    {".shp", "ESRI Shapefile"}, {".geojson", "GeoJSON"},
      {".json", "GeoJSON"}, {".fgb", "FlatGeobuf"},     {".gml", "GML"},
      {".kml", "KML"},      {".sqlite", "SQLite"},      {".csv", "CSV"}};
  const auto it = drivers.find(ext);
  if (!format.empty()) {
    // A name of another format's extension would mislead (CSV into x.gpkg makes a folder). An
    // unknown driver is refused as such when the output is made.
    GDALAllRegister();
    const bool known = GetGDALDriverManager()->GetDriverByName(format.c_str()) != nullptr;
    if (known && it != drivers.end() && !EQUAL(it->second.c_str(), format.c_str())) {
      throw Error("--format " + format + " does not write '" + path + "': a " + ext + " name is " +
                  it->second + "'s; name the output so, or leave --format out");
    }
    return format;
  }
  if (it == drivers.end()) {
    throw Error("cannot tell the vector format of '" + path +
                "' from its extension; use .gpkg, .shp, .geojson, .fgb, .gml, .kml, .sqlite or "
                ".csv, or name an OGR driver with --format");
  }
  return it->second;
}

std::string check_vector_output(const std::string& path, const std::string& format) {
  // Only the database formats keep other data beside a layer (a project's GeoPackage) and open
  // in a moment; a GeoJSON or KML file is one layer, and opening it would parse all of it.
  GDALAllRegister();
  std::string driver = vector_driver_for(path, format);
  if (driver != "GPKG" && driver != "SQLite") return driver;
  check_journal_fits(path);
  GdalErrorCapture quiet;  // a path that is no dataset (or none yet) is free to write
  const NoAuxFiles no_aux;
  const char* const drivers[] = {driver.c_str(), nullptr};
  DatasetPtr existing(
      GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_RASTER | GDAL_OF_READONLY, drivers));
  if (!existing) return driver;
  const auto refuse = [&](const std::string& what) {
    throw Error("'" + path + "' holds " + what + ", which writing it would destroy; choose " +
                "another file");
  };
  const char* const* subdatasets = existing->GetMetadata("SUBDATASETS");
  if (existing->GetRasterCount() > 0 || (subdatasets && *subdatasets)) refuse("a raster");
  // An earlier output is one layer with one of our names, or the file's (as QGIS names them).
  const std::string stem = std::filesystem::path(path).stem().string();
  std::size_t panorama_layers = 0;
  for (OGRLayer* layer : existing->GetLayers()) {
    const std::string name = layer->GetName();
    const bool panorama =
        name == kPanoramaMapLayer || name == kPanoramaLayer || name == kPanoramaPeakLayer;
    panorama_layers += panorama;
    if (name != kStrokeLayer && name != kProfileLayer && name != kPStrokeLayer && name != stem &&
        !panorama)
      refuse("the layer '" + name + "'");
  }
  // A panorama's two or three layers are one earlier output.
  const auto layers = static_cast<std::size_t>(existing->GetLayerCount());
  if (layers > 1 && !(layers == panorama_layers && layers <= 3))
    refuse(std::to_string(layers) + " layers");
  return driver;
}

namespace {

// A field of a line layer.
struct Field {
  const char* name;
  OGRFieldType type;
};

// Where the features of a line layer go: the attributes of a feature by field position (drivers
// may shorten names: shapefile to 10 characters), then its line.
class LineOutput {
 public:
  virtual ~LineOutput() = default;
  virtual void set(int field, std::int64_t value) = 0;
  virtual void set(int field, double value) = 0;  // NaN and infinities are null
  virtual void set(int field, const char* text) = 0;
  // The line through `points`, with `m` (one per point) when the layer is measured.
  virtual void add(const std::vector<StrokePoint>& points, const std::vector<double>& m = {}) = 0;
};

// Features through OGR, for any vector format.
class OgrLineOutput : public LineOutput {
 public:
  OgrLineOutput(OGRLayer& layer, const std::string& path)
      : layer_(layer), path_(path), feature_(layer.GetLayerDefn()) {}
  void set(int field, std::int64_t value) override { feature_.SetField(field, GIntBig{value}); }
  void set(int field, double value) override {
    if (std::isfinite(value)) {
      feature_.SetField(field, value);
    } else {
      feature_.SetFieldNull(field);
    }
  }
  void set(int field, const char* text) override { feature_.SetField(field, text); }
  void add(const std::vector<StrokePoint>& points, const std::vector<double>& m) override {
    OGRLineString line;
    line.setNumPoints(static_cast<int>(points.size()));
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (m.empty()) {
        line.setPoint(static_cast<int>(k), points[k].x, points[k].y);
      } else {
        line.setPointM(static_cast<int>(k), points[k].x, points[k].y, m[k]);
      }
    }
    feature_.SetGeometry(&line);
    feature_.SetFID(OGRNullFID);  // a new feature each time
    // Captured here: strokes are written from the thread that links them, which GDAL's error
    // handlers (one stack per thread) set on the caller's would not keep quiet.
    const GdalErrorCapture capture;
    check(layer_.CreateFeature(&feature_), "writing a line to '" + path_ + "'", capture);
  }

 private:
  OGRLayer& layer_;
  const std::string& path_;
  OGRFeature feature_;
};

// Features straight into a GeoPackage's SQLite tables (gpkg_line_appender.h).
class GpkgLineOutput : public LineOutput {
 public:
  GpkgLineOutput(GDALDataset& dataset, OGRLayer& layer) : appender_(dataset, layer.GetName()) {}
  void set(int field, std::int64_t value) override { appender_.set(field, value); }
  void set(int field, double value) override { appender_.set(field, value); }
  void set(int field, const char* text) override { appender_.set(field, text); }
  void add(const std::vector<StrokePoint>& points, const std::vector<double>& m) override {
    appender_.add(points, m);
  }
  void finish() { appender_.finish(); }

 private:
  GpkgLineAppender appender_;
};

// One line layer of an output: its name, CRS (WKT, may be empty), fields and features.
struct LineLayer {
  std::string name;
  std::string srs_wkt;
  std::vector<Field> fields;
  std::function<void(LineOutput&)> add_features;
  bool measured = false;
};

// What a driver needs to be told to write lines: GeoPackages get their spatial index in bulk, and
// a CSV keeps no geometry and no field types unless asked to (the lines go in a WKT column, read
// back as lines, and the types in a .csvt file beside it).
CPLStringList line_layer_options(const std::string& driver_name) {
  CPLStringList options;
  if (driver_name == "GPKG") options.SetNameValue("SPATIAL_INDEX", "NO");
  if (driver_name == "CSV") {
    options.SetNameValue("GEOMETRY", "AS_WKT");
    options.SetNameValue("CREATE_CSVT", "YES");
  }
  return options;
}

// Creates `layer` in `ds` (at `path` for messages) and fills it.
void fill_line_layer(GDALDataset& ds, const std::string& path, const std::string& driver_name,
                     const LineLayer& spec, const GdalErrorCapture& capture) {
  OGRSpatialReference srs;
  const bool has_srs =
      !spec.srs_wkt.empty() && srs.importFromWkt(spec.srs_wkt.c_str()) == OGRERR_NONE;
  srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  // KML places features by longitude and latitude; without a CRS nothing says where they are
  // (GDAL wrote the map coordinates as degrees, which GDAL 3.13 then reads as no feature).
  if ((driver_name == "KML" || driver_name == "LIBKML") && !has_srs) {
    throw Error("'" + path + "' is KML, which places features by longitude and latitude, and the " +
                "DEM has no CRS to find them from; give the DEM its CRS (gdal_edit.py -a_srs " +
                "EPSG:...) or write another format (.gpkg)");
  }
  OGRLayer* layer = ds.CreateLayer(spec.name.c_str(), has_srs ? &srs : nullptr,
                                   spec.measured ? wkbLineStringM : wkbLineString,
                                   line_layer_options(driver_name).List());
  if (!layer) throw Error("cannot create layer in '" + path + "': " + capture.message());
  for (const Field& field : spec.fields) {
    OGRFieldDefn defn(field.name, field.type);
    check(layer->CreateField(&defn), std::string("creating field '") + field.name + "'", capture);
  }
  if (driver_name == "GPKG" && !has_srs) {
    // GDAL records a layer without a CRS as "undefined geographic", which QGIS would place as
    // degrees on the earth: "undefined Cartesian" (-1) leaves it unplaced, as the panorama is.
    const std::string name = spec.name;
    for (const char* table : {"gpkg_geometry_columns", "gpkg_contents"}) {
      const std::string sql =
          std::string("UPDATE ") + table + " SET srs_id = -1 WHERE table_name = '" + name + "'";
      ds.ExecuteSQL(sql.c_str(), nullptr, nullptr);
    }
  }
  if (driver_name == "GPKG") {
    GpkgLineOutput output(ds, *layer);
    spec.add_features(output);
    output.finish();
  } else {
    OgrLineOutput output(*layer, path);
    spec.add_features(output);
  }
}

// Creates `path` with `layers` and fills them, all inside a transaction; whole or not at all. A
// GeoPackage is filled through SQLite and gets its spatial index in bulk; other formats through
// OGR.
void write_line_layers(const std::string& path, const std::string& format,
                       const std::vector<LineLayer>& layers,
                       const std::function<std::string()>& describe = {}) {
  const std::string driver_name = check_vector_output(path, format);
  GdalErrorCapture capture;
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driver_name.c_str());
  if (!driver || !driver->GetMetadataItem(GDAL_DCAP_VECTOR) ||
      !driver->GetMetadataItem(GDAL_DCAP_CREATE)) {
    throw Error("'" + driver_name + "' is not an OGR vector driver that can create files");
  }
  const bool database = driver_name == "GPKG" || driver_name == "SQLite";
  if (layers.size() > 1 && !database) {
    throw Error("'" + path + "' is to hold " + std::to_string(layers.size()) + " layers, and a " +
                driver_name +
                " file holds one: write a GeoPackage (.gpkg) or SQLite file (.sqlite)");
  }
  // Creates the layers at `target`, fills them and closes the file.
  const auto fill = [&](const std::string& target) {
    std::optional<BulkLoadPages> pages;
    if (database) pages.emplace();
    CPLStringList options;
    for (const std::string& option : new_file_options(driver_name))
      options.AddString(option.c_str());
    DatasetPtr ds(driver->Create(target.c_str(), 0, 0, 0, GDT_Unknown, options.List()));
    pages.reset();
    if (!ds) throw Error("cannot create '" + path + "': " + capture.message());
    const bool transaction = ds->StartTransaction() == OGRERR_NONE;
    for (const LineLayer& layer : layers) fill_line_layer(*ds, path, driver_name, layer, capture);
    // A GeoPackage's layers' description (gpkg_contents). Not the file's metadata (gpkg_metadata):
    // GDAL 3.10 then writes an .aux.xml beside the GeoPackage whenever it opens it. GDAL's SQLite
    // driver keeps no layer metadata, so an SQLite file has no place for it.
    if (describe && driver_name == "GPKG") {
      const std::string description = describe();
      for (const LineLayer& layer : layers)
        if (OGRLayer* written = ds->GetLayerByName(layer.name.c_str()))
          written->SetMetadataItem("DESCRIPTION", description.c_str());
    }
    if (transaction) check(ds->CommitTransaction(), "committing '" + path + "'", capture);
    CPLErrorReset();
    ds.reset();  // closing flushes: a failure here means an incomplete file
    if (CPLGetLastErrorType() >= CE_Failure) {
      throw Error("closing '" + path + "' failed: " + capture.message());
    }
  };
  // The database formats report their failed writes themselves.
  write_atomically(path, [&](const std::filesystem::path& staged) {
    const std::filesystem::path folder = staged.parent_path();
    take_write_failure(folder);  // none left from an earlier try in this folder
    // A write that failed explains a driver's error best, and some drivers report none at all.
    const auto fail_if_a_write_failed = [&] {
      const std::string failure = take_write_failure(folder);
      if (!failure.empty()) throw Error("writing '" + path + "' failed: " + failure);
    };
    try {
      fill(database ? staged.string() : checked_path(staged));
    } catch (const Error&) {
      fail_if_a_write_failed();
      throw;
    }
    fail_if_a_write_failed();
  });
}

void write_line_layer(const std::string& path, const std::string& format,
                      const std::string& srs_wkt, const std::string& layer_name,
                      const std::vector<Field>& fields,
                      const std::function<void(LineOutput&)>& add_features, bool measured = false,
                      const std::function<std::string()>& describe = {}) {
  write_line_layers(path, format, {{layer_name, srs_wkt, fields, add_features, measured}},
                    describe);
}

// The fields of a stroke layer: class, cells and stroke_real_fields().
std::vector<Field> stroke_fields() {
  std::vector<Field> fields = {{"class", OFTString}, {"cells", OFTInteger}};
  for (const StrokeRealField& f : stroke_real_fields()) fields.push_back({f.name, OFTReal});
  return fields;
}

// Writes a line with M values 0.5 and 0.25 to `path` through `driver`, with our options.
bool write_measured_line(GDALDriver& driver, const std::string& path,
                         const std::string& driver_name) {
  DatasetPtr ds(driver.Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
  OGRLayer* layer =
      ds ? ds->CreateLayer("probe", nullptr, wkbLineStringM, line_layer_options(driver_name).List())
         : nullptr;
  if (!layer) return false;
  OGRLineString line;
  line.addPointM(0.0, 0.0, 0.5);
  line.addPointM(1.0, 1.0, 0.25);
  OGRFeature feature(layer->GetLayerDefn());
  feature.SetGeometry(&line);
  return layer->CreateFeature(&feature) == OGRERR_NONE && close_dataset(ds);
}

// Whether the first line of the file at `path` has the M value 0.25 at its second point.
bool reads_back_measured_line(const std::string& path) {
  DatasetPtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  OGRLayer* layer = ds && ds->GetLayerCount() > 0 ? ds->GetLayer(0) : nullptr;
  if (!layer) return false;
  const std::unique_ptr<OGRFeature> feature(layer->GetNextFeature());
  const OGRGeometry* geometry = feature ? feature->GetGeometryRef() : nullptr;
  return geometry && geometry->IsMeasured() &&
         wkbFlatten(geometry->getGeometryType()) == wkbLineString &&
         geometry->toLineString()->getM(1) == 0.25;
}

}  // namespace

bool keeps_m_values(const std::string& driver_name) {
  // A GeoPackage's lines are written by our own appender, M values and all.
  if (driver_name == "GPKG") return true;
  // GDAL's DCAP_MEASURED_GEOMETRIES is no guide: GDAL 3.10's GeoJSON driver declares it and writes
  // lines without their M values. So a line with M values is written to memory, with the options
  // our outputs use, and read back. A driver that cannot write to memory (CSV) is taken to keep
  // them: nothing is said that is not known.
  GDALAllRegister();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driver_name.c_str());
  if (!driver) return true;
  static std::atomic<unsigned> probes{0};
  const char* extension = driver->GetMetadataItem(GDAL_DMD_EXTENSION);
  const std::string folder =
      "/vsimem/tsk_m_probe_" + std::to_string(getpid()) + "_" + std::to_string(probes++);
  const std::string path = folder + "/probe." + (extension ? extension : "dat");
  const GdalErrorCapture quiet;
  const bool kept =
      !write_measured_line(*driver, path, driver_name) || reads_back_measured_line(path);
  VSIRmdirRecursive(folder.c_str());
  return kept;
}

std::vector<std::string> new_file_options(const std::string& driver_name) {
  if (driver_name != "SQLite") return {};
  GDALAllRegister();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("SQLite");
  const char* known = driver ? driver->GetMetadataItem(GDAL_DMD_CREATIONOPTIONLIST) : nullptr;
  if (!known || !std::strstr(known, "SPATIALITE")) return {};  // GDAL built without SpatiaLite
  // Without the EPSG table SpatiaLite would fill (7 MB): only the layers' CRS is stored.
  return {"SPATIALITE=YES", "INIT_WITH_EPSG=NO"};
}

void write_strokes(const std::string& path, const std::string& format, const std::string& srs_wkt,
                   const std::function<void(const StrokeWriter& write)>& produce,
                   const std::string& layer_name, bool weighted,
                   const std::function<std::string()>& describe) {
  write_line_layer(
      path, format, srs_wkt, layer_name, stroke_fields(),
      [&](LineOutput& output) {
        produce([&](const Stroke& s) {
          if (weighted != !s.weights.empty())
            throw Error("a stroke " + std::string(weighted ? "without" : "with") +
                        " weights for a layer " + (weighted ? "with" : "without") + " them");
          set_stroke_attributes(output, s);
          output.add(s.points, s.weights);
        });
      },
      weighted, describe);
}

void write_strokes(const std::string& path, const std::string& format,
                   const std::vector<Stroke>& strokes, const std::string& srs_wkt,
                   const std::string& layer_name) {
  const bool weighted = !strokes.empty() && !strokes.front().weights.empty();
  write_strokes(
      path, format, srs_wkt,
      [&](const StrokeWriter& write) {
        for (const Stroke& s : strokes) write(s);
      },
      layer_name, weighted);
}

namespace {

// The layers' description (a GeoPackage's), when there is one.
std::function<std::string()> described(const std::string& description) {
  if (description.empty()) return {};
  return [description] { return description; };
}

}  // namespace

void write_profile_lines(const std::string& path, const std::string& format,
                         const std::vector<ProfileLine>& lines, const std::string& srs_wkt,
                         const std::string& description) {
  write_line_layer(
      path, format, srs_wkt, kProfileLayer, {{"section", OFTInteger}, {"distance", OFTReal}},
      [&](LineOutput& output) {
        for (const ProfileLine& line : lines) {
          output.set(0, static_cast<std::int64_t>(line.cross_section));
          output.set(1, line.distance);
          output.add(line.points);
        }
      },
      false, described(description));
}

void write_pstrokes(const std::string& path, const std::string& format,
                    const std::vector<PStroke>& strokes, const std::string& srs_wkt,
                    const std::string& description) {
  write_line_layer(
      path, format, srs_wkt, kPStrokeLayer, {{"class", OFTString}, {"score_m2", OFTReal}},
      [&](LineOutput& output) {
        for (const PStroke& s : strokes) {
          output.set(0, pstroke_class_name(s.cls));
          output.set(1, s.score_m2);
          output.add(s.points);
        }
      },
      false, described(description));
}

void write_panorama_strokes(const std::string& path, const std::string& format,
                            const std::vector<PanoramaStroke>& strokes, const std::string& srs_wkt,
                            const std::vector<PeakLeader>* peaks, double exaggeration,
                            const std::string& description) {
  std::vector<Field> fields = stroke_fields();
  const int azimuth_field = static_cast<int>(fields.size());
  fields.push_back({"azimuth_min", OFTReal});
  fields.push_back({"azimuth_max", OFTReal});
  // Both stroke layers carry the same attributes; they differ in geometry.
  const auto layer = [&](bool panorama) {
    return [&strokes, azimuth_field, panorama, exaggeration](LineOutput& output) {
      for (const PanoramaStroke& s : strokes) {
        set_stroke_attributes(output, s.map);
        output.set(azimuth_field, s.azimuth_min);
        output.set(azimuth_field + 1, s.azimuth_max);
        output.add(panorama ? exaggerated(s.view, exaggeration) : s.map.points);
      }
    };
  };
  std::vector<LineLayer> layers = {{kPanoramaMapLayer, srs_wkt, fields, layer(false)},
                                   {kPanoramaLayer, "", fields, layer(true)}};
  if (peaks) {
    // The peaks in sight, each a leader from its top up to where its name goes.
    const auto add_peaks = [peaks, exaggeration](LineOutput& output) {
      for (const PeakLeader& l : *peaks) {
        output.set(0, l.peak.name.c_str());
        output.set(1, l.peak.distance);
        output.set(2, l.peak.azimuth_deg);
        output.set(3, l.peak.elevation_deg);
        output.add(exaggerated({l.top, l.label}, exaggeration));
      }
    };
    layers.push_back(
        {kPanoramaPeakLayer,
         "",
         {{"name", OFTString}, {"distance", OFTReal}, {"azimuth", OFTReal}, {"elevation", OFTReal}},
         add_peaks});
  }
  write_line_layers(path, format, layers, described(description));
}

}  // namespace tsk::io
