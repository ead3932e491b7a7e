#include "plugin/drape_algorithm.h"

#include <qgsprocessingfeedback.h>
#include <qgsrasterblock.h>
#include <qgsrasterdataprovider.h>
#include <qgsrasterinterface.h>
#include <qgsrasterlayer.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/applications/drape.h"
#include "core/base/errors.h"
#include "core/method/visibility.h"
#include "plugin/raster_grid.h"
#include "plugin/raster_output.h"
#include "plugin/run_notes.h"

namespace tsk::plugin {

DrapeAlgorithm::DrapeAlgorithm() = default;
DrapeAlgorithm::~DrapeAlgorithm() = default;

QString DrapeAlgorithm::name() const {
  return QStringLiteral("drape");
}
QString DrapeAlgorithm::displayName() const {
  return tr("Drape raster (plan oblique)");
}

QString DrapeAlgorithm::shortHelpString() const {
  return tr(
      "Projects a raster on the DEM's grid (a hillshade, a slope or row slope map, an "
      "image; every band) into plan-oblique space: each visible cell moves along the view "
      "azimuth by exaggeration / base slope x (height - lowest height), terrain hidden "
      "behind nearer terrain is removed and slopes facing the viewer are stretched. The "
      "result lies exactly under the plan-oblique silhouettes and the profile plot made "
      "with the same view. The raster to drape must have the DEM's size (resample it to "
      "the DEM's grid first).");
}

DrapeAlgorithm* DrapeAlgorithm::createInstance() const {
  return new DrapeAlgorithm();
}

void DrapeAlgorithm::initAlgorithm(const QVariantMap&) {
  addWithHelp(SharedParameters::dem());
  addWithHelp(SharedParameters::view(true));
  addWithHelp(
      new QgsProcessingParameterRasterLayer(QStringLiteral("SOURCE"), tr("Raster to drape")),
      tr("A raster with the DEM's number of rows and columns; all its bands are draped."));
  addWithHelp(
      new QgsProcessingParameterRasterDestination(QStringLiteral("OUTPUT"), tr("Draped raster")),
      tr("Float32 raster in plan-oblique space, one band per source band."));
}

double DrapeAlgorithm::readParameters(const QVariantMap& parameters,
                                      QgsProcessingContext& context) {
  mView = SharedParameters::readView(*this, parameters, context);
  mView.validate();
  return mView.azimuth_deg;
}

bool DrapeAlgorithm::prepareAlgorithm(const QVariantMap& parameters, QgsProcessingContext& context,
                                      QgsProcessingFeedback* feedback) {
  DemViewAlgorithm::prepareAlgorithm(parameters, context, feedback);
  QgsRasterLayer* dem = parameterAsRasterLayer(parameters, QStringLiteral("INPUT"), context);
  QgsRasterLayer* source = parameterAsRasterLayer(parameters, QStringLiteral("SOURCE"), context);
  if (!source)
    throw QgsProcessingException(invalidRasterError(parameters, QStringLiteral("SOURCE")));
  if (source->width() != dem->width() || source->height() != dem->height()) {
    throw QgsProcessingException(
        tr("The raster to drape has %1 x %2 cells, the DEM %3 x %4: resample it to the DEM's "
           "grid first (Raster > Projections > Warp with the DEM's extent and resolution).")
            .arg(source->width())
            .arg(source->height())
            .arg(dem->width())
            .arg(dem->height()));
  }
  // The same grid on the ground, not only the same size: a source shifted or in another CRS was
  // draped silently onto the wrong ground.
  const double cell = std::min(dem->rasterUnitsPerPixelX(), dem->rasterUnitsPerPixelY());
  const QgsRectangle a = source->extent(), b = dem->extent();
  const bool sameGrid = std::abs(a.xMinimum() - b.xMinimum()) <= 1e-6 * cell &&
                        std::abs(a.yMaximum() - b.yMaximum()) <= 1e-6 * cell &&
                        std::abs(a.width() - b.width()) <= 1e-6 * cell &&
                        std::abs(a.height() - b.height()) <= 1e-6 * cell;
  if (!sameGrid) {
    throw QgsProcessingException(
        tr("The raster to drape covers %1 and the DEM %2: warp it onto the DEM's grid first "
           "(Raster > Projections > Warp with the DEM's extent and resolution).")
            .arg(a.toString(3), b.toString(3)));
  }
  if (source->crs().isValid() && dem->crs().isValid() && source->crs() != dem->crs()) {
    throw QgsProcessingException(
        tr("The raster to drape is in %1, the DEM in %2: warp it onto the DEM's grid and CRS "
           "first.")
            .arg(source->crs().authid(), dem->crs().authid()));
  }
  mSource.reset(source->dataProvider()->clone());
  mSourceBands = source->bandCount();
  mSourceName = source->name();
  return true;
}

PlanObliqueDrape DrapeAlgorithm::layOut(const RasterGrid& raster,
                                        QgsProcessingFeedback* feedback) const {
  // Laying out the drape takes as long as reading the DEM: progress from 30 to 60 %, and Cancel
  // heard within a few hundred profiles.
  return lay_out_drape(raster.held(), mView, 0, progressBetween(feedback, 30, 60));
}

HeightGrid DrapeAlgorithm::readSourceBand(int band, std::size_t rows, std::size_t cols,
                                          QgsProcessingFeedback* feedback) const {
  // QGIS reads the whole band in one call, which hears Cancel through a feedback of its own.
  QgsRasterBlockFeedback reading;
  if (feedback) {
    QObject::connect(feedback, &QgsFeedback::canceled, &reading, &QgsFeedback::cancel,
                     Qt::DirectConnection);
  }
  HeightGrid values(rows, cols);
  const std::unique_ptr<QgsRasterBlock> block(mSource->block(
      band, mSource->extent(), static_cast<int>(cols), static_cast<int>(rows), &reading));
  if (reading.isCanceled() || (feedback && feedback->isCanceled())) throw Cancelled();
  if (!block || !block->isValid()) {
    throw QgsProcessingException(tr("Could not read band %1 of the raster to drape.").arg(band));
  }
  copyHeights(*block, static_cast<int>(rows), values.data());
  return values;
}

QVariantMap DrapeAlgorithm::writeOutputs(const QVariantMap& parameters,
                                         QgsProcessingContext& context,
                                         QgsProcessingFeedback* feedback) {
  const RasterGrid& raster = readRaster(feedback, 30);
  const std::size_t rows = raster.frame().dem_rows, cols = raster.frame().dem_cols;
  const QgsCoordinateReferenceSystem crs = raster.crs();
  const QString path = parameterAsOutputLayer(parameters, QStringLiteral("OUTPUT"), context);
  withCoreErrors([&] {
    const PlanObliqueDrape drape = layOut(raster, feedback);
    const GeoTransform gt = drape.geotransform(raster.geotransform());
    releaseRaster();  // the DEM goes before the bands are draped
    std::vector<HeightGrid> bands;
    for (int band = 1; band <= mSourceBands; ++band) {
      if (feedback && feedback->isCanceled()) throw QgsProcessingException(tr("Cancelled."));
      bands.push_back(drape.drape(readSourceBand(band, rows, cols, feedback)));
      if (feedback) feedback->setProgress(60 + 30.0 * band / mSourceBands);
    }
    writeFloatRaster(path, bands, gt, crs,
                     productNote(demName(), tr("A drape of %1").arg(mSourceName), mView).abstract);
  });
  releaseRaster();
  mSource.reset();
  return {{QStringLiteral("OUTPUT"), path}};
}

}  // namespace tsk::plugin
