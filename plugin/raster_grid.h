// Adapter from a QGIS raster layer to the core's oriented grid: prepared on the main thread,
// read on the worker thread from the layer's file through GDAL, or through a clone of its data
// provider.
#pragma once

#include <qgscoordinatereferencesystem.h>
#include <qgsrectangle.h>

#include <QCoreApplication>
#include <QStringList>
#include <memory>
#include <optional>

#include "core/method/orient.h"
#include "core/method/run_recipes.h"
#include "core/method/silhouettes.h"
#include "core/method/strokes.h"
#include "io/read/dem_notes.h"

class QgsRasterBlock;
class QgsRasterDataProvider;
class QgsRasterLayer;
class QgsProcessingFeedback;
class QgsCoordinateTransformContext;

namespace tsk::io {
class BandWindows;
}

namespace tsk::plugin {

// Copies a raster block of `count` rows into `out` as floats with NaN for nodata.
void copyHeights(QgsRasterBlock& block, int count, float* out);

class RasterGrid {
  Q_DECLARE_TR_FUNCTIONS(RasterGrid)

 public:
  // Main thread. Throws QgsProcessingException for a missing layer, a band that does not exist or
  // a geographic CRS; notes() lists what the user should know (no CRS, Mercator scaling).
  RasterGrid(QgsRasterLayer* layer, int band, const QgsCoordinateTransformContext& transforms);
  ~RasterGrid();
  RasterGrid(const RasterGrid&) = delete;
  RasterGrid& operator=(const RasterGrid&) = delete;

  // Worker thread. Reads the band in blocks of rows into the grid oriented for `azimuthDeg`
  // (resampled along the line of sight for a non-cardinal azimuth), reporting progress from
  // `progressFrom` to `progressTo` percent; throws on cancel.
  void read(double azimuthDeg, QgsProcessingFeedback* feedback, double progressFrom,
            double progressTo);

  // Worker thread, for DEMs read strip by strip (any view): the DEM for sketch_silhouettes, read
  // window by window through this object, which must outlive it.
  DemSource source() const;
  // The DEM's lowest height, the plan-oblique reference (SPEC 1.9), once read() has read it.
  double lowestHeight() const;
  // Worker thread, once read(): the DEM held whole for the recipes (run_recipes.h), its windows
  // read through this object, which must outlive it.
  HeldDem held() const;

  const HeightGrid& oriented() const { return mOriented; }
  const OrientedFrame& frame() const { return mFrame; }
  const GeoTransform& geotransform() const { return mGeoTransform; }
  const QgsCoordinateReferenceSystem& crs() const { return mCrs; }
  const QgsRectangle& extent() const { return mExtent; }
  const QStringList& notes() const { return mNotes; }
  // True when the layer's file is read straight through GDAL (see openFile).
  bool readsFileDirectly() const { return mFile != nullptr; }

 private:
  // Sets the geotransform and the DEM's grid in ground units (main thread, once).
  void setGrid();
  // Sets the frame for a view.
  void setView(double azimuthDeg);
  // Reads the band in blocks of rows into mOriented.
  void readBlocks(QgsProcessingFeedback* feedback, double progressFrom, double progressTo);
  // The layer's file read straight through GDAL when that gives what its provider would: a GDAL
  // layer of one file whose grid is the layer's, without nodata set in QGIS (a band's scale and
  // offset are applied as the provider applies them). Null otherwise (the provider reads it).
  std::unique_ptr<io::BandWindows> openFile(QgsRasterLayer& layer, int band) const;
  // The user's words for a note on the DEM (io/dem_notes.h); empty for notes a layer never gets.
  static QString noteText(const io::DemNote& note);
  // Reads a window of the band, NaN for nodata.
  void readWindow(const DemWindow& window, float* heights) const;

  // The pixel domain of a rotated or sheared file: QGIS shows such a raster through a north-up
  // warped copy whose cells around the file's own are 0 when it has no nodata value, which would
  // draw its edges as cliffs.
  struct SourceCells {
    double toPixel[6];  // the file's geotransform inverted
    double cols, rows;
    bool cover(double x, double y) const;
  };
  static std::optional<SourceCells> rotatedSourceCells(const QString& path);

  std::unique_ptr<io::BandWindows> mFile;
  std::unique_ptr<QgsRasterDataProvider> mProvider;  // when mFile is null
  std::optional<SourceCells> mSourceCells;           // a rotated file read through mProvider
  int mBand = 1;
  int mCols = 0;
  int mRows = 0;
  QgsRectangle mExtent;
  QgsCoordinateReferenceSystem mCrs;
  double mGroundScale = 1.0;
  QStringList mNotes;
  HeightGrid mOriented;
  DemGrid mGrid;
  OrientedFrame mFrame;
  GeoTransform mGeoTransform;
  double mLowest = 0;  // known once the heights are read
};

}  // namespace tsk::plugin
