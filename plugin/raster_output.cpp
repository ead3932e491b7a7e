#include "raster_output.h"

#include <qgsexception.h>
#include <qgsrasterblock.h>
#include <qgsrasterdataprovider.h>
#include <qgsrasterfilewriter.h>

#include <QCoreApplication>
#include <QFileInfo>
#include <limits>
#include <memory>

#include "raster_grid.h"

namespace tsk::plugin {
namespace {

class RasterOutput {
  Q_DECLARE_TR_FUNCTIONS(RasterOutput)

 public:
  static void write(const QString& path, Qgis::DataType type, const void* data,
                    std::size_t bytesPerCell, std::size_t rows, std::size_t cols, double noData,
                    const RasterGrid& dem) {
    QgsRasterFileWriter writer(path);
    writer.setOutputProviderKey(QStringLiteral("gdal"));
    writer.setOutputFormat(QgsRasterFileWriter::driverForExtension(QFileInfo(path).suffix()));
    std::unique_ptr<QgsRasterDataProvider> provider(writer.createOneBandRaster(
        type, static_cast<int>(cols), static_cast<int>(rows), dem.extent(), dem.crs()));
    if (!provider || !provider->isValid()) {
      throw QgsProcessingException(tr("Could not create the raster %1.").arg(path));
    }
    QgsRasterBlock block(type, static_cast<int>(cols), static_cast<int>(rows));
    block.setData(QByteArray::fromRawData(static_cast<const char*>(data),
                                          static_cast<int>(rows * cols * bytesPerCell)));
    provider->setNoDataValue(1, noData);
    // The provider made by createOneBandRaster is open for writing already.
    if (!provider->writeBlock(&block, 1, 0, 0)) {
      throw QgsProcessingException(tr("Could not write the raster %1.").arg(path));
    }
  }
};

}  // namespace

void writeByteRaster(const QString& path, const Grid<std::uint8_t>& grid, const RasterGrid& dem) {
  RasterOutput::write(path, Qgis::DataType::Byte, grid.data(), 1, grid.rows(), grid.cols(), 0, dem);
}

void writeFloatRaster(const QString& path, const HeightGrid& grid, const RasterGrid& dem) {
  RasterOutput::write(path, Qgis::DataType::Float32, grid.data(), sizeof(float), grid.rows(),
                      grid.cols(), std::numeric_limits<double>::quiet_NaN(), dem);
}

}  // namespace tsk::plugin
