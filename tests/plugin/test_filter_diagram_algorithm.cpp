// The slope filter diagram algorithm.
#include "plugin_test_support.h"

using namespace tsk::plugin_test;

TEST_CASE("the slope filter diagram is an HTML page with the filter drawn",
          "[plugin][filter diagram]") {
  QTemporaryDir dir;
  auto page = [&](int filter) {
    const Run run = runOk(kData + "/volcano.tif",
                          {{"CTRL_COL", 6}, {"FILTER", filter}, {"OUTPUT", dir.filePath("f.html")}},
                          dir, QStringLiteral("filterdiagram"));
    QFile file(run.results.value("OUTPUT").toString());
    REQUIRE(file.open(QIODevice::ReadOnly));
    return QString::fromUtf8(file.readAll());
  };
  const QString fixed = page(1);
  CHECK(fixed.startsWith("<!DOCTYPE html>"));
  CHECK(fixed.contains("<polygon id=\"removal\""));
  CHECK(fixed.contains("control point (6 %, 3.6 %)"));
  // Adapted, the diagram draws the cut-offs the run used: the volcano's slopes are steeper than
  // the thesis's terrain, so they are higher.
  const QString adapted = page(0);
  CHECK(adapted.contains("<polygon id=\"removal\""));
  CHECK_FALSE(adapted.contains("control point (6 %, 3.6 %)"));
}
