#include "core/render/plot_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "core/error.hpp"
#include "core/render/canvas.hpp"
#include "core/render/palette.hpp"
#include "core/render/plot_frame.hpp"

namespace ppsynth {
namespace {

using namespace render;

constexpr double kMargin = 14;      // outer margin (px)
constexpr double kLeftAxis = 30;    // room for y tick labels
constexpr double kBottomAxis = 20;  // room for x tick labels
constexpr double kTitleH = 28;
constexpr double kTickFont = 10.5;
constexpr double kColorbarH = 34;
// readable_plot_px: the mean spacing of the points on screen it aims for, and its largest size.
constexpr double kReadableSpacingPx = 4;
constexpr int kMaxReadablePlotPx = 2400;

struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  bool valid() const { return lo <= hi; }
  double norm(double v) const { return hi > lo ? (v - lo) / (hi - lo) : 0.5; }
};

int require_attribute(const PointSet& ps, const std::string& name, const char* what) {
  if (auto a = ps.attribute_index(name)) return *a;
  std::string known;
  for (const auto& n : ps.attribute_names()) known += (known.empty() ? "" : ", ") + n;
  throw InputError(std::string(what) + " attribute '" + name + "' not found (attributes: " +
                   (known.empty() ? "none" : known) + ")");
}

bool uses_disks(const PointSet& ps, const PointStyle& st) {
  return st.draw_disks && ps.attribute_index("radius").has_value();
}

// Side lengths in px of the frame for a domain fitted in a square of side `side`.
void frame_size(const Domain& d, double side, double& w, double& h) {
  double aspect = d.width() > 0 && d.height() > 0 ? d.height() / d.width() : 1.0;
  if (!std::isfinite(aspect) || aspect <= 0) aspect = 1.0;
  aspect = std::clamp(aspect, 1e-3, 1e3);  // a 1e-300-high strip still gets a visible frame
  if (aspect <= 1) {
    w = side;
    h = side * aspect;
  } else {
    h = side;
    w = side / aspect;
  }
}

double auto_radius(size_t n, double w_px, double h_px) {
  if (n == 0) return 3;
  // Mean spacing on screen: sqrt(area / N); a fifth of it keeps dense patterns readable and
  // gives the same look to an exemplar and a u^2-times larger output drawn at the same size.
  const double spacing = std::sqrt(w_px * h_px / static_cast<double>(n));
  return std::clamp(0.2 * spacing, 0.6, 8.0);
}

// Radii (px) up to kArcPx go to cairo_arc as they are (cairo's fixed-point coordinates end
// at +-8e6 px); up to kPolylinePx the visible part of the rim is a polyline computed here;
// beyond, the rim is a straight edge (off the arc by diagonal^2 / (2 r) < 1e-4 px).
constexpr double kArcPx = 2e6, kPolylinePx = 1e12;

// A disk (light fill, outline) of center (cx, cy) and radius r px seen through the frame
// (fx, fy, fw, fh). Only geometry near the frame reaches cairo: a disk of radius 1e30 px
// made cairo flatten an arc of ~1e31 segments (it never returned), and cairo's fixed-point
// coordinates end at +-8e6 px. Non-finite centers are skipped; NaN or negative radii are
// drawn as the smallest disk (0.5 px); a disk containing the frame fills it.
void draw_disk_clipped(cairo_t* cr, double cx, double cy, double r, double fx, double fy, double fw, double fh,
                       const Rgb& c) {
  if (!std::isfinite(cx) || !std::isfinite(cy)) return;
  if (!(r >= 0.5)) r = 0.5;  // NaN, negative, tiny
  const double lw = std::isfinite(r) ? std::clamp(r * 0.08, 0.5, 1.2) : 1.2;
  const double dx = std::max({fx - cx, 0.0, cx - (fx + fw)}), dy = std::max({fy - cy, 0.0, cy - (fy + fh)});
  const double nearest = std::hypot(dx, dy);
  const double farthest = std::hypot(std::max(std::abs(cx - fx), std::abs(cx - fx - fw)),
                                     std::max(std::abs(cy - fy), std::abs(cy - fy - fh)));
  if (nearest > r + lw) return;  // wholly outside the frame
  cairo_save(cr);
  cairo_new_path(cr);
  if (r > farthest + lw) {  // the frame lies inside the disk: all of it is tinted
    cairo_rectangle(cr, fx, fy, fw, fh);
    set_color(cr, c, 0.35);
    cairo_fill(cr);
  } else if (r <= kArcPx) {
    cairo_arc(cr, cx, cy, r, 0, 2 * M_PI);
    set_color(cr, c, 0.35);
    cairo_fill_preserve(cr);
    set_color(cr, c, 0.95);
    cairo_set_line_width(cr, lw);
    cairo_stroke(cr);
  } else {
    // The rim crosses the frame from a center far away. Only the part of the rim inside the
    // circle of radius R around the frame's center m is drawn; the fill is closed by two
    // points 2D inwards (towards the center) from the ends of that arc.
    const double mx = fx + fw / 2, my = fy + fh / 2;
    const double R = std::hypot(fw, fh) / 2 + 4 * lw, D = 2 * R;
    const double L = std::hypot(cx - mx, cy - my);
    const double ux = (mx - cx) / L, uy = (my - cy) / L;  // from the center towards m
    std::vector<std::pair<double, double>> rim;  // points relative to m
    if (r <= kPolylinePx) {
      // Angle between u and the rim points on that circle: cos a = 1 - (R^2 - (L - r)^2) / (2 r L).
      const double ca = std::clamp(1 - (R * R - (L - r) * (L - r)) / (2 * r * L), -1.0, 1.0);
      const double a = std::acos(ca), phi = std::atan2(uy, ux);
      const int segs = 256;
      for (int k = 0; k <= segs; ++k) {
        const double t = phi - a + 2 * a * k / segs;
        // center + r (cos t, sin t) - m, without forming the far-away center's coordinates:
        // = (r cos t - L ux, r sin t - L uy), with L = r + (L - r) to keep the digits.
        const double e = L - r;
        rim.push_back({r * (std::cos(t) - ux) - e * ux, r * (std::sin(t) - uy) - e * uy});
      }
    } else {
      const double s = std::clamp(L - r, -D, D);  // center-to-m distance minus r: m to the rim
      const double vx = -uy, vy = ux;
      rim.push_back({-ux * s + vx * D, -uy * s + vy * D});
      rim.push_back({-ux * s - vx * D, -uy * s - vy * D});
    }
    cairo_move_to(cr, mx + rim.front().first, my + rim.front().second);
    for (size_t k = 1; k < rim.size(); ++k) cairo_line_to(cr, mx + rim[k].first, my + rim[k].second);
    cairo_line_to(cr, mx + rim.back().first - ux * 2 * D, my + rim.back().second - uy * 2 * D);
    cairo_line_to(cr, mx + rim.front().first - ux * 2 * D, my + rim.front().second - uy * 2 * D);
    cairo_close_path(cr);
    set_color(cr, c, 0.35);
    cairo_fill(cr);
    cairo_move_to(cr, mx + rim.front().first, my + rim.front().second);
    for (size_t k = 1; k < rim.size(); ++k) cairo_line_to(cr, mx + rim[k].first, my + rim[k].second);
    set_color(cr, c, 0.95);
    cairo_set_line_width(cr, lw);
    cairo_stroke(cr);
  }
  cairo_restore(cr);
}

// Draws the frame, the ticks and the points of `ps` with the frame's top-left at (fx, fy).
void draw_points_in_frame(cairo_t* cr, const PointSet& ps, const PointStyle& st, double fx, double fy,
                          double fw, double fh, const Range& color_range) {
  const Domain& d = ps.domain();
  double sx = fw / (d.width() > 0 ? d.width() : 1), sy = fh / (d.height() > 0 ? d.height() : 1);
  if (!std::isfinite(sx) || sx <= 0) sx = 1;
  if (!std::isfinite(sy) || sy <= 0) sy = 1;
  auto X = [&](double x) { return fx + (x - d.x0) * sx; };
  auto Y = [&](double y) { return fy + fh - (y - d.y0) * sy; };  // y up

  // Ticks and labels (outside the frame).
  cairo_save(cr);
  set_color(cr, kAxis);
  cairo_set_line_width(cr, 0.8);
  for (double t : nice_ticks(d.x0, d.x1, 2)) {
    cairo_move_to(cr, X(t), fy + fh);
    cairo_line_to(cr, X(t), fy + fh + 4);
    cairo_stroke(cr);
    set_color(cr, kText);
    draw_text(cr, tick_label(t), X(t), fy + fh + 5, kTickFont, HAlign::Center, VAlign::Top);
    set_color(cr, kAxis);
  }
  for (double t : nice_ticks(d.y0, d.y1, 2)) {
    cairo_move_to(cr, fx, Y(t));
    cairo_line_to(cr, fx - 4, Y(t));
    cairo_stroke(cr);
    set_color(cr, kText);
    draw_text(cr, tick_label(t), fx - 6, Y(t), kTickFont, HAlign::Right, VAlign::Middle);
    set_color(cr, kAxis);
  }
  cairo_restore(cr);

  // Points, clipped to the domain.
  cairo_save(cr);
  cairo_rectangle(cr, fx, fy, fw, fh);
  cairo_clip(cr);
  const double base = st.point_radius_px > 0 ? st.point_radius_px : auto_radius(ps.size(), fw, fh);
  int size_a = -1, color_a = -1, radius_a = -1;
  Range size_range;
  if (!st.size_attribute.empty()) {
    size_a = require_attribute(ps, st.size_attribute, "size");
    for (double v : ps.attribute_column(size_a)) size_range.add(v);
  }
  if (!st.color_attribute.empty()) color_a = require_attribute(ps, st.color_attribute, "color");
  if (uses_disks(ps, st)) radius_a = *ps.attribute_index("radius");

  // Draw class by class (class 0 first) so colors layer predictably.
  std::vector<size_t> order(ps.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return ps.cls(a) < ps.cls(b); });
  for (size_t i : order) {
    const Vec2& p = ps[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    const Rgb c = color_a >= 0 ? viridis(color_range.norm(ps.attr(i, color_a))) : class_color(ps.cls(i));
    if (radius_a >= 0) {
      const double r = ps.attr(i, radius_a) * std::sqrt(sx * sy);
      draw_disk_clipped(cr, X(p.x), Y(p.y), r, fx, fy, fw, fh, c);
      continue;
    }
    double r = base;
    if (size_a >= 0) r = base * (0.5 + 1.5 * size_range.norm(ps.attr(i, size_a)));
    if (!std::isfinite(r) || r <= 0) r = base;
    const double cx = X(p.x), cy = Y(p.y);
    if (!std::isfinite(cx) || !std::isfinite(cy) || cx < fx - r || cx > fx + fw + r || cy < fy - r || cy > fy + fh + r)
      continue;  // outside the frame (and its clip)
    cairo_new_path(cr);
    cairo_arc(cr, cx, cy, r, 0, 2 * M_PI);
    set_color(cr, c);
    cairo_fill(cr);
  }
  cairo_restore(cr);

  if (st.show_frame) {
    cairo_save(cr);
    set_color(cr, kAxis);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, fx, fy, fw, fh);
    cairo_stroke(cr);
    cairo_restore(cr);
  }
}

// Legend entries for the classes present in any of the point sets (labels from the files).
std::vector<LegendItem> class_legend(const std::vector<const PointSet*>& sets, const PointStyle& st,
                                     bool with_counts) {
  // class id (the color) -> its file labels; panels of one figure may label the same id
  // differently (a merged 1-class set "0" beside a 2-class file's "1000"): show them all.
  std::map<int, std::set<int>> labels_of;
  std::map<int, size_t> count;
  bool disks = false;
  for (const PointSet* ps : sets) {
    disks = disks || uses_disks(*ps, st);
    for (size_t i = 0; i < ps->size(); ++i) {
      labels_of[ps->cls(i)].insert(ps->class_label(ps->cls(i)));
      ++count[ps->cls(i)];
    }
  }
  std::vector<LegendItem> items;
  if (labels_of.size() <= 1) return items;
  for (const auto& [k, labels] : labels_of) {
    std::string text = "class", sep = " ";
    for (int label : labels) {
      text += sep + std::to_string(label);
      sep = " / ";
    }
    if (with_counts) text += " (n=" + std::to_string(count[k]) + ")";
    items.push_back({text, class_color(k), disks ? Marker::Disk : Marker::Dot});
  }
  return items;
}

Range color_range_of(const std::vector<const PointSet*>& sets, const PointStyle& st) {
  Range r;
  if (st.color_attribute.empty()) return r;
  for (const PointSet* ps : sets) {
    const int a = require_attribute(*ps, st.color_attribute, "color");
    for (double v : ps->attribute_column(a)) r.add(v);
  }
  return r;
}

void draw_colorbar(cairo_t* cr, const std::string& name, const Range& r, double x, double y) {
  set_color(cr, kText);
  draw_text(cr, name, x, y + 12, 12, HAlign::Left, VAlign::Middle);
  const double bx = x + measure_text(name, 12) + 10, bw = 160, bh = 10;
  cairo_pattern_t* g = cairo_pattern_create_linear(bx, 0, bx + bw, 0);
  for (int i = 0; i <= 8; ++i) {
    const Rgb c = viridis(i / 8.0);
    cairo_pattern_add_color_stop_rgb(g, i / 8.0, c.r, c.g, c.b);
  }
  cairo_rectangle(cr, bx, y + 7, bw, bh);
  cairo_set_source(cr, g);
  cairo_fill(cr);
  cairo_pattern_destroy(g);
  set_color(cr, kText);
  draw_text(cr, tick_label(r.valid() ? r.lo : 0), bx, y + 19, 10, HAlign::Left, VAlign::Top);
  draw_text(cr, tick_label(r.valid() ? r.hi : 0), bx + bw, y + 19, 10, HAlign::Right, VAlign::Top);
}

}  // namespace

int readable_plot_px(const std::vector<const PointSet*>& sets, int base_px) {
  double need = base_px;
  for (const PointSet* ps : sets) {
    if (!ps || ps->empty()) continue;
    double fw, fh;
    frame_size(ps->domain(), 1.0, fw, fh);  // the long side 1, the short side the aspect
    // Long side L px: mean spacing sqrt(L^2 fw fh / N) >= kReadableSpacingPx.
    const double frame = kReadableSpacingPx * std::sqrt(static_cast<double>(ps->size()) / (fw * fh));
    need = std::max(need, frame + kLeftAxis + kMargin);
  }
  return static_cast<int>(std::ceil(std::min(need, static_cast<double>(std::max(base_px, kMaxReadablePlotPx)))));
}

void plot_points(const std::string& path, const PointSet& ps, const PointStyle& style, int size_px) {
  plot_panels(path, {{style.title, ps}}, style, size_px, 1);
}

void plot_panels(const std::string& path, const std::vector<std::pair<std::string, PointSet>>& panels,
                 const PointStyle& style, int panel_px, int columns) {
  render::image_kind_for(path);  // fail on a bad extension before any work
  if (panels.empty()) throw InputError("plot_panels: no point sets to plot for " + path);
  if (panel_px < 80) throw InputError("plot: panel size must be at least 80 px (got " + std::to_string(panel_px) + ")");
  const int n = static_cast<int>(panels.size());
  const int cols = columns <= 0 ? n : std::min(columns, n);
  const int rows = (n + cols - 1) / cols;

  // A blank cell (empty title, empty set) only holds a place in the grid: it is not drawn and
  // takes no part in the legend or the color range.
  auto blank = [](const std::pair<std::string, PointSet>& p) { return p.first.empty() && p.second.empty(); };
  std::vector<const PointSet*> sets;
  for (const auto& p : panels)
    if (!blank(p)) sets.push_back(&p.second);
  const bool single = n == 1;
  const auto legend = class_legend(sets, style, single);
  const Range crange = color_range_of(sets, style);

  const double side = panel_px - kLeftAxis - kMargin;  // frame fits in side x side
  // Each row is as tall as its tallest frame: a row of 4 x 1 strips is a quarter of a row of
  // squares (a fixed square cell left the strips under a tall blank band, their titles far
  // above them). Frames are top-aligned under their titles.
  std::vector<double> row_frame_h(rows, 0.0);
  for (int i = 0; i < n; ++i) {
    if (blank(panels[i])) continue;
    double fw, fh;
    frame_size(panels[i].second.domain(), side, fw, fh);
    row_frame_h[i / cols] = std::max(row_frame_h[i / cols], fh);
  }
  std::vector<double> row_y(rows + 1, 0.0);
  for (int r = 0; r < rows; ++r) {
    if (row_frame_h[r] <= 0) row_frame_h[r] = side;  // a row of blank cells keeps its place
    row_y[r + 1] = row_y[r] + kTitleH + row_frame_h[r] + kBottomAxis;
  }
  const double cell_w = panel_px;
  const double width = cols * cell_w + kMargin;
  const double legend_w = width - 2 * kMargin - kLeftAxis;
  const double leg_h = legend_height(legend, legend_w);
  const double cbar_h = style.color_attribute.empty() ? 0 : kColorbarH;
  const double height = row_y[rows] + leg_h + cbar_h + kMargin;

  if (!render::image_size_ok(std::ceil(width), std::ceil(height)))
    throw InputError("plot " + path + ": " + std::to_string(n) + " panels of " + std::to_string(panel_px) + " px in " +
                     std::to_string(cols) + " columns make a " + std::to_string(static_cast<long>(std::ceil(width))) +
                     " x " + std::to_string(static_cast<long>(std::ceil(height))) + " px image, beyond the limit of " +
                     std::to_string(render::kMaxImageSide) + " px a side and " +
                     std::to_string(static_cast<long>(render::kMaxImagePixels / 1e6)) +
                     " megapixels: use --columns or a smaller --size");
  render::render_to_file(path, static_cast<int>(std::ceil(width)), static_cast<int>(std::ceil(height)), [&](cairo_t* cr) {
    for (int i = 0; i < n; ++i) {
      if (blank(panels[i])) continue;
      const auto& [title, ps] = panels[i];
      const double cx = (i % cols) * cell_w + kMargin, cy = row_y[i / cols];
      double fw, fh;
      frame_size(ps.domain(), side, fw, fh);
      const double fx = cx + kLeftAxis + (side - fw) / 2;
      const double fy = cy + kTitleH;
      if (!title.empty()) {
        set_color(cr, kText);
        draw_text(cr, title, fx, cy + kTitleH - 8, 15, HAlign::Left, VAlign::Baseline, true);
      }
      set_color(cr, kAxis);
      draw_text(cr, "N = " + std::to_string(ps.size()), fx + fw, cy + kTitleH - 8, 11,
                HAlign::Right, VAlign::Baseline);
      draw_points_in_frame(cr, ps, style, fx, fy, fw, fh, crange);
    }
    const double ly = row_y[rows] + 4;
    draw_legend(cr, legend, kMargin + kLeftAxis, ly, legend_w);
    if (cbar_h > 0) draw_colorbar(cr, style.color_attribute, crange, kMargin + kLeftAxis, ly + leg_h);
  });
}

}  // namespace ppsynth
