#include "raster_output.h"

#include <cpl_error.h>
#include <qgsexception.h>
#include <qgsrasterblock.h>
#include <qgsrasterdataprovider.h>
#include <qgsrasterfilewriter.h>

#include <QCoreApplication>
#include <QFileInfo>
#include <limits>
#include <memory>

#include "line_output.h"
#include "raster_grid.h"

namespace tsk::plugin {
namespace {

// GDAL's first failure while this lives, kept from QGIS's log: GDAL itself keeps only the last,
// and a full disk's "File too large" is followed by libtiff's consequences of it.
class FirstGdalFailure {
 public:
  FirstGdalFailure() { CPLPushErrorHandlerEx(&FirstGdalFailure::handle, this); }
  ~FirstGdalFailure() { CPLPopErrorHandler(); }
  FirstGdalFailure(const FirstGdalFailure&) = delete;
  FirstGdalFailure& operator=(const FirstGdalFailure&) = delete;
  bool failed() const { return mFailed; }
  const QString& message() const { return mMessage; }

 private:
  static void CPL_STDCALL handle(CPLErr type, CPLErrorNum, const char* message) {
    auto* self = static_cast<FirstGdalFailure*>(CPLGetErrorHandlerUserData());
    if (type < CE_Failure || self->mFailed) return;
    self->mFailed = true;
    self->mMessage = QString::fromUtf8(message);
  }
  bool mFailed = false;
  QString mMessage;
};

class RasterOutput {
  Q_DECLARE_TR_FUNCTIONS(RasterOutput)

 public:
  // Writes one band per entry of `bands` (cells of `bytesPerCell` bytes, rows x cols each).
  // The raster is whole or gone: GDAL writes what it caches only as it closes the file, and a
  // write that fails then (a full disk) shows only as a GDAL error, which QGIS merely logs.
  static void write(const QString& path, Qgis::DataType type, const std::vector<const void*>& bands,
                    std::size_t bytesPerCell, std::size_t rows, std::size_t cols, double noData,
                    const QgsRectangle& extent, const QgsCoordinateReferenceSystem& crs) {
    try {
      const FirstGdalFailure failure;
      writeBands(path, type, bands, bytesPerCell, rows, cols, noData, extent, crs);
      if (failure.failed()) {
        throw QgsProcessingException(
            tr("Could not write the raster %1: %2").arg(path, failure.message()));
      }
    } catch (const QgsProcessingException&) {
      deleteDataset(path);
      throw;
    }
  }

 private:
  static void writeBands(const QString& path, Qgis::DataType type,
                         const std::vector<const void*>& bands, std::size_t bytesPerCell,
                         std::size_t rows, std::size_t cols, double noData,
                         const QgsRectangle& extent, const QgsCoordinateReferenceSystem& crs) {
    QgsRasterFileWriter writer(path);
    writer.setOutputProviderKey(QStringLiteral("gdal"));
    writer.setOutputFormat(QgsRasterFileWriter::driverForExtension(QFileInfo(path).suffix()));
    std::unique_ptr<QgsRasterDataProvider> provider(
        writer.createMultiBandRaster(type, static_cast<int>(cols), static_cast<int>(rows), extent,
                                     crs, static_cast<int>(bands.size())));
    if (!provider || !provider->isValid()) {
      throw QgsProcessingException(tr("Could not create the raster %1.").arg(path));
    }
    for (std::size_t b = 0; b < bands.size(); ++b) {
      const int band = static_cast<int>(b) + 1;
      QgsRasterBlock block(type, static_cast<int>(cols), static_cast<int>(rows));
      block.setData(QByteArray::fromRawData(static_cast<const char*>(bands[b]),
                                            static_cast<int>(rows * cols * bytesPerCell)));
      provider->setNoDataValue(band, noData);
      // The provider made by createMultiBandRaster is open for writing already.
      if (!provider->writeBlock(&block, band, 0, 0)) {
        throw QgsProcessingException(tr("Could not write the raster %1.").arg(path));
      }
    }
  }
};

}  // namespace

void writeByteRaster(const QString& path, const Grid<std::uint8_t>& grid, const RasterGrid& dem) {
  RasterOutput::write(path, Qgis::DataType::Byte, {grid.data()}, 1, grid.rows(), grid.cols(), 0,
                      dem.extent(), dem.crs());
}

void writeFloatRaster(const QString& path, const std::vector<HeightGrid>& bands,
                      const QgsRectangle& extent, const QgsCoordinateReferenceSystem& crs) {
  std::vector<const void*> data;
  for (const HeightGrid& b : bands) data.push_back(b.data());
  RasterOutput::write(path, Qgis::DataType::Float32, data, sizeof(float), bands.at(0).rows(),
                      bands.at(0).cols(), std::numeric_limits<double>::quiet_NaN(), extent, crs);
}

}  // namespace tsk::plugin
