// Prints the time to give a GeoPackage layer of line features its spatial index, two ways: this
// project's bulk R-tree loader (io/gpkg_spatial_index) and GDAL's own CreateSpatialIndex, which
// GDAL 3.8 and later also load in bulk. A figure, never a timed test.
//   tsk_gpkg_index_bench LINES.gpkg [RUNS]
// LINES.gpkg: one line layer without a spatial index (ogr2ogr -lco SPATIAL_INDEX=NO), e.g. the
// silhouettes of the 8000^2 benchmark DEM.
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "io/gpkg/gpkg_spatial_index.h"
#include "io/read/gdal_util.h"

namespace {

using Clock = std::chrono::steady_clock;

tsk::io::DatasetPtr open_copy(const std::string& source, const std::string& copy) {
  std::filesystem::copy_file(source, copy, std::filesystem::copy_options::overwrite_existing);
  return tsk::io::DatasetPtr(static_cast<GDALDataset*>(
      GDALOpenEx(copy.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE, nullptr, nullptr, nullptr)));
}

// Seconds for this project's loader, the boxes read beforehand (the writer has them at hand).
double own_loader(const std::string& source, const std::string& copy) {
  tsk::io::DatasetPtr ds = open_copy(source, copy);
  OGRLayer* layer = ds->GetLayer(0);
  tsk::io::IndexBoxes boxes;
  for (auto& feature : *layer) {
    OGREnvelope e;
    feature->GetGeometryRef()->getEnvelope(&e);
    boxes.push_back({feature->GetFID(), e.MinX, e.MaxX, e.MinY, e.MaxY});
  }
  const std::string table = layer->GetName();
  const auto start = Clock::now();
  ds->StartTransaction();
  tsk::io::add_gpkg_spatial_index(*ds, table, boxes);
  ds->CommitTransaction();
  ds.reset();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Seconds for GDAL's CreateSpatialIndex.
double gdal_loader(const std::string& source, const std::string& copy) {
  tsk::io::DatasetPtr ds = open_copy(source, copy);
  OGRLayer* layer = ds->GetLayer(0);
  const std::string sql = std::string("SELECT CreateSpatialIndex('") + layer->GetName() + "', '" +
                          layer->GetGeometryColumn() + "')";
  const auto start = Clock::now();
  ds->StartTransaction();
  ds->ReleaseResultSet(ds->ExecuteSQL(sql.c_str(), nullptr, nullptr));
  ds->CommitTransaction();
  ds.reset();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: tsk_gpkg_index_bench LINES.gpkg [RUNS]\n");
    return 2;
  }
  GDALAllRegister();
  const std::string source = argv[1];
  const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  const std::string copy = (std::filesystem::temp_directory_path() / "tsk_index_bench.gpkg");
  std::vector<double> own, gdal;
  for (int k = 0; k < runs; ++k) {  // alternated, so that both see the same machine
    own.push_back(own_loader(source, copy));
    gdal.push_back(gdal_loader(source, copy));
  }
  std::filesystem::remove(copy);
  tsk::io::DatasetPtr ds(static_cast<GDALDataset*>(
      GDALOpenEx(source.c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr)));
  std::printf(
      "GDAL %s, %lld features, medians of %d runs: own bulk R-tree %.3f s, GDAL's "
      "CreateSpatialIndex %.3f s\n",
      GDALVersionInfo("RELEASE_NAME"), static_cast<long long>(ds->GetLayer(0)->GetFeatureCount()),
      runs, median(own), median(gdal));
  return 0;
}
