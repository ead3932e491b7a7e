// The io/ layer's GDAL messages.
#include <cpl_error.h>

#include <string>

#include "catch_compat.h"
#include "io/read/gdal_util.h"

using namespace tsk;

TEST_CASE("a GDAL message quoting a whole script is shortened to its start and its reason",
          "[io]") {
  const io::GdalErrorCapture capture;
  const std::string script(2000, 's');
  CPLError(CE_Failure, CPLE_AppDefined, "sqlite3_exec(%s) failed: unable to open database file",
           script.c_str());
  const std::string message = capture.message();
  CHECK(message.size() < 400);
  CHECK(message.rfind("sqlite3_exec(sss", 0) == 0);
  CHECK_THAT(message, Catch::EndsWith("failed: unable to open database file"));
}
