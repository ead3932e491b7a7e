#include "preview.h"

#include <gdal_priv.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <locale>
#include <sstream>
#include <vector>

#include "gdal_util.h"
#include "output_files.h"
#include "plan_oblique.h"

namespace tsk::io {
namespace {

// A grey-level canvas on which pens darken pixels with anti-aliased discs.
class Canvas {
 public:
  Canvas(int width, int height)
      : width_(width), height_(height), ink_(static_cast<std::size_t>(width) * height, 0.f) {}

  void line(double x0, double y0, double x1, double y1, double radius, float darkness) {
    const double len = std::hypot(x1 - x0, y1 - y0);
    const int steps = std::max(1, static_cast<int>(std::ceil(len / 0.35)));
    for (int k = 0; k <= steps; ++k) {
      const double t = static_cast<double>(k) / steps;
      dot(x0 + t * (x1 - x0), y0 + t * (y1 - y0), radius, darkness);
    }
  }

  std::vector<GByte> pixels() const {
    std::vector<GByte> out(ink_.size());
    for (std::size_t k = 0; k < ink_.size(); ++k) {
      out[k] = static_cast<GByte>(std::lround(255.0 * (1.0 - std::min(1.f, ink_[k]))));
    }
    return out;
  }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void dot(double cx, double cy, double radius, float darkness) {
    const int x_lo = std::max(0, static_cast<int>(std::floor(cx - radius - 1)));
    const int x_hi = std::min(width_ - 1, static_cast<int>(std::ceil(cx + radius + 1)));
    const int y_lo = std::max(0, static_cast<int>(std::floor(cy - radius - 1)));
    const int y_hi = std::min(height_ - 1, static_cast<int>(std::ceil(cy + radius + 1)));
    for (int y = y_lo; y <= y_hi; ++y) {
      for (int x = x_lo; x <= x_hi; ++x) {
        const double dist = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
        const double coverage = std::clamp(radius + 0.5 - dist, 0.0, 1.0);
        float& v = ink_[static_cast<std::size_t>(y) * width_ + x];
        v = std::max(v, static_cast<float>(coverage) * darkness);
      }
    }
  }

  int width_, height_;
  std::vector<float> ink_;
};

// Where the strokes go on the picture: the profile plot, x across the view, y the
// plan-oblique position along it (from the lowest height), far side up.
struct PreviewLayout {
  int width = 0, height = 0;
  std::function<void(const ChainCell&, double&, double&)> to_screen;
};

PreviewLayout preview_layout(const HeightGrid& z, const OrientedFrame& frame,
                             const ViewParams& view, const PreviewOptions& options) {
  double z_min = std::numeric_limits<double>::infinity();
  double z_max = -z_min;
  for (std::size_t k = 0; k < z.size(); ++k) {
    if (is_data(z.data()[k])) {
      z_min = std::min(z_min, static_cast<double>(z.data()[k]));
      z_max = std::max(z_max, static_cast<double>(z.data()[k]));
    }
  }
  if (!std::isfinite(z_min)) z_min = z_max = 0.0;
  const double plot_w = std::max(frame.w, static_cast<double>(frame.profiles) * frame.w);
  const PlanObliqueShift shift(view, frame.d, z_min);
  const double plot_h = shift(static_cast<double>(frame.length), z_max) * frame.d;
  const int margin = 10;
  PreviewLayout layout;
  layout.width = std::clamp(options.width_px, 64, 20000);
  const double scale = (layout.width - 2.0 * margin) / plot_w;
  layout.height = std::clamp(static_cast<int>(std::ceil(plot_h * scale)) + 2 * margin, 64, 20000);
  const int height = layout.height;
  layout.to_screen = [&z, frame, shift, scale, height, margin](const ChainCell& c, double& sx,
                                                               double& sy) {
    const double zc =
        static_cast<double>(z(static_cast<std::size_t>(c.p), static_cast<std::size_t>(c.i)));
    sx = margin + (c.p + 0.5) * frame.w * scale;
    sy = height - margin - shift(c.i + 0.5, zc) * frame.d * scale;
  };
  return layout;
}

void write_png_preview(const std::string& path, const SilhouetteResult& result,
                       const PreviewLayout& layout) {
  Canvas canvas(layout.width, layout.height);
  // Formulated first so factual strokes stay on top.
  for (StrokeClass cls : {StrokeClass::formulated, StrokeClass::factual}) {
    const bool factual = cls == StrokeClass::factual;
    for (const Stroke& s : result.strokes) {
      if (s.cls != cls) continue;
      for (std::size_t k = 1; k < s.chain.size(); ++k) {
        double x0, y0, x1, y1;
        layout.to_screen(s.chain[k - 1], x0, y0);
        layout.to_screen(s.chain[k], x1, y1);
        canvas.line(x0, y0, x1, y1, factual ? 1.1 : 0.55, factual ? 1.f : 0.6f);
      }
    }
  }
  GDALAllRegister();
  GdalErrorCapture capture;
  std::vector<GByte> pixels = canvas.pixels();
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  GDALDriver* png = GetGDALDriverManager()->GetDriverByName("PNG");
  if (!mem || !png) throw Error("GDAL has no MEM or PNG driver");
  const int width = layout.width, height = layout.height;
  DatasetPtr image(mem->Create("", width, height, 1, GDT_Byte, nullptr));
  if (!image || image->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, width, height, pixels.data(),
                                                  width, height, GDT_Byte, 0, 0) != CE_None) {
    throw Error("cannot draw the preview: " + capture.message());
  }
  write_atomically(path, [&](const std::filesystem::path& staged) {
    DatasetPtr out(png->CreateCopy(staged.c_str(), image.get(), FALSE, nullptr, nullptr, nullptr));
    if (!out) throw Error("cannot write preview '" + path + "': " + capture.message());
  });
}

// Vector art: one group (an Illustrator or Inkscape layer) per class, one path per stroke, in the
// colours and widths of the QGIS styles; formulated first so that factual strokes lie on top.
void write_svg_preview(const std::string& path, const SilhouetteResult& result,
                       const PreviewLayout& layout) {
  std::ostringstream svg;
  svg.imbue(std::locale::classic());
  svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" "
         "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\""
      << layout.width << "\" height=\"" << layout.height << "\" viewBox=\"0 0 " << layout.width
      << " " << layout.height << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg.setf(std::ios::fixed);
  svg.precision(2);
  for (StrokeClass cls : {StrokeClass::formulated, StrokeClass::factual}) {
    const bool factual = cls == StrokeClass::factual;
    svg << "<g id=\"" << (factual ? "factual" : "formulated") << "\" inkscape:label=\""
        << (factual ? "Factual silhouettes" : "Formulated silhouettes")
        << "\" inkscape:groupmode=\"layer\" fill=\"none\" stroke=\""
        << (factual ? "#111111" : "#6e3e1c") << "\" stroke-width=\"" << (factual ? 2.2 : 1.1)
        << "\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
    for (const Stroke& s : result.strokes) {
      if (s.cls != cls || s.chain.empty()) continue;
      svg << "<path d=\"";
      for (std::size_t k = 0; k < s.chain.size(); ++k) {
        double x, y;
        layout.to_screen(s.chain[k], x, y);
        svg << (k == 0 ? "M" : " L") << x << " " << y;
      }
      svg << "\"/>\n";
    }
    svg << "</g>\n";
  }
  svg << "</svg>\n";
  write_text_file(path, svg.str());
}

}  // namespace

void write_preview(const std::string& path, const SilhouetteResult& result, const HeightGrid& z,
                   const OrientedFrame& frame, const ViewParams& view,
                   const PreviewOptions& options) {
  const PreviewLayout layout = preview_layout(z, frame, view, options);
  if (lowercase_extension(path) == ".svg") {
    write_svg_preview(path, result, layout);
  } else {
    write_png_preview(path, result, layout);
  }
}

}  // namespace tsk::io
