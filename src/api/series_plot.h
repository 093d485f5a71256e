// A quick look at recorded time series (`sylva run --record M --plot out.png`):
// the recorded module parameters drawn against time as dots, one colour per
// parameter, with ticked axes, a legend and a title. Drawn as a Drawing
// (render/vector_drawing.h) and made a PNG by the cairo plugin, so cairo is
// loaded only when a plot is asked for.
#pragma once

#include <string>
#include <vector>

namespace sylva {

struct PlotSeries {  // one parameter of one module name, e.g. "Cell p1"
  std::string name;
  // The points, t[i] with value[i]: dots, not a line, since every module of
  // the name adds its own point at each time.
  std::vector<double> t, value;
};

// Draws the series against t into a width x height PNG at `path` ("-":
// standard output), written whole or not at all. Both axes span the data with
// a margin (a unit range around constant data, 0..1 without data) and are
// ticked at 1, 2 or 5 x 10^k. Series i has colour i of a fixed palette of ten
// (repeating); series without points are left out of the legend, and points
// that are not finite are left out. Throws ModelError naming the path when it
// cannot be written or drawn, when a series' t and value differ in length, and
// when the size is under 320 x 200 or over 16384 either way.
void write_series_plot(const std::string& path, const std::vector<PlotSeries>& series, const std::string& title,
                       int width = 900, int height = 600);

}  // namespace sylva
