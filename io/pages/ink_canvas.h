// The PNG preview's canvas: grey levels darkened by round-capped pen lines, anti-aliased.
#pragma once

#include <cstdint>
#include <vector>

namespace tsk::io {

class InkCanvas {
 public:
  InkCanvas(int width, int height);

  // Inks the pixels within `radius` (pixels) of the segment from (x0, y0) to (x1, y1), where x
  // runs right and y down from the canvas's top left corner. A pixel whose centre lies d from the
  // segment takes `darkness` times its coverage, min(1, radius + 0.5 - d) when that is positive;
  // where lines cross, the darker ink stays. A segment off the canvas, or with a coordinate or
  // radius that is not a finite number, inks nothing.
  void line(double x0, double y0, double x1, double y1, double radius, float darkness);

  // The grey levels, row by row from the top: 255 where no ink fell, 0 under full ink.
  std::vector<std::uint8_t> pixels() const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void capsule(double ax, double ay, double bx, double by, double radius, float darkness);

  int width_, height_;
  std::vector<float> ink_;
};

}  // namespace tsk::io
