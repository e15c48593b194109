#pragma once
// Large outputs, window by window. The canvas (the output, grown by the clean
// border's pad) is covered by equal square windows in raster order (rows bottom to top,
// left to right in a row). Each window runs the paper's plan (classes one after another,
// sigmas coarse to fine) on its own grid, so memory is one window's whatever the canvas:
//
//     +---------+---------+        window grid G: a square of `side` exemplar units
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
#include <vector>

#include "core/point_set.hpp"
#include "optim/gabor/stage_plan.hpp"

namespace ppsynth {

struct WindowLayout {
  Domain canvas;
  double side = 0;     // of every window's grid (exemplar units)
  double margin = 0;   // reserved on each side of an interior (exemplar units)
  double reach = 0;    // of the maps beyond the grid, for frozen context (exemplar units)
  int nx = 1, ny = 1;
  std::vector<StageWindow> windows;  // raster order
};

// Windows of at most `max_side` on `canvas`; points move only inside `moving_area` (the
// canvas, or the rectangle when the pad is frozen). side = min(max_side, canvas width, height);
// one window per axis when it covers the axis, else the fewest whose overlaps are >= 2 margins.
// Throws InputError naming `key` when the side cannot hold two margins (and more than one
// window is needed).
WindowLayout window_layout(const Domain& canvas, const Domain& moving_area, double max_side, double margin, double reach, const std::string& key);
// True when window_layout takes windows of `max_side` with `margin` on `canvas`.
bool windows_fit(const Domain& canvas, double max_side, double margin);

// The stages of every window: the paper's class / sigma stages (class_sigma_plan's labels,
// with "window i/n, " before them), one group per window and class.
SynthesisPlan window_plan(const PointSet& exemplar, const GaborSettings& settings, const WindowLayout& layout);

}  // namespace ppsynth
