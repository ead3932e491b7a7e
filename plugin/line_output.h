// A line output of an algorithm, whole or not at all. The features go to the sink QGIS makes for
// the destination or, into a GeoPackage file, straight through SQLite (gpkg_line_sink.h). A file
// written whole is staged, and put in place with the run's other outputs when the run has done
// (io/write/output_set.h). An output that goes out of scope unfinished, or by an exception (the
// run failed or was cancelled, perhaps after this output was finished), is discarded: a
// GeoPackage's rows roll back, the staged file goes with its staging folder, and a layer QGIS
// added to a file that already existed is dropped. Features may be added from any one thread at a
// time.
#pragma once

#include <qgscoordinatereferencesystem.h>
#include <qgsfeature.h>
#include <qgsfeaturesink.h>
#include <qgsfields.h>
#include <qgsprocessingalgorithm.h>
#include <qgsprocessingcontext.h>
#include <qgsprocessingfeedback.h>

#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <QVariantMap>
#include <memory>

#include "core/method/strokes.h"
#include "io/write/destination_lock.h"
#include "io/write/output_set.h"

namespace tsk::plugin {

class GpkgLineSink;

// The file an output destination writes, as QGIS reads the destination: "ogr:" with a database
// adds (or replaces) a layer in that file when it exists; any other provider prefix ("memory:",
// "postgres:", ...) writes no file (empty); a plain path is a file QGIS writes whole.
QString destinationFile(const QString& target);

// Restores, when it goes, the layers `context` was to load on completion when it was made: what a
// check reads of the outputs (QGIS's parameterAsOutputLayer lists each as a layer to load, a new
// temporary file each time) must not leave layers that no run writes, which the dialog, sharing
// its context between the check and the run, reported as "not correctly generated".
class LayersToLoadKept {
 public:
  explicit LayersToLoadKept(QgsProcessingContext& context)
      : mContext(context), mKept(context.layersToLoadOnCompletion()) {}
  ~LayersToLoadKept() { mContext.setLayersToLoadOnCompletion(mKept); }
  LayersToLoadKept(const LayersToLoadKept&) = delete;
  LayersToLoadKept& operator=(const LayersToLoadKept&) = delete;

 private:
  QgsProcessingContext& mContext;
  QMap<QString, QgsProcessingContext::LayerDetails> mKept;
};

// Where output `key` of `algorithm` goes, read without asking QGIS to load it: QGIS's own
// parameterAsOutputLayer also lists a destination the dialog gave (with a project) as a layer to
// load, which for a temporary sink is a name ("memory:Factual silhouettes") that no layer has: the
// dialog then said the layer "was not correctly generated".
QString outputTarget(const QgsProcessingAlgorithm& algorithm, const QVariantMap& parameters,
                     const QString& key, QgsProcessingContext& context);

// Whether output `key` is a temporary output (QGIS's TEMPORARY_OUTPUT, as a string or in an output
// definition): QGIS makes up a new temporary file for it each time it is read, in a folder of its
// own, so a check that reads it leaves an empty folder behind and checks a file no run writes.
bool isTemporaryOutput(const QgsProcessingAlgorithm& algorithm, const QVariantMap& parameters,
                       const QString& key);

// Removes a dataset with the files its format keeps beside it (a shapefile's .shx, .dbf, ...).
void deleteDataset(const QString& path);

class LineOutput {
  Q_DECLARE_TR_FUNCTIONS(LineOutput)

 public:
  // Line output `key` of `algorithm` with `fields`, in `crs`, of LineString M when `measured`.
  // Throws QgsProcessingException with QGIS's message when the destination cannot be created. A
  // layer added to a file is locked for as long as the output lives (io/destination_lock.h):
  // another run writing the file, from QGIS or the command line, is waited for (said on
  // `feedback`, which can cancel the wait).
  LineOutput(const QgsProcessingAlgorithm& algorithm, const QVariantMap& parameters,
             const QString& key, QgsProcessingContext& context, const QgsFields& fields,
             const QgsCoordinateReferenceSystem& crs, QgsProcessingFeedback* feedback,
             bool measured = false);
  ~LineOutput();
  LineOutput(const LineOutput&) = delete;
  LineOutput& operator=(const LineOutput&) = delete;

  // QGIS's identifier of the output layer, for the algorithm's results.
  const QString& destination() const { return mDestination; }

  // Both throw QgsProcessingException with QGIS's message when the line cannot be written.
  void add(QgsFeature& feature);
  void add(const Stroke& stroke);  // with the fields of strokeFields()

  // Completes the output: a GeoPackage's extent, count and spatial index, its layer's
  // description (`note`, what made it), and its commit.
  void finish(const QString& note = QString());

  // How a run waits for another writing one of its files (io/destination_lock.h): said on
  // `feedback`, and ended by its Cancel (Cancelled is thrown).
  static io::OutputSet::Waiting waitingOn(QgsProcessingFeedback* feedback);

 private:
  // Stages `path` in the run's output set; returns where to write it.
  static QString stagedFile(const QString& path);
  static std::unique_ptr<io::DestinationLock> lockDestination(const QString& path,
                                                              QgsProcessingFeedback* feedback);
  [[noreturn]] void failWriting() const;
  void closeSink();
  void discard() noexcept;

  std::unique_ptr<io::DestinationLock> mLock;  // first made, last gone: after the sink closes
  QVariantMap mParameters;                     // for QGIS's message on a failed write
  QString mKey;
  QgsFields mFields;
  std::unique_ptr<QgsFeatureSink> mSink;
  GpkgLineSink* mGpkg = nullptr;  // mSink, when it writes through SQLite
  QString mDestination;
  QString mFile;  // the file holding the output (staged); empty for a memory layer or a database
  bool mStaged = false;  // mFile is staged in the run's output set
  QString mAddedLayer;   // the layer QGIS added to a file that existed before; empty: QGIS's file
  QStringList mFilesBefore;  // named after QGIS's file, there before it was made
  bool mFinished = false;
  int mExceptionsAtStart;  // exceptions in flight when the output was made
};

}  // namespace tsk::plugin
