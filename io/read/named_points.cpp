#include "io/read/named_points.h"

#include <ogrsf_frmts.h>

#include <memory>

#include "core/base/errors.h"
#include "io/read/gdal_util.h"

namespace tsk::io {
namespace {

// The transformation from the layer's CRS to the DEM's, or null when either has none.
std::unique_ptr<OGRCoordinateTransformation> to_dem_crs(OGRLayer& layer, const std::string& wkt,
                                                        const std::string& path) {
  const OGRSpatialReference* from = layer.GetSpatialRef();
  if (!from || wkt.empty()) return nullptr;
  OGRSpatialReference to;
  if (to.importFromWkt(wkt.c_str()) != OGRERR_NONE) return nullptr;
  to.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  OGRSpatialReference source(*from);
  source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  if (source.IsSame(&to)) return nullptr;
  std::unique_ptr<OGRCoordinateTransformation> transform(
      OGRCreateCoordinateTransformation(&source, &to));
  if (!transform) throw Error("the points of '" + path + "' cannot be moved into the DEM's CRS");
  return transform;
}

std::string field_list(OGRFeatureDefn& defn) {
  std::string names;
  for (int k = 0; k < defn.GetFieldCount(); ++k)
    names += (k ? ", " : "") + std::string(defn.GetFieldDefn(k)->GetNameRef());
  return names.empty() ? "none" : names;
}

// Why `path` is no layer of points, GDAL having said nothing when it is another kind of file.
std::string not_points(const std::string& path, const GdalErrorCapture& capture) {
  const std::string why = "cannot open '" + path + "' as a layer of points: ";
  if (!capture.first_failure().empty()) return why + capture.message();
  DatasetPtr raster(static_cast<GDALDataset*>(
      GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
  if (raster) return why + "it is a raster; give points (GeoPackage, shapefile, GeoJSON, CSV, ...)";
  return why + "no vector format of GDAL reads it";
}

}  // namespace

std::vector<NamedPoint> read_named_points(const std::string& path, const std::string& name_field,
                                          const std::string& srs_wkt) {
  GDALAllRegister();
  GdalErrorCapture capture;
  DatasetPtr ds(static_cast<GDALDataset*>(
      GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
  if (!ds || ds->GetLayerCount() == 0) throw Error(not_points(path, capture));
  OGRLayer& layer = *ds->GetLayer(0);
  const int field = layer.GetLayerDefn()->GetFieldIndex(name_field.c_str());
  if (field < 0) {
    throw Error("'" + path + "' has no field '" + name_field +
                "' for the names (its fields: " + field_list(*layer.GetLayerDefn()) + ")");
  }
  const auto transform = to_dem_crs(layer, srs_wkt, path);
  std::vector<NamedPoint> points;
  for (auto& feature : layer) {
    const OGRGeometry* geometry = feature->GetGeometryRef();
    if (!geometry) continue;
    const std::string name = feature->GetFieldAsString(field);
    std::vector<OGRPoint> found;
    if (wkbFlatten(geometry->getGeometryType()) == wkbPoint) {
      found.push_back(*geometry->toPoint());
    } else if (wkbFlatten(geometry->getGeometryType()) == wkbMultiPoint) {
      for (const OGRPoint* p : *geometry->toMultiPoint()) found.push_back(*p);
    } else {
      throw Error("'" + path + "' holds a " + geometry->getGeometryName() +
                  ": the peaks must be points");
    }
    for (OGRPoint& p : found) {
      if (transform && p.transform(transform.get()) != OGRERR_NONE)
        throw Error("the point '" + name + "' of '" + path +
                    "' cannot be moved into the DEM's CRS");
      points.push_back({name, p.getX(), p.getY()});
    }
  }
  return points;
}

}  // namespace tsk::io
