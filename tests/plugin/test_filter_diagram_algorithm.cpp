// The slope filter diagram algorithm.
#include "plugin_test_support.h"

using namespace tsk::plugin_test;

TEST_CASE("the slope filter diagram is an HTML page with the filter drawn",
          "[plugin][filter diagram]") {
  QTemporaryDir dir;
  const Run run =
      runOk(kData + "/volcano.tif", {{"CTRL_COL", 6}, {"OUTPUT", dir.filePath("filter.html")}}, dir,
            QStringLiteral("filterdiagram"));
  QFile file(run.results.value("OUTPUT").toString());
  REQUIRE(file.open(QIODevice::ReadOnly));
  const QString html = QString::fromUtf8(file.readAll());
  CHECK(html.startsWith("<!DOCTYPE html>"));
  CHECK(html.contains("<polygon id=\"removal\""));
  CHECK(html.contains("control point (6 %, 3.6 %)"));
}
