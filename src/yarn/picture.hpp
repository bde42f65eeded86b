// A picture of the yarn: every segment drawn as a shaded capsule (a z-buffered software
// rasteriser, 2x2 supersampled), each yarn piece in its own colour, orthographic from a
// direction given by azimuth and elevation around the model's y axis. Written as PNG with
// libpng.
#pragma once

#include <iosfwd>
#include <string>

#include "yarn/curves.hpp"

namespace skein {

struct PictureOptions {
  int width = 900, height = 900;
  float azimuth = 30, elevation = 20;  // degrees; 0, 0 looks along -z
  unsigned threads = 0;
};

void write_yarn_png(const YarnModel& model, std::ostream& out, const PictureOptions& options = {});

}  // namespace skein
