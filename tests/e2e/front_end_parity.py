"""Both front ends give the same outputs: every algorithm run through the command line and through
the QGIS plugin (headless, through Processing as the dialog runs it) on the same DEM and options,
and the outputs compared: vector rows (geometry with M, attributes) and raster cells. Then the
panorama of a DEM warped to Web Mercator must see what the panorama of the UTM DEM sees.

Usage (QGIS's Python): /usr/bin/python3 front_end_parity.py BUILD_DIR REPO_DIR WORK_DIR
Prints one line per check and 'N passed, N failed'; exits 1 on any failure.
"""
import math
import os
import subprocess
import sys

import numpy as np

build, repo, work = (os.path.abspath(a) for a in sys.argv[1:4])
os.makedirs(work, exist_ok=True)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import headless_qgis  # noqa: E402

app = headless_qgis.start(build)
from osgeo import gdal, ogr, osr  # noqa: E402
from qgis import processing  # noqa: E402

gdal.UseExceptions()
CLI = os.path.join(build, "cli", "terrain-sketch")
SAMPLE = os.path.join(repo, "resources", "sample", "jacksboro_utm16n.tif")
SUMMIT = (749008.1394, 4009477.9308)  # the sample's summit (scripts/demo.sh)
results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    results["passed" if ok else "failed"] += 1
    print(("ok      " if ok else "FAILED  ") + name + ("" if ok else ": " + detail), flush=True)


def warped_to_mercator(path):
    out = os.path.join(work, "sample_3857.tif")
    gdal.Warp(out, path, dstSRS="EPSG:3857", resampleAlg="bilinear", dstNodata=-9999)
    return out


def with_nodata_hole(path):
    """The sample with a block of nodata inside it and a ragged edge."""
    out = os.path.join(work, "sample_hole.tif")
    gdal.Translate(out, path)
    ds = gdal.Open(out, gdal.GA_Update)
    band = ds.GetRasterBand(1)
    nodata = band.GetNoDataValue()
    values = band.ReadAsArray()
    values[150:230, 120:260] = nodata
    for row in range(values.shape[0]):
        values[row, : (row * 7) % 23] = nodata
    band.WriteArray(values)
    ds = None
    return out


def srs(epsg):
    s = osr.SpatialReference()
    s.ImportFromEPSG(epsg)
    s.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    return s


def transform_point(x, y, from_epsg, to_epsg):
    px, py, _ = osr.CoordinateTransformation(srs(from_epsg), srs(to_epsg)).TransformPoint(x, y)
    return px, py


# Hills of an analytic terrain about the sample's summit, 300 km across so that the earth's
# curvature (and a wrong ground scale) shows: (east, north, height, sigma) in metres.
HILLS = [(30000, 20000, 600, 17500), (-37500, 50000, 450, 22500), (62500, -45000, 700, 20000),
         (-75000, -62500, 500, 30000), (95000, 75000, 650, 25000), (12500, -100000, 400, 15000),
         (-105000, 12500, 550, 17500), (75000, 12500, 350, 12500)]


def analytic_dem(path, epsg, x0, y0, cell, size):
    """The analytic terrain sampled at the cell centres of a grid in EPSG:`epsg`: heights of the
    same ground in any CRS, free of resampling."""
    xs = x0 + (np.arange(size) + 0.5) * cell
    ys = y0 - (np.arange(size) + 0.5) * cell
    gx, gy = np.meshgrid(xs, ys)
    if epsg != 32616:
        points = np.column_stack([gx.ravel(), gy.ravel()]).tolist()
        utm = np.array(osr.CoordinateTransformation(srs(epsg), srs(32616)).TransformPoints(points))
        gx, gy = utm[:, 0].reshape(gx.shape), utm[:, 1].reshape(gy.shape)
    heights = 200 + 0.002 * (gx - SUMMIT[0])
    for east, north, height, sigma in HILLS:
        r2 = (gx - SUMMIT[0] - east) ** 2 + (gy - SUMMIT[1] - north) ** 2
        heights = heights + height * np.exp(-r2 / (2 * sigma * sigma))
    ds = gdal.GetDriverByName("GTiff").Create(path, size, size, 1, gdal.GDT_Float32)
    ds.SetGeoTransform((x0, cell, 0, y0, 0, -cell))
    ds.SetProjection(srs(epsg).ExportToWkt())
    ds.GetRasterBand(1).WriteArray(heights.astype(np.float32))
    ds = None
    return path


def analytic_pair():
    """The analytic terrain on a UTM grid of 500 m cells and on a Web Mercator grid of the same
    ground size, both about the summit; and the summit in Web Mercator."""
    half, cell, size = 150000, 500, 600
    utm = analytic_dem(os.path.join(work, "analytic_utm.tif"), 32616, SUMMIT[0] - half,
                       SUMMIT[1] + half, cell, size)
    mx, my = transform_point(*SUMMIT, 32616, 3857)
    scale = 1 / math.cos(math.radians(transform_point(*SUMMIT, 32616, 4326)[1]))
    merc = analytic_dem(os.path.join(work, "analytic_3857.tif"), 3857, mx - half * scale,
                        my + half * scale, cell * scale, size)
    return utm, merc, (mx, my)


def rows(path, layer=None, where=None):
    """The rows of a vector layer: geometry as ISO WKT (with M) and attributes, sorted."""
    ds = ogr.Open(path)
    lyr = ds.GetLayerByName(layer) if layer else ds.GetLayer(0)
    if where:
        lyr.SetAttributeFilter(where)
    defn = lyr.GetLayerDefn()
    names = [defn.GetFieldDefn(k).GetName() for k in range(defn.GetFieldCount())]
    out = []
    for f in lyr:
        g = f.GetGeometryRef()
        attrs = tuple((n, f.GetField(n)) for n in names if n != "class")
        out.append((g.ExportToIsoWkt() if g else "", attrs))
    return sorted(out)


def cells(path):
    ds = gdal.Open(path)
    return (ds.RasterXSize, ds.RasterYSize, ds.GetGeoTransform(),
            [ds.GetRasterBand(b + 1).ReadRaster() for b in range(ds.RasterCount)])


def cli(*args):
    proc = subprocess.run([CLI, *args], capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError(f"terrain-sketch {' '.join(args)}: {proc.stderr.strip()}")


def qgis(algorithm, params):
    return processing.run("terrainsketch:" + algorithm, params)


def compare_rows(name, a, b):
    first = next((k for k, (x, y) in enumerate(zip(a, b)) if x != y), None)
    detail = f"{len(a)} rows against {len(b)}"
    if first is not None:
        detail += f"; first difference at row {first}: {a[first]!r} against {b[first]!r}"[:600]
    check(name, len(a) > 0 and a == b, detail)


def compare_cells(name, a, b):
    same_grid = a[:3] == b[:3]
    check(name, same_grid and a[3] == b[3],
          f"grid {a[:3]} against {b[:3]}" if not same_grid else "cell values differ")


def silhouettes(tag, dem, azimuth):
    out = os.path.join(work, f"{tag}_az{azimuth:g}")
    cli("silhouettes", dem, out + "_cli.gpkg", "--azimuth", str(azimuth), "--geometry", "oblique")
    qgis("silhouettes", {"INPUT": dem, "AZIMUTH": azimuth, "GEOMETRY": 1,
                         "FACTUAL": out + "_f.gpkg", "FORMULATED": out + "_o.gpkg"})
    for cls, path in (("factual", out + "_f.gpkg"), ("formulated", out + "_o.gpkg")):
        compare_rows(f"{tag}: silhouettes azimuth {azimuth:g}, {cls}",
                     rows(out + "_cli.gpkg", where=f"class = '{cls}'"), rows(path))


def rasters(tag, dem):
    out = os.path.join(work, tag)
    for algorithm, command, extra_cli, extra_qgis in (
            ("classification", "classify", [], {}),
            ("rowslope", "row-slope", [], {}),
            ("drape", "drape", ["--source", dem], {"SOURCE": dem})):
        cli(command, dem, f"{out}_{command}_cli.tif", "--azimuth", "180", *extra_cli)
        qgis(algorithm, {"INPUT": dem, "AZIMUTH": 180, "OUTPUT": f"{out}_{command}_qgis.tif",
                         **extra_qgis})
        compare_cells(f"{tag}: {algorithm}", cells(f"{out}_{command}_cli.tif"),
                      cells(f"{out}_{command}_qgis.tif"))


def line_products(tag, dem):
    out = os.path.join(work, tag)
    cli("pstrokes", dem, out + "_ps_cli.gpkg", "--geometry", "oblique")
    qgis("pstrokes", {"INPUT": dem, "GEOMETRY": 1, "OUTPUT": out + "_ps_qgis.gpkg"})
    compare_rows(f"{tag}: pstrokes", rows(out + "_ps_cli.gpkg"), rows(out + "_ps_qgis.gpkg"))
    cli("profiles", dem, out + "_pp_cli.gpkg", "--every", "7")
    qgis("profileplot", {"INPUT": dem, "EVERY": 7, "OUTPUT": out + "_pp_qgis.gpkg"})
    compare_rows(f"{tag}: profile plot", rows(out + "_pp_cli.gpkg"), rows(out + "_pp_qgis.gpkg"))
    cli("filter-plot", dem, out + "_fd_cli.html")
    qgis("filterdiagram", {"INPUT": dem, "OUTPUT": out + "_fd_qgis.html"})
    svg = []
    for path in (out + "_fd_cli.html", out + "_fd_qgis.html"):
        with open(path, encoding="utf-8") as page:
            svg.append(page.read().split("<svg", 1)[-1])
    check(f"{tag}: filter diagram", svg[0] == svg[1], "the diagrams' SVG differ")


def panorama(tag, dem, observer, epsg, per_cell=1):
    """The panorama through both front ends, the observer 2 m above the ground, `per_cell`
    samples a cell along each ray; returns their visibility rasters."""
    out = os.path.join(work, tag)
    cli("panorama", dem, out + "_pan_cli.gpkg", "--observer", f"{observer[0]},{observer[1]}",
        "--observer-height", "2", "--visibility", out + "_seen_cli.tif",
        "--samples-per-cell", str(per_cell))
    qgis("panorama", {"INPUT": dem, "OBSERVER": f"{observer[0]},{observer[1]} [EPSG:{epsg}]",
                      "OBSERVER_HEIGHT": 2, "SAMPLES_PER_CELL": per_cell,
                      "MAP_OUTPUT": out + "_map_qgis.gpkg",
                      "PANORAMA_OUTPUT": out + "_view_qgis.gpkg",
                      "VISIBILITY": out + "_seen_qgis.tif"})
    compare_rows(f"{tag}: panorama on the map", rows(out + "_pan_cli.gpkg", "map"),
                 rows(out + "_map_qgis.gpkg"))
    compare_rows(f"{tag}: panorama", rows(out + "_pan_cli.gpkg", "panorama"),
                 rows(out + "_view_qgis.gpkg"))
    compare_cells(f"{tag}: panorama visibility", cells(out + "_seen_cli.tif"),
                  cells(out + "_seen_qgis.tif"))
    return out + "_seen_cli.tif", out + "_seen_qgis.tif"


def visibility_agreement(utm_seen, mercator_seen):
    """Share of the UTM raster's cells in range whose class the Mercator raster gives too, at the
    same place on the ground (its nearest cell); the share whose class it gives within a cell of
    that place; and how many cells were compared."""
    utm, merc = gdal.Open(utm_seen), gdal.Open(mercator_seen)
    a, b = utm.GetRasterBand(1).ReadAsArray(), merc.GetRasterBand(1).ReadAsArray()
    gt_a, gt_b = utm.GetGeoTransform(), merc.GetGeoTransform()
    gx, gy = np.meshgrid(gt_a[0] + (np.arange(a.shape[1]) + 0.5) * gt_a[1],
                         gt_a[3] + (np.arange(a.shape[0]) + 0.5) * gt_a[5])
    to_merc = osr.CoordinateTransformation(srs(32616), srs(3857))
    merc_xy = np.array(to_merc.TransformPoints(np.column_stack([gx.ravel(), gy.ravel()]).tolist()))
    cols = np.floor((merc_xy[:, 0] - gt_b[0]) / gt_b[1]).astype(int)
    rows = np.floor((merc_xy[:, 1] - gt_b[3]) / gt_b[5]).astype(int)
    inside = (cols >= 1) & (cols < b.shape[1] - 1) & (rows >= 1) & (rows < b.shape[0] - 1)
    seen_a, rows, cols = a.ravel()[inside], rows[inside], cols[inside]
    seen_b = b[rows, cols]
    both = (seen_a != 255) & (seen_b != 255)
    near = np.zeros(seen_a.shape, bool)
    for dr in (-1, 0, 1):
        for dc in (-1, 0, 1):
            near |= b[rows + dr, cols + dc] == seen_a
    return (float(np.mean(seen_a[both] == seen_b[both])), float(np.mean(near[both])),
            int(both.sum()))


mercator = warped_to_mercator(SAMPLE)
hole = with_nodata_hole(SAMPLE)
topobathy = os.path.join(repo, "tests", "data", "topobathy_3857.tif")
topo = gdal.Open(topobathy)
topo_gt = topo.GetGeoTransform()
topo_centre = (topo_gt[0] + topo_gt[1] * topo.RasterXSize * 0.5,
               topo_gt[3] + topo_gt[5] * topo.RasterYSize * 0.5)
topo = None
summit_3857 = transform_point(*SUMMIT, 32616, 3857)

for tag, dem in (("utm", SAMPLE), ("mercator", mercator), ("topobathy", topobathy),
                 ("nodata", hole)):
    for azimuth in (90, 200):
        silhouettes(tag, dem, azimuth)
    rasters(tag, dem)
    line_products(tag, dem)

utm_seen = panorama("utm", SAMPLE, SUMMIT, 32616)
merc_seen = panorama("mercator", mercator, summit_3857, 3857)
panorama("topobathy", topobathy, topo_centre, 3857)
panorama("nodata", hole, SUMMIT, 32616)
# The sample warped to Web Mercator has new heights, resampled (bilinear): its panorama differs
# from the UTM one as much as a panorama of the sample resampled in its own CRS does. Figures
# only, at one and at four samples a cell (docs/PANORAMA.md 1.1).
fine_seen = (panorama("utm_fine", SAMPLE, SUMMIT, 32616, 4),
             panorama("mercator_fine", mercator, summit_3857, 3857, 4))
for front_end, k in (("command line", 0), ("QGIS", 1)):
    for per_cell, (utm, merc) in ((1, (utm_seen, merc_seen)), (4, fine_seen)):
        share, near, total = visibility_agreement(utm[k], merc[k])
        print(f"sample, UTM against warped to Web Mercator, {per_cell} sample(s) a cell "
              f"({front_end}): {100 * share:.2f} % of {total} cells agree, "
              f"{100 * near:.2f} % within a cell")
# The same ground on both grids: what the observer sees must not depend on the CRS. A Mercator
# panorama measured in map units instead of ground metres sees 97 % of it.
analytic_utm, analytic_merc, analytic_observer = analytic_pair()
utm_seen = panorama("analytic_utm", analytic_utm, SUMMIT, 32616)
merc_seen = panorama("analytic_mercator", analytic_merc, analytic_observer, 3857)
for front_end, k in (("command line", 0), ("QGIS", 1)):
    share, _, total = visibility_agreement(utm_seen[k], merc_seen[k])
    check(f"Web Mercator panorama sees what the UTM one sees ({front_end}): {100 * share:.2f} %",
          share >= 0.99 and total > 300000, f"{100 * share:.2f} % of {total} cells")

print(f"front-end parity: {results['passed']} passed, {results['failed']} failed")
app.exitQgis()
sys.exit(1 if results["failed"] else 0)
