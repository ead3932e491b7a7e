#include "io/pages/vector_art.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <locale>
#include <ostream>
#include <string>

#include "core/drawn/stroke_outline.h"
#include "io/pages/fixed_number.h"
#include "io/write/output_files.h"

namespace tsk::io {
namespace {

constexpr StrokeClass kClassOrder[] = {StrokeClass::formulated, StrokeClass::factual};

struct ClassLook {
  const char* id;
  const char* label;
  const char* svg_colour;
  double rgb[3];
};

ClassLook look(StrokeClass cls) {
  if (cls == StrokeClass::factual)
    return {"factual", "Factual silhouettes", "#111111", {0.067, 0.067, 0.067}};
  return {"formulated", "Formulated silhouettes", "#6e3e1c", {0.431, 0.243, 0.110}};
}

bool uniform(const std::vector<double>& widths) {
  return std::all_of(widths.begin(), widths.end(), [&](double w) { return w == widths.front(); });
}

// Calls draw(points, closed, width, ink) for each path of class `cls`: a line of one width, or a
// tapered stroke's filled outline (width 0).
template <typename Draw>
void class_paths(const SketchPage& page, const PlotterPage* plotter, std::size_t class_index,
                 Draw&& draw) {
  if (plotter) {
    for (const auto& line : plotter->classes[class_index].paths) draw(line, false, 0.0, 1.0);
    return;
  }
  for (const PagePath& p : page.paths) {
    if (p.cls != kClassOrder[class_index] || p.points.empty()) continue;
    if (uniform(p.widths)) {
      draw(p.points, false, p.widths.front(), p.ink);
    } else {
      draw(tapered_outline(p.points, p.widths), true, 0.0, p.ink);
    }
  }
}

// The class's colour `ink` of the way from white, each channel from 0 to 1.
std::array<double, 3> inked(const ClassLook& l, double ink) {
  std::array<double, 3> rgb{};
  for (int k = 0; k < 3; ++k) rgb[k] = 1.0 - ink * (1.0 - l.rgb[k]);
  return rgb;
}

// The colour as SVG writes it: the class's own at full ink.
std::string svg_colour(const ClassLook& l, double ink) {
  if (ink == 1.0) return l.svg_colour;
  const std::array<double, 3> rgb = inked(l, ink);
  char hex[8];
  std::snprintf(hex, sizeof hex, "#%02x%02x%02x", static_cast<unsigned>(std::lround(rgb[0] * 255)),
                static_cast<unsigned>(std::lround(rgb[1] * 255)),
                static_cast<unsigned>(std::lround(rgb[2] * 255)));
  return hex;
}

// Numbers as vector formats want them: a point for the decimal, no exponent.
void format_numbers(std::ostream& out) {
  out.imbue(std::locale::classic());
  out.setf(std::ios::fixed);
  out.precision(3);
}

}  // namespace

// Text as XML holds it.
std::string xml_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// The labels' layer: grey leaders, names in a sans-serif face.
void write_svg_labels(std::ostream& svg, const SketchPage& page) {
  if (page.labels.empty()) return;
  svg << "<g id=\"labels\" inkscape:label=\"Peaks\" inkscape:groupmode=\"layer\" "
         "font-family=\"sans-serif\" font-size=\""
      << page.label_size() << "\" fill=\"#333333\">\n";
  for (const PageLabel& l : page.labels) {
    svg << "<path d=\"M" << l.from.x << " " << l.from.y << " L" << l.to.x << " " << l.to.y
        << "\" fill=\"none\" stroke=\"#777777\" stroke-width=\"" << page.label_size() / 16
        << "\"/>\n<text x=\"" << l.to.x << "\" y=\"" << l.to.y << "\">" << xml_text(l.text)
        << "</text>\n";
  }
  svg << "</g>\n";
}

// Text as a PDF string in WinAnsi (Latin-1 for the letters it shares): UTF-8 decoded, what
// Latin-1 lacks as '?', and the string's special characters escaped.
std::string pdf_text(const std::string& text) {
  std::string out;
  for (std::size_t k = 0; k < text.size(); ++k) {
    unsigned code = static_cast<unsigned char>(text[k]);
    if (code >= 0xc0 && code < 0xe0 && k + 1 < text.size()) {
      code = ((code & 0x1fu) << 6) | (static_cast<unsigned char>(text[++k]) & 0x3fu);
    } else if (code >= 0x80) {
      while (k + 1 < text.size() && (static_cast<unsigned char>(text[k + 1]) & 0xc0u) == 0x80u) ++k;
      code = '?';
    }
    if (code > 0xff) code = '?';
    if (code == '(' || code == ')' || code == '\\') out += '\\';
    out += static_cast<char>(code);
  }
  return out;
}

PlotterPage plan_plotter_page(const SketchPage& page) {
  PlotterPage plotter;
  // Ends closer than a fifth of a millimetre (or of a pixel's width, 0.75 px) meet.
  const double meet = page.millimetres ? 0.2 : 0.75;
  for (StrokeClass cls : kClassOrder) {
    std::vector<std::vector<StrokePoint>> lines;
    for (const PagePath& p : page.paths)
      if (p.cls == cls && !p.points.empty()) lines.push_back(p.points);
    plotter.report.strokes += lines.size();
    PenPlan plan = plan_pen_paths(std::move(lines), meet, {0.0, 0.0});
    plotter.report.travel_before += plan.travel_before;
    plotter.report.travel_after += plan.travel_after;
    plotter.report.paths += plan.paths.size();
    plotter.classes.push_back(std::move(plan));
  }
  return plotter;
}

namespace {

// The page's strokes as SVG, one layer per class.
void svg_classes(std::ostream& svg, const SketchPage& page, const PlotterPage* plotter) {
  std::string path;  // one path's text, its storage reused
  for (std::size_t c = 0; c < 2; ++c) {
    const ClassLook l = look(kClassOrder[c]);
    svg << "<g id=\"" << l.id << "\" inkscape:label=\"" << l.label
        << "\" inkscape:groupmode=\"layer\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
    class_paths(page, plotter, c,
                [&](const std::vector<StrokePoint>& pts, bool closed, double w, double ink) {
                  path.assign("<path d=\"");
                  for (std::size_t k = 0; k < pts.size(); ++k) {
                    path += k == 0 ? "M" : " L";
                    append_fixed3(path, pts[k].x);
                    path += ' ';
                    append_fixed3(path, pts[k].y);
                  }
                  svg << path;
                  if (closed) {
                    svg << " Z\" fill=\"" << svg_colour(l, ink) << "\" stroke=\"none\"/>\n";
                  } else {
                    svg << "\" fill=\"none\" stroke=\"" << svg_colour(l, ink)
                        << "\" stroke-width=\"" << (plotter ? (page.millimetres ? 0.3 : 1.0) : w)
                        << "\"/>\n";
                  }
                });
    svg << "</g>\n";
  }
}

}  // namespace

void write_svg(const std::string& path, const SketchPage& page, const PlotterPage* plotter) {
  write_text_file(path, [&](std::ostream& svg) {
    format_numbers(svg);
    const char* unit = page.millimetres ? "mm" : "";
    svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" "
           "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\""
        << page.width << unit << "\" height=\"" << page.height << unit << "\" viewBox=\"0 0 "
        << page.width << " " << page.height << "\">\n";
    if (!page.description.empty()) svg << "<desc>" << xml_text(page.description) << "</desc>\n";
    if (!plotter) svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg_classes(svg, page, plotter);
    write_svg_labels(svg, page);
    svg << "</svg>\n";
  });
}

namespace {

// A PDF written as it is made: its objects numbered from 1 in the order they are begun, their
// offsets kept for the cross-reference table.
class PdfWriter {
 public:
  explicit PdfWriter(std::ostream& out) : out_(out) { out_ << "%PDF-1.5\n%\xe2\xe3\xcf\xd3\n"; }
  // Begins the next object, whose body goes to the stream returned until end_object().
  std::ostream& begin_object() {
    offsets_.push_back(static_cast<std::size_t>(out_.tellp()));
    out_ << offsets_.size() << " 0 obj\n";
    return out_;
  }
  void end_object() { out_ << "\nendobj\n"; }
  void object(const std::string& body) {
    begin_object() << body;
    end_object();
  }
  // The cross-reference table and the trailer; object 1 is the catalogue.
  void finish() {
    const auto xref = static_cast<std::size_t>(out_.tellp());
    out_ << "xref\n0 " << offsets_.size() + 1 << "\n0000000000 65535 f \n";
    for (std::size_t at : offsets_) {
      char line[24];
      std::snprintf(line, sizeof line, "%010zu 00000 n \n", at);
      out_ << line;
    }
    out_ << "trailer\n<< /Size " << offsets_.size() + 1 << " /Root 1 0 R >>\nstartxref\n"
         << xref << "\n%%EOF\n";
  }

 private:
  std::ostream& out_;
  std::vector<std::size_t> offsets_;
};

// Points of 1/72 inch, y up: millimetres and pixels (taken as points) turned over.
struct PdfPlace {
  double to_pt, height;  // page units to points; the page's height in points
  double x(const StrokePoint& p) const { return p.x * to_pt; }
  double y(const StrokePoint& p) const { return height - p.y * to_pt; }
};

// The page's strokes as a PDF content stream, a marked layer per class.
void pdf_strokes(std::ostream& content, const SketchPage& page, const PlotterPage* plotter,
                 const PdfPlace& at) {
  content << "1 J 1 j\n";
  std::string path;  // one path's operators, their storage reused
  for (std::size_t c = 0; c < 2; ++c) {
    const ClassLook l = look(kClassOrder[c]);
    content << "/OC /L" << c << " BDC\n"
            << l.rgb[0] << " " << l.rgb[1] << " " << l.rgb[2] << " RG " << l.rgb[0] << " "
            << l.rgb[1] << " " << l.rgb[2] << " rg\n";
    double current_ink = 1.0;
    class_paths(page, plotter, c,
                [&](const std::vector<StrokePoint>& pts, bool closed, double w, double ink) {
                  // Only lighter paths change the colour: the others stay as they were.
                  if (ink != current_ink) {
                    const std::array<double, 3> rgb = inked(l, ink);
                    content << rgb[0] << " " << rgb[1] << " " << rgb[2] << " RG " << rgb[0] << " "
                            << rgb[1] << " " << rgb[2] << " rg\n";
                    current_ink = ink;
                  }
                  path.clear();
                  for (std::size_t k = 0; k < pts.size(); ++k) {
                    append_fixed3(path, at.x(pts[k]));
                    path += ' ';
                    append_fixed3(path, at.y(pts[k]));
                    path += k ? " l\n" : " m\n";
                  }
                  content << path;
                  if (closed) {
                    content << "f\n";
                  } else {
                    content << (plotter ? (page.millimetres ? 0.3 : 1.0) : w) * at.to_pt
                            << " w S\n";
                  }
                });
    content << "EMC\n";
  }
}

// A panorama's peaks: grey leaders, then the names in Helvetica (/F1).
void pdf_labels(std::ostream& content, const SketchPage& page, const PdfPlace& at) {
  if (page.labels.empty()) return;
  content << "0.47 0.47 0.47 RG " << page.label_size() / 16 * at.to_pt << " w\n";
  for (const PageLabel& l : page.labels)
    content << at.x(l.from) << " " << at.y(l.from) << " m " << at.x(l.to) << " " << at.y(l.to)
            << " l S\n";
  content << "0.2 0.2 0.2 rg\n";
  for (const PageLabel& l : page.labels) {
    content << "BT /F1 " << page.label_size() * at.to_pt << " Tf " << at.x(l.to) << " "
            << at.y(l.to) << " Td (" << pdf_text(l.text) << ") Tj ET\n";
  }
}

}  // namespace

void write_pdf(const std::string& path, const SketchPage& page, const PlotterPage* plotter) {
  const double to_pt = page.millimetres ? 72.0 / 25.4 : 1.0;
  const PdfPlace at{to_pt, page.height * to_pt};
  write_text_file(path, [&](std::ostream& out) {
    format_numbers(out);
    PdfWriter pdf(out);
    pdf.object(
        "<< /Type /Catalog /Pages 2 0 R /OCProperties << /OCGs [5 0 R 6 0 R] /D << /Order "
        "[5 0 R 6 0 R] >> >> >>");
    pdf.object("<< /Type /Pages /Kids [3 0 R] /Count 1 >>");
    pdf.begin_object() << "<< /Type /Page /Parent 2 0 R /MediaBox [0 0 " << page.width * to_pt
                       << " " << at.height
                       << "] /Resources << /Properties << /L0 5 0 R /L1 6 0 R >> /Font << /F1 "
                          "7 0 R >> >> /Contents 4 0 R >>";
    pdf.end_object();
    // The content goes straight to the file: its length, known once it is written, is object 8.
    pdf.begin_object() << "<< /Length 8 0 R >>\nstream\n";
    const std::streamoff start = out.tellp();
    pdf_strokes(out, page, plotter, at);
    pdf_labels(out, page, at);
    const std::streamoff length = out.tellp() - start;
    out << "\nendstream";
    pdf.end_object();
    pdf.object(std::string("<< /Type /OCG /Name (") + look(kClassOrder[0]).label + ") >>");
    pdf.object(std::string("<< /Type /OCG /Name (") + look(kClassOrder[1]).label + ") >>");
    pdf.object("<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica /Encoding /WinAnsiEncoding >>");
    pdf.begin_object() << length;
    pdf.end_object();
    pdf.finish();
  });
}

}  // namespace tsk::io
