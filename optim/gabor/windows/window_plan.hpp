#pragma once
// Rectangle outputs on one grid, or window by window past the memory budget. The canvas (the
// output, grown by the clean border's pad) is one grid of rows x columns positions whenever
// those positions fit the budget (method.window.pixels^2), whatever its aspect: the cost
// follows the canvas's grid positions, not a window count. A canvas past the budget is
// covered by the fewest equal rectangular windows that fit it, in raster order (rows bottom
// to top, left to right in a row). Each window runs the paper's plan (classes one after
// another, sigmas coarse to fine) on its own grid, so memory is one window's whatever the canvas:
//
//     +---------+---------+        window grid G: a rectangle of width x height exemplar units
//     |   ...   |  next   |        interior I: its share of the canvas (the windows'
//     +----+----+----+----+          interiors tile it); neighbors overlap by >= 2 margins
//     |done| I  ->  overhang|      movable M = [I.x0, G.x1] x [I.y0, G.y1]: the window's part
//     +----+---------------+         and its overhang over windows still to come
//     |      done (final)  |       frozen: every other point of the stage's classes in G and
//     +--------------------+         within the maps' reach around it (final points below and
//                                    left, earlier windows' overhang above)
//
// A window moves the points in M that are not final and keeps them in M; those inside I at
// its end are final. Its grid border therefore lies either over final points (below, left:
// the maps see the finished pattern there, as inside one big grid) or over its overhang
// (right, above), where points park or thin out as on any grid border and are moved again by
// the next windows. Margin = the maps' reach (3 sigma_max) + the network's receptive field,
// so a final point never sees a grid border. Interiors meet half-way in the overlaps.
// One window (the canvas fits the budget) is the canvas's grid: I = M = the canvas.
#include <optional>
#include <string>
#include <vector>

#include "core/point_set.hpp"
#include "optim/gabor/settings/gabor_settings.hpp"
#include "optim/gabor/settings/window_size.hpp"
#include "optim/gabor/stages/stage_plan.hpp"

namespace ppsynth {

struct WindowLayout {
  Domain canvas;
  WindowSize size;
  double margin = 0;   // reserved on each side of an interior (exemplar units)
  double reach = 0;    // of the maps beyond the grid, for frozen context (exemplar units)
  int nx = 1, ny = 1;
  std::vector<StageWindow> windows;  // raster order
};

// `size`'s windows on `canvas`: along each axis the first starts at the canvas's start, the
// last ends at its end, the rest evenly between; points move only inside `moving_area` (the
// canvas, or the rectangle when the pad is frozen).
WindowLayout window_layout(const Domain& canvas, const Domain& moving_area, const WindowSize& size, double margin, double reach);

// The stages of every window: the paper's class / sigma stages (class_sigma_plan's labels,
// with "window i/n, " before them when there are several), one group per window and class.
SynthesisPlan window_plan(const PointSet& exemplar, const GaborSettings& settings, const WindowLayout& layout);

}  // namespace ppsynth
