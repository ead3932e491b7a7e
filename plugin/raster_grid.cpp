#include "plugin/raster_grid.h"

#include <gdal.h>
#include <qgscoordinatetransform.h>
#include <qgsexception.h>
#include <qgsprocessingfeedback.h>
#include <qgsproviderregistry.h>
#include <qgsrasterblock.h>
#include <qgsrasterdataprovider.h>
#include <qgsrasterlayer.h>

#include <QFile>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>
#include <utility>
#include <vector>

#include "core/method/silhouettes.h"
#include "io/read/dem_reader.h"
#include "io/read/gdal_util.h"
#include "plugin/core_errors.h"
#include "plugin/qgis_compat.h"

namespace tsk::plugin {
namespace {

// The raster's centre in degrees of longitude and latitude; false when it cannot be transformed.
bool centreInDegrees(const QgsCoordinateReferenceSystem& crs, const QgsRectangle& extent,
                     const QgsCoordinateTransformContext& transforms, io::DemFacts& facts) {
  try {
    const QgsCoordinateTransform toLonLat(
        crs, QgsCoordinateReferenceSystem(QStringLiteral("EPSG:4326")), transforms);
    const QgsPointXY centre = toLonLat.transform(extent.center());
    facts.centre_lon = centre.x();
    facts.centre_lat = centre.y();
    return true;
  } catch (const QgsCsException&) {
    return false;
  }
}

// What is known of the layer before reading it, for io::assess_dem. Its range is GDAL's over a
// sample of the cells (fill values cover holes and edges), with the band's scale and offset
// applied as the provider applies them; other providers (web services) would fetch data for it
// on the main thread.
io::DemFacts layerFacts(QgsRasterLayer& layer, int band,
                        const QgsCoordinateTransformContext& transforms) {
  io::DemFacts f;
  f.rows = static_cast<std::size_t>(layer.height());
  f.cols = static_cast<std::size_t>(layer.width());
  f.cell_x = layer.extent().width() / layer.width();
  f.cell_y = layer.extent().height() / layer.height();
  f.west = layer.extent().xMinimum();
  f.north = layer.extent().yMaximum();
  f.bands = layer.bandCount();
  f.band = band;
  // QGIS numbers colour interpretations as GDAL does (3 to 6: red, green, blue, alpha), whatever
  // its enum's name in this version.
  const int colour = static_cast<int>(layer.dataProvider()->colorInterpretation(band));
  f.colour_band = colour >= 3 && colour <= 6;
  const QgsCoordinateReferenceSystem crs = layer.crs();
  f.has_crs = crs.isValid();
  if (f.has_crs) {
    f.geographic = crs.isGeographic();
    f.crs_id = crs.authid().toStdString();
    f.unit_is_metre = crs.mapUnits() == kMetres;
    f.unit = QgsUnitTypes::toString(crs.mapUnits()).toStdString();
    f.proj = crs.toProj().toStdString();
    f.has_centre = centreInDegrees(crs, layer.extent(), transforms, f);
  }
  if (layer.providerType() == QLatin1String("gdal")) {
    // A band without a valid cell makes GDAL print "no valid pixels found" on each call: QGIS
    // told it once as it loaded the layer, and the warning on all-nodata runs says it better.
    const io::GdalErrorCapture quiet;
    const QgsRasterBandStats range =
        layer.dataProvider()->bandStatistics(band, kRangeStatistics, QgsRectangle(), 250000);
    f.has_range = true;
    f.lowest_value = range.minimumValue;
    f.highest_value = range.maximumValue;
  }
  return f;
}

// The file of a GDAL layer that is one plain file (not a layer or subdataset of one, nor opened
// with options); empty otherwise.
QString plainGdalFile(const QgsRasterLayer& layer) {
  if (layer.providerType() != QLatin1String("gdal")) return {};
  const QVariantMap parts =
      QgsProviderRegistry::instance()->decodeUri(QStringLiteral("gdal"), layer.source());
  for (auto it = parts.begin(); it != parts.end(); ++it) {
    if (it.key() != QLatin1String("path") && !it.value().toString().isEmpty()) return {};
  }
  return parts.value(QStringLiteral("path")).toString();
}

}  // namespace

// Copies a block of `count` rows into `out` as floats with NaN for nodata and for float's fill
// values, as io's reader gives them. Float32 blocks whose nodata is a plain value (or absent) are
// copied in bulk; anything else cell by cell.
void copyHeights(QgsRasterBlock& block, int count, float* out) {
  const auto cells = static_cast<std::size_t>(count) * static_cast<std::size_t>(block.width());
  const bool plainNoData = block.hasNoDataValue() || !block.hasNoData();
  if (block.dataType() == Qgis::DataType::Float32 && plainNoData) {
    std::memcpy(out, block.bits(0), cells * sizeof(float));
    mark_nodata(out, cells, block.hasNoDataValue(), static_cast<float>(block.noDataValue()));
    return;
  }
  for (int r = 0; r < count; ++r) {
    for (int c = 0; c < block.width(); ++c) {
      bool noData = false;
      const double v = block.valueAndNoData(r, c, noData);
      out[static_cast<std::size_t>(r) * static_cast<std::size_t>(block.width()) + c] =
          noData ? kNoData : static_cast<float>(v);
    }
  }
  mark_nodata(out, cells, false, 0.0f);
}

RasterGrid::RasterGrid(QgsRasterLayer* layer, int band,
                       const QgsCoordinateTransformContext& transforms) {
  if (!layer || !layer->isValid() || !layer->dataProvider()) {
    throw QgsProcessingException(tr("The input raster layer is not valid."));
  }
  const int bands = layer->bandCount();
  if (band < 1 || band > bands) {
    throw QgsProcessingException(
        tr("Band %1 does not exist: the raster has %2 band(s).").arg(band).arg(bands));
  }
  mBand = band;
  mCols = layer->width();
  mRows = layer->height();
  mExtent = layer->extent();
  mCrs = layer->crs();
  if (mCols < 1 || mRows < 1) throw QgsProcessingException(tr("The raster has no cells."));
  const io::DemAssessment assessment = io::assess_dem(layerFacts(*layer, band, transforms));
  if (assessment.refused) throw QgsProcessingException(noteText(assessment.notes.front()));
  mGroundScale = assessment.ground_scale;
  for (const io::DemNote& note : assessment.notes)
    if (const QString text = noteText(note); !text.isEmpty()) mNotes << text;
  mFile = openFile(*layer, band);
  setGrid();
  if (mFile) return;
  const QString file = plainGdalFile(*layer);
  if (!file.isEmpty()) mSourceCells = rotatedSourceCells(file);
  if (mSourceCells) {
    mNotes << tr(
        "The raster is rotated: QGIS turns it north-up, and the cells it adds around it "
        "are left out as no data.");
  }
  mProvider.reset(layer->dataProvider()->clone());
  if (!mProvider) throw QgsProcessingException(tr("Could not open the raster's data provider."));
}

QString RasterGrid::noteText(const io::DemNote& note) {
  const auto number = [&note](std::size_t k) { return note.numbers.at(k); };
  const QString text = QString::fromStdString(note.text);
  switch (note.code) {
    case io::DemNoteCode::colour_image:
      return tr("Band %1 of the raster's %2 is a colour channel (red, green, blue or alpha) of an "
                "image, not heights: choose a DEM.")
          .arg(number(1))
          .arg(number(0));
    case io::DemNoteCode::too_far:
      if (!std::isfinite(number(0)))
        return tr(
            "A corner of the raster lies at a coordinate that is not a finite number: its "
            "georeferencing is wrong. Set its corners, for example with gdal_edit.py "
            "-a_ullr WEST NORTH EAST SOUTH.");
      return tr("The raster's corners lie up to %L1 from the CRS's origin, too far for coordinates "
                "to tell a thousandth of its %L2 cells apart: its georeferencing is wrong. Set "
                "its corners, for example with gdal_edit.py -a_ullr WEST NORTH EAST SOUTH.")
          .arg(number(0), 0, 'g', 3)
          .arg(number(1), 0, 'g', 3);
    case io::DemNoteCode::geographic_crs:
      return tr("The raster is in a geographic CRS (%1): its cell sizes are degrees, not metres "
                "like its heights. Reproject it to a metric CRS first, for example with Raster > "
                "Projections > Warp (Reproject) to the UTM zone of the area.")
          .arg(text);
    case io::DemNoteCode::no_crs:
      return tr(
          "The raster has no CRS: cell sizes are taken as metres and the outputs have no "
          "CRS.");
    case io::DemNoteCode::mercator_scaled:
      return tr("Mercator projection: map units are not ground metres here; cell sizes are "
                "scaled by cos(latitude of the centre) = %L1.")
          .arg(number(0), 0, 'f', 4);
    case io::DemNoteCode::unit_not_metre:
      return tr("The CRS's unit is %1, not the metre: the heights must be in %1 too, and "
                "depths and lengths come out in %1.")
          .arg(text);
    case io::DemNoteCode::several_bands:
      return tr("The raster has %1 bands; band %2 is used.").arg(number(0)).arg(number(1));
    case io::DemNoteCode::fill_value:
      return tr("Some heights are %1, a common fill value: if those cells have no data, set "
                "it as the layer's no data value (Layer Properties > Transparency) or in the "
                "file.")
          .arg(number(0));
    case io::DemNoteCode::fill_taken:
      return tr("Some heights are %1, a fill value (of magnitude 1e30 or more, as float's) that "
                "no terrain has: those cells are taken as no data.")
          .arg(number(0));
    case io::DemNoteCode::implausible_relief:
      return tr("Heights span %1 over a raster %2 across, more than any terrain: if they are "
                "millimetres or centimetres, give the band a scale in the file (gdal_edit.py "
                "-scale 0.001).")
          .arg(number(0))
          .arg(number(1));
    case io::DemNoteCode::scaled_values:      // the provider applies the band's scale: heights
    case io::DemNoteCode::assumed_cell_size:  // a layer always has its extent
    case io::DemNoteCode::cell_size_ignored:
      break;
  }
  return {};
}

std::unique_ptr<io::BandWindows> RasterGrid::openFile(QgsRasterLayer& layer, int band) const {
  QgsRasterDataProvider& provider = *layer.dataProvider();
  const bool sourceNoData =
      !provider.sourceHasNoDataValue(band) || provider.useSourceNoDataValue(band);
  const QString path = plainGdalFile(layer);
  if (path.isEmpty() || !sourceNoData || !provider.userNoDataValues(band).isEmpty()) {
    return nullptr;
  }
  std::unique_ptr<io::BandWindows> file;
  try {
    file = std::make_unique<io::BandWindows>(QFile::encodeName(path).toStdString(), band);
  } catch (const Error&) {
    return nullptr;
  }
  // The same grid as the layer's: QGIS shows a rotated raster through a warped copy.
  GeoTransform gt;
  const double dx = mExtent.width() / mCols, dy = mExtent.height() / mRows;
  const auto near = [](double a, double b, double cell) { return std::abs(a - b) <= 1e-6 * cell; };
  if (file->rows() != static_cast<std::size_t>(mRows) ||
      file->cols() != static_cast<std::size_t>(mCols) || !file->geotransform(gt) ||
      gt.a[2] != 0.0 || gt.a[4] != 0.0 || !near(gt.a[0], mExtent.xMinimum(), dx) ||
      !near(gt.a[3], mExtent.yMaximum(), dy) || !near(gt.a[1], dx, dx) || !near(-gt.a[5], dy, dy)) {
    return nullptr;
  }
  return file;
}

RasterGrid::~RasterGrid() = default;

std::optional<RasterGrid::SourceCells> RasterGrid::rotatedSourceCells(const QString& path) {
  GDALDatasetH dataset = GDALOpen(QFile::encodeName(path).constData(), GA_ReadOnly);
  if (!dataset) return std::nullopt;
  double gt[6];
  SourceCells cells{};
  const bool rotated = GDALGetGeoTransform(dataset, gt) == CE_None && (gt[2] != 0 || gt[4] != 0) &&
                       GDALInvGeoTransform(gt, cells.toPixel);
  cells.cols = GDALGetRasterXSize(dataset);
  cells.rows = GDALGetRasterYSize(dataset);
  GDALClose(dataset);
  if (!rotated) return std::nullopt;
  return cells;
}

bool RasterGrid::SourceCells::cover(double x, double y) const {
  const double col = toPixel[0] + x * toPixel[1] + y * toPixel[2];
  const double row = toPixel[3] + x * toPixel[4] + y * toPixel[5];
  return col >= 0 && col < cols && row >= 0 && row < rows;
}

void RasterGrid::setGrid() {
  // A file read straight through GDAL keeps its own geotransform, as the command line does: the
  // layer's extent divided by its size may differ from it in the last digits.
  if (!mFile || !mFile->geotransform(mGeoTransform)) {
    mGeoTransform.a = {
        mExtent.xMinimum(),       mExtent.width() / mCols, 0.0, mExtent.yMaximum(), 0.0,
        -mExtent.height() / mRows};
  }
  mGrid = {static_cast<std::size_t>(mRows), static_cast<std::size_t>(mCols),
           mGeoTransform.a[1] * mGroundScale, -mGeoTransform.a[5] * mGroundScale};
  withCoreErrors([&] { return make_frame(mGrid, 90.0); });  // a grid no view could address
}

void RasterGrid::setView(double azimuthDeg) {
  mFrame = withCoreErrors([&] { return make_frame(mGrid, azimuthDeg); });
}

DemSource RasterGrid::source() const {
  return {mGrid, mGeoTransform,
          [this](const DemWindow& w, float* heights) { readWindow(w, heights); }};
}

HeldDem RasterGrid::held() const {
  return {mOriented, mFrame, source(), lowestHeight(), mGroundScale};
}

void RasterGrid::readWindow(const DemWindow& w, float* heights) const {
  if (mFile) {
    mFile->read(w, heights);
    return;
  }
  // In blocks of at most 4 MiB: memory the allocator reuses from block to block, where one
  // block per window would be fresh pages for every strip.
  const double dx = mExtent.width() / mCols, dy = mExtent.height() / mRows;
  const std::size_t blockRows = std::max<std::size_t>(1, (std::size_t{1} << 20) / w.cols);
  for (std::size_t top = w.row0; top < w.row0 + w.rows; top += blockRows) {
    const std::size_t count = std::min(blockRows, w.row0 + w.rows - top);
    const QgsRectangle rect(mExtent.xMinimum() + static_cast<double>(w.col0) * dx,
                            mExtent.yMaximum() - static_cast<double>(top + count) * dy,
                            mExtent.xMinimum() + static_cast<double>(w.col0 + w.cols) * dx,
                            mExtent.yMaximum() - static_cast<double>(top) * dy);
    std::unique_ptr<QgsRasterBlock> block(
        mProvider->block(mBand, rect, static_cast<int>(w.cols), static_cast<int>(count)));
    if (!block || !block->isValid()) {
      throw QgsProcessingException(
          tr("Could not read rows %1 to %2 of the raster.").arg(top).arg(top + count - 1));
    }
    float* out = heights + (top - w.row0) * w.cols;
    copyHeights(*block, static_cast<int>(count), out);
    if (!mSourceCells) continue;
    for (std::size_t r = 0; r < count; ++r) {
      const double y = mExtent.yMaximum() - (static_cast<double>(top + r) + 0.5) * dy;
      for (std::size_t c = 0; c < w.cols; ++c) {
        const double x = mExtent.xMinimum() + (static_cast<double>(w.col0 + c) + 0.5) * dx;
        if (!mSourceCells->cover(x, y)) out[r * w.cols + c] = kNoData;
      }
    }
  }
}

double RasterGrid::lowestHeight() const {
  return mLowest;
}

void RasterGrid::read(double azimuthDeg, QgsProcessingFeedback* feedback, double progressFrom,
                      double progressTo) {
  setView(azimuthDeg);
  if (too_large_to_turn_whole(mFrame)) {
    throw QgsProcessingException(
        tr("The raster (%1 x %2 cells) is too large for this algorithm, which holds the whole DEM "
           "turned to the view: that would take more than half of this machine's memory. The "
           "Silhouettes algorithm reads large DEMs strip by strip; or clip or resample the DEM.")
            .arg(mCols)
            .arg(mRows));
  }
  try {
    readBlocks(feedback, progressFrom, progressTo);
  } catch (const Error& e) {
    throw QgsProcessingException(QString::fromStdString(e.what()));
  } catch (const std::bad_alloc&) {
    throw QgsProcessingException(
        tr("Not enough memory for a %1 x %2 raster.").arg(mCols).arg(mRows));
  }
}

void RasterGrid::readBlocks(QgsProcessingFeedback* feedback, double progressFrom,
                            double progressTo) {
  TurnedDem turned = turn_dem(
      mFrame,
      [this, feedback](const DemWindow& w, float* heights) {
        if (feedback && feedback->isCanceled()) throw QgsProcessingException(tr("Cancelled."));
        readWindow(w, heights);
      },
      [&](double done) {
        if (feedback) feedback->setProgress(progressFrom + (progressTo - progressFrom) * done);
      });
  mLowest = turned.lowest_height;
  mOriented = std::move(turned.oriented);
}

}  // namespace tsk::plugin
