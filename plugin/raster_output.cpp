#include "plugin/raster_output.h"

#include <QFile>

#include "io/write/raster_writer.h"
#include "plugin/core_errors.h"
#include "plugin/raster_grid.h"

namespace tsk::plugin {
namespace {

std::string filePath(const QString& path) {
  return QFile::encodeName(path).toStdString();
}

std::string crsWkt(const QgsCoordinateReferenceSystem& crs) {
  return crs.isValid() ? crs.toWkt().toStdString() : std::string();
}

}  // namespace

void writeByteRaster(const QString& path, const Grid<std::uint8_t>& grid, const RasterGrid& dem,
                     const QString& note) {
  withCoreErrors([&] {
    io::write_classification(filePath(path), grid, dem.geotransform(), crsWkt(dem.crs()),
                             note.toStdString());
  });
}

void writeVisibilityRaster(const QString& path, const Grid<std::uint8_t>& grid,
                           const RasterGrid& dem, const QString& note) {
  withCoreErrors([&] {
    io::write_visibility(filePath(path), grid, dem.geotransform(), crsWkt(dem.crs()),
                         note.toStdString());
  });
}

void writeFloatRaster(const QString& path, const std::vector<HeightGrid>& bands,
                      const GeoTransform& geotransform, const QgsCoordinateReferenceSystem& crs,
                      const QString& note) {
  withCoreErrors([&] {
    io::write_float_raster(filePath(path), bands, geotransform, crsWkt(crs), note.toStdString());
  });
}

}  // namespace tsk::plugin
