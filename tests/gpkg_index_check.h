// Checks on a GeoPackage layer's spatial index: SQLite's own rtreecheck(), and window queries on
// the index against a brute-force test of every feature's box.
#pragma once

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "catch_compat.h"
#include "io/read/gdal_util.h"

namespace tsk::test {

struct Window {
  double x0, y0, x1, y1;
};

// A GeoPackage opened through GDAL, with the R-tree of its layer `layer`.
class IndexedGpkg {
 public:
  IndexedGpkg(const std::string& path, const std::string& layer, bool update = false)
      : layer_(layer), rtree_("rtree_" + layer + "_geom") {
    GDALAllRegister();
    dataset_.reset(static_cast<GDALDataset*>(
        GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | (update ? GDAL_OF_UPDATE : GDAL_OF_READONLY),
                   nullptr, nullptr, nullptr)));
    REQUIRE(dataset_);
  }

  GDALDataset& dataset() { return *dataset_; }
  OGRLayer& layer() {
    OGRLayer* l = dataset_->GetLayerByName(layer_.c_str());
    REQUIRE(l);
    return *l;
  }

  // The first field of every row `sql` gives.
  std::vector<std::string> first_column(const std::string& sql) {
    std::vector<std::string> values;
    OGRLayer* result = dataset_->ExecuteSQL(sql.c_str(), nullptr, nullptr);
    REQUIRE(result);
    for (auto& row : *result) values.emplace_back(row->GetFieldAsString(0));
    dataset_->ReleaseResultSet(result);
    return values;
  }

  long long page_size() { return std::stoll(first_column("PRAGMA page_size").at(0)); }
  std::string rtree_check() { return first_column("SELECT rtreecheck('" + rtree_ + "')").at(0); }
  long long indexed(const std::string& where = "1") {
    return std::stoll(first_column("SELECT count(*) FROM " + rtree_ + " WHERE " + where).at(0));
  }

  std::set<GIntBig> index_hits(const Window& w) {
    std::set<GIntBig> ids;
    for (const std::string& id : first_column(
             "SELECT id FROM " + rtree_ + " WHERE maxx >= " + std::to_string(w.x0) +
             " AND minx <= " + std::to_string(w.x1) + " AND maxy >= " + std::to_string(w.y0) +
             " AND miny <= " + std::to_string(w.y1))) {
      ids.insert(std::stoll(id));
    }
    return ids;
  }

  // Features whose geometry's box meets the window, by looking at every feature.
  std::set<GIntBig> box_hits(const Window& w) {
    std::set<GIntBig> ids;
    OGRLayer& l = layer();
    l.SetSpatialFilter(nullptr);
    for (auto& feature : l) {
      OGREnvelope e;
      feature->GetGeometryRef()->getEnvelope(&e);
      if (e.MaxX >= w.x0 && e.MinX <= w.x1 && e.MaxY >= w.y0 && e.MinY <= w.y1) {
        ids.insert(feature->GetFID());
      }
    }
    return ids;
  }

 private:
  io::DatasetPtr dataset_;
  std::string layer_, rtree_;
};

// The index is whole, holds every feature, and finds what a brute-force search finds in a grid
// of windows over the layer's extent, plus at most boxes within float rounding of a window.
inline void check_spatial_index(const std::string& path, const std::string& layer) {
  IndexedGpkg gpkg(path, layer);
  CHECK(gpkg.rtree_check() == "ok");
  CHECK(gpkg.indexed() == gpkg.layer().GetFeatureCount());
  OGREnvelope extent;
  REQUIRE(gpkg.layer().GetExtent(&extent) == OGRERR_NONE);
  const double w = (extent.MaxX - extent.MinX) / 5, h = (extent.MaxY - extent.MinY) / 5;
  // Two float steps at the largest coordinate: how far outwards the index may round a box.
  const double slack = std::ldexp(std::max({std::fabs(extent.MinX), std::fabs(extent.MaxX),
                                            std::fabs(extent.MinY), std::fabs(extent.MaxY)}),
                                  -22);
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      const Window window{extent.MinX + i * w, extent.MinY + j * h, extent.MinX + (i + 0.5) * w,
                          extent.MinY + (j + 0.5) * h};
      const std::set<GIntBig> by_index = gpkg.index_hits(window), by_box = gpkg.box_hits(window);
      CHECK(std::includes(by_index.begin(), by_index.end(), by_box.begin(), by_box.end()));
      const std::set<GIntBig> near_box = gpkg.box_hits(
          {window.x0 - slack, window.y0 - slack, window.x1 + slack, window.y1 + slack});
      CHECK(std::includes(near_box.begin(), near_box.end(), by_index.begin(), by_index.end()));
    }
  }
}

}  // namespace tsk::test
