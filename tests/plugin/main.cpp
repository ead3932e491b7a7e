// Headless QGIS for the plugin tests: QgsApplication on the main thread, offscreen.
#define CATCH_CONFIG_RUNNER
#include <qgsapplication.h>

#include "catch_compat.h"

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QgsApplication app(argc, argv, false);
  QgsApplication::setPrefixPath(QStringLiteral("/usr"), true);
  QgsApplication::initQgis();
  const int rc = Catch::Session().run(argc, argv);
  QgsApplication::exitQgis();
  return rc;
}
