#!/usr/bin/python3
"""Draws the README's figure of the sample drawn for 1:50 000, 1:250 000 and 1:1 000 000, each
at its size on paper: the command line's SVG previews at 200 dpi, shown at half size.

    /usr/bin/python3 scripts/render_scales.py BUILD_DIR [OUT.png (docs/drawn_for_scales.png)]

1:50 000 shows the middle 85 x 85 cells of the sample (a 127 mm square: the whole DEM would be
about 65 cm wide). Needs rsvg-convert, GDAL's Python bindings, numpy and matplotlib.
"""
import os
import subprocess
import sys
import tempfile

import matplotlib
import numpy as np
from osgeo import gdal

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SAMPLE = os.path.join(ROOT, "resources", "sample", "jacksboro_utm16n.tif")
DPI = 200
FRAME_MM = 2  # white space between the strokes and a panel's frame


def preview(cli, dem, scale, page_mm, work):
    """The sketch of `dem` drawn for 1:scale at that scale, as a white RGB array at DPI."""
    svg = os.path.join(work, "s%d.svg" % scale)
    subprocess.run([cli, "silhouettes", dem, os.path.join(work, "s%d.gpkg" % scale),
                    "--drawn-for", str(scale), "--page-scale", str(scale), "--page",
                    "%dx%d" % (page_mm, page_mm), "--preview", svg], check=True)
    png = svg[:-4] + ".png"
    subprocess.run(["rsvg-convert", "-d", str(DPI), "-p", str(DPI), svg, "-o", png], check=True)
    return plt.imread(png)[:, :, :3]


def trimmed(image):
    """`image` cut to its strokes and FRAME_MM around them."""
    rows, cols = np.nonzero(image.mean(axis=2) < 0.9)
    pad = int(round(FRAME_MM / 25.4 * DPI))
    top, left = max(rows.min() - pad, 0), max(cols.min() - pad, 0)
    return image[top:rows.max() + pad + 1, left:cols.max() + pad + 1]


def half_size(image):
    """Each 2 x 2 block of pixels averaged: the figure at half size, its lines smoothed."""
    h, w = image.shape[0] // 2 * 2, image.shape[1] // 2 * 2
    return image[:h, :w].reshape(h // 2, 2, w // 2, 2, 3).mean(axis=(1, 3))


def middle_of(dem, cells, work):
    """The middle `cells` x `cells` of `dem`, as a GeoTIFF in `work`."""
    ds = gdal.Open(dem)
    col0, row0 = (ds.RasterXSize - cells) // 2, (ds.RasterYSize - cells) // 2
    out = os.path.join(work, "middle.tif")
    gdal.Translate(out, ds, srcWin=[col0, row0, cells, cells])
    return out


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    cli = os.path.join(os.path.abspath(sys.argv[1]), "cli", "terrain-sketch")
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "docs", "drawn_for_scales.png")
    with tempfile.TemporaryDirectory() as work:
        panels = [
            (preview(cli, middle_of(SAMPLE, 85, work), 50000, 260, work),
             "1:50 000 (a 127 mm square of the page)"),
            (preview(cli, SAMPLE, 250000, 300, work), "1:250 000 (the whole DEM)"),
            (preview(cli, SAMPLE, 1000000, 100, work), "1:1 000 000"),
        ]
    images = [half_size(trimmed(image)) for image, _ in panels]
    gap, label = 30, 40  # pixels between panels, and under them for the labels
    height = max(i.shape[0] for i in images) + label
    width = sum(i.shape[1] for i in images) + gap * (len(images) + 1)
    fig = plt.figure(figsize=(width / 100, height / 100), dpi=100)
    x = gap
    for image, (_, text) in zip(images, panels):
        h, w = image.shape[:2]
        ax = fig.add_axes([x / width, label / height, w / width, h / height])
        ax.imshow(image, interpolation="none")
        ax.set_xticks([])
        ax.set_yticks([])
        for spine in ax.spines.values():
            spine.set_color("#cccccc")
        fig.text(x / width, 0.35 * label / height, text, fontsize=13, color="#222222")
        x += w + gap
    fig.savefig(out, dpi=100, facecolor="white")
    print("wrote", out)


if __name__ == "__main__":
    main()
