#pragma once
// Scatter plots of point sets: the figure researchers look at first (exemplar | output).
// The domain is drawn as a square/rectangle with a thin frame (aspect kept); classes get
// the Tableau-10 palette (render/palette.hpp) with a legend when K > 1.
//
// Marker size: auto radius 0.2 x the mean spacing on screen (sqrt(frame area / N)), clamped
// to [0.6, 8] px, so an exemplar with N points in the unit square and an output with u^2*N
// points look alike (same visual density) when drawn at the same size. Below ~4 px of
// spacing (10,000+ points in 600 px) markers merge: readable_plot_px gives the image size
// that keeps them apart, and `ppsynth plot` uses it unless --size is given.
// Rectangles (a 4 x 1 strip in exemplar units) keep their aspect: the long side spans the
// panel and each row of panels is as tall as its tallest frame.
// Points with a "radius" attribute (disk patterns) are drawn as disks of their true radius
// in domain units when `draw_disks` is set (outline + light fill).
// Output format by extension: .png, .svg, .pdf (render/canvas.hpp); atomic writes.
#include <string>
#include <utility>
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

struct PointStyle {
  double point_radius_px = 0;   // 0 = auto from N (see above)
  std::string size_attribute;   // map this attribute to marker size (min..max -> 0.5..2x)
  std::string color_attribute;  // color by this attribute (viridis ramp) instead of class
  bool draw_disks = true;       // draw points that have a "radius" attribute as true disks
  bool show_frame = true;       // thin frame around the domain
  std::string title;            // drawn above the plot (plot_points only)
};

// The image (or panel) size for `sets` that keeps their points at least 4 px apart on screen
// on average: base_px, or more for many points, up to 2400 px.
int readable_plot_px(const std::vector<const PointSet*>& sets, int base_px);

// One point set in a size_px x size_px image (plus a legend strip when K > 1).
// Unknown size/color attribute => InputError naming the attribute and the known ones.
void plot_points(const std::string& path, const PointSet& ps, const PointStyle& style = {},
                 int size_px = 600);

// Several point sets side by side, each with its title (e.g. exemplar | init | output),
// wrapping after `columns` panels (0 = all in one row). Auto marker size is computed per
// panel from its own N. One shared class legend below. An entry with an empty title and an
// empty set is a blank cell (fills the last cells of a ragged grid: no frame, no "N = 0").
void plot_panels(const std::string& path,
                 const std::vector<std::pair<std::string, PointSet>>& panels,
                 const PointStyle& style = {}, int panel_px = 400, int columns = 0);

}  // namespace ppsynth
