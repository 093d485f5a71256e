// A quick look at recorded time series (`sylva run --record M --plot out.png`)
// and at an experiment's measure against a parameter (`[plot]` of a plan):
// the recorded module parameters drawn against time as dots, as small
// multiples: one panel per parameter, stacked, each with its own value axis
// and named in its own colour, over one shared time axis, under a title.
// Drawn as a Drawing (render/vector_drawing.h) and made a PNG by the cairo
// plugin, so cairo is loaded only when a plot is asked for.
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
// standard output), written whole or not at all. Each series with points gets
// a panel of its own, in order from the top, its y axis spanning its own
// values; all share the t axis, labelled under the bottom panel. The axes
// span the data with a margin (a unit range around constant data, 0..1
// without data) and are ticked at 1, 2 or 5 x 10^k. Series i has colour i of a
// fixed palette of ten (repeating) for its dots and its name. Series without
// points get no panel (one empty panel is drawn when none has any), and points
// that are not finite are left out. Panels are at least some 80 pixels high,
// name included: series beyond those that fit in `height` are not drawn, and
// a line at the bottom says "+N more series not shown". Throws ModelError
// naming the path when it cannot be written or drawn, when a series' t and
// value differ in length, and when the size is under 320 x 200 or over 16384
// either way.
void write_series_plot(const std::string& path, const std::vector<PlotSeries>& series, const std::string& title,
                       int width = 900, int height = 600, const std::string& x_label = "t");

}  // namespace sylva
