#pragma once
// The CAM-style chord circle of KRN-6 / KRN-9 (docs/CONTOURING.md, docs/HSC.md):
// a circle of radius R as G01 chords of `chord` mm at F6000, counter-clockwise
// from (R, 0), its end points written with `decimals` decimals as a CAM post
// writes them. bench/chord_circle.py writes the same text for the rig.
#include <cmath>
#include <cstdio>
#include <string>

namespace hil::bench {

enum class Smoothing { none, g261, hsc };

struct ChordCircle {
  int chords = 10000;
  double radius = 15.9, chord = 0.1, path_dev = 0.01;
  int decimals = 9;
  int merge = 1;  // MERGE of #HSC

  double step_angle() const { return 2 * std::asin(chord / (2 * radius)); }
  double x(int c) const { return radius * std::cos(c * step_angle()); }
  double y(int c) const { return radius * std::sin(c * step_angle()); }

  // N1 the rapid to (R, 0), the smoothing's command, then the chords (the
  // first one's line is 3 with a smoothing command, else 2), M30.
  std::string program(Smoothing smoothing) const {
    char line[160];
    std::snprintf(line, sizeof line, "%%chord_circle\nN1 G90 G00 X%.6f Y0 Z0\n", radius);
    std::string text = line;
    if (smoothing == Smoothing::hsc) {
      std::snprintf(line, sizeof line, "#HSC ON [BSPLINE PATH_DEV=%.6g MERGE=%d]\n", path_dev, merge);
      text += line;
    } else if (smoothing == Smoothing::g261) {
      std::snprintf(line, sizeof line, "#CONTOUR MODE [DEV PATH_DEV=%.6g]\n", path_dev);
      text += line;
    }
    for (int c = 1; c <= chords; ++c) {
      std::snprintf(line, sizeof line, "%sX%.*f Y%.*f%s\n",
                    c == 1 ? (smoothing == Smoothing::g261 ? "G01 G261 " : "G01 ") : "", decimals, x(c), decimals,
                    y(c), c == 1 ? " F6000" : "");
      text += line;
    }
    return text + "M30\n";
  }
};

}  // namespace hil::bench
