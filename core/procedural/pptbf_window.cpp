#include "core/procedural/pptbf_window.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ppsynth::pptbf_impl {

double minkowski(Vec2 v, double n) {
  const double ax = std::abs(v.x), ay = std::abs(v.y);
  if (n == 2) return std::sqrt(ax * ax + ay * ay);
  if (n == 1) return ax + ay;
  if (n >= 50) return std::max(ax, ay);
  return std::pow(std::pow(ax, n) + std::pow(ay, n), 1.0 / n);
}

double cell_distance(Vec2 x, const FeaturePoint& fp, double norm, double larp) {
  const Vec2 dv{x.x - fp.p.x, x.y - fp.p.y};
  double d = minkowski(dv, norm);
  if (larp == 0) return d;
  const double sx = dv.x < 0 ? fp.p.x - fp.c.x : fp.c.x + fp.d.x - fp.p.x;
  const double sy = dv.y < 0 ? fp.p.y - fp.c.y : fp.c.y + fp.d.y - fp.p.y;
  const double ex = std::abs(dv.x) / std::max(sx, 1e-9), ey = std::abs(dv.y) / std::max(sy, 1e-9);
  return (1 - larp) * d + larp * std::max(ex, ey);
}

void nth_closest(Vec2 x, const std::vector<FeaturePoint>& pts, double norm, double larp,
                 std::vector<int>& order) {
  std::vector<double> dist(pts.size());
  for (size_t k = 0; k < pts.size(); ++k) dist[k] = cell_distance(x, pts[k], norm, larp);
  order.resize(pts.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return dist[a] < dist[b]; });
}

namespace {

bool in_cell(const CellShape& cs, Vec2 y) {
  const double ds = cell_distance(y, cs.site, cs.norm, cs.larp);
  for (const FeaturePoint& q : cs.competitors)
    if (cell_distance(y, q, cs.norm, cs.larp) < ds) return false;
  return true;
}

double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

// Ray p + t u against segment [A, B]: t >= 0 when hit, else -1.
double ray_segment(Vec2 p, Vec2 u, Vec2 A, Vec2 B) {
  const Vec2 e{B.x - A.x, B.y - A.y};
  const double den = cross(u, e);
  if (std::abs(den) < 1e-15) return -1;
  const Vec2 ap{A.x - p.x, A.y - p.y};
  const double t = cross(ap, e) / den;
  const double s = cross(ap, u) / den;
  if (s < -1e-9 || s > 1 + 1e-9 || t < 0) return -1;
  return t;
}

// Ray p + t u against the quadratic Bezier (A, C, E): distance |B(s) - p| or -1.
double ray_bezier(Vec2 p, Vec2 u, Vec2 A, Vec2 C, Vec2 E) {
  auto g = [&](Vec2 q) { return cross(Vec2{q.x - p.x, q.y - p.y}, u); };
  const double gA = g(A), gC = g(C), gE = g(E);
  const double a = gA - 2 * gC + gE, b = 2 * (gC - gA), c = gA;
  double roots[2];
  int nr = 0;
  if (std::abs(a) < 1e-14) {
    if (std::abs(b) > 1e-14) roots[nr++] = -c / b;
  } else {
    const double disc = b * b - 4 * a * c;
    if (disc >= 0) {
      const double sq = std::sqrt(disc);
      roots[nr++] = (-b - sq) / (2 * a);
      roots[nr++] = (-b + sq) / (2 * a);
    }
  }
  double best = -1;
  for (int i = 0; i < nr; ++i) {
    const double s = roots[i];
    if (s < -1e-9 || s > 1 + 1e-9) continue;
    const double w0 = (1 - s) * (1 - s), w1 = 2 * s * (1 - s), w2 = s * s;
    const Vec2 q{w0 * A.x + w1 * C.x + w2 * E.x, w0 * A.y + w1 * C.y + w2 * E.y};
    const Vec2 dq{q.x - p.x, q.y - p.y};
    if (dq.x * u.x + dq.y * u.y <= 0) continue;
    const double r = std::hypot(dq.x, dq.y);
    if (best < 0 || r < best) best = r;
  }
  return best;
}

Vec2 vertex(const CellShape& cs, int m) {
  const int nv = static_cast<int>(cs.vertex_r.size());
  const int mm = ((m % nv) + nv) % nv;
  const double a = cs.start_angle + mm * cs.step;
  return {cs.site.p.x + cs.vertex_r[mm] * std::cos(a), cs.site.p.y + cs.vertex_r[mm] * std::sin(a)};
}

int sector_of(const CellShape& cs, double angle) {
  double rel = std::fmod(angle - cs.start_angle, 2 * M_PI);
  if (rel < 0) rel += 2 * M_PI;
  return static_cast<int>(std::floor(rel / cs.step)) % static_cast<int>(cs.vertex_r.size());
}

}  // namespace

CellShape make_cell_shape(const FeaturePoint& site, const std::vector<FeaturePoint>& neighbors,
                          double norm, double larp, int arity, double start_angle) {
  CellShape cs;
  cs.site = site;
  cs.norm = norm;
  cs.larp = larp;
  std::vector<FeaturePoint> others;
  for (const FeaturePoint& q : neighbors)
    if (!(q.key == site.key)) others.push_back(q);
  auto d2 = [&](const FeaturePoint& q) {
    return (q.p.x - site.p.x) * (q.p.x - site.p.x) + (q.p.y - site.p.y) * (q.p.y - site.p.y);
  };
  const size_t keep = std::min<size_t>(16, others.size());
  std::partial_sort(others.begin(), others.begin() + keep, others.end(),
                    [&](const FeaturePoint& a, const FeaturePoint& b) { return d2(a) < d2(b); });
  others.resize(keep);
  cs.competitors = std::move(others);
  cs.start_angle = start_angle;
  cs.step = 2 * M_PI / arity;
  cs.vertex_r.resize(arity);
  for (int m = 0; m < arity; ++m) {
    const double a = start_angle + m * cs.step;
    cs.vertex_r[m] = cellborder(cs, std::cos(a), std::sin(a));
  }
  return cs;
}

double cellborder(const CellShape& cs, double ux, double uy) {
  const Vec2 p = cs.site.p;
  double nearest = 1e300;
  for (const FeaturePoint& q : cs.competitors) nearest = std::min(nearest, std::hypot(q.p.x - p.x, q.p.y - p.y));
  const double tmax = cs.competitors.empty() ? 10.0 : 4.0 * nearest;
  if (cs.larp == 0 && cs.norm == 2) {  // Euclidean Voronoi: closed form
    double r = tmax;
    for (const FeaturePoint& q : cs.competitors) {
      const double vx = q.p.x - p.x, vy = q.p.y - p.y;
      const double proj = ux * vx + uy * vy;
      if (proj > 1e-15) r = std::min(r, (vx * vx + vy * vy) / (2 * proj));
    }
    return r;
  }
  const double h = 0.05 * std::min(nearest, tmax);
  double t = 0;
  while (t < tmax && in_cell(cs, Vec2{p.x + (t + h) * ux, p.y + (t + h) * uy})) t += h;
  if (t >= tmax) return tmax;
  double lo = t, hi = t + h;
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (in_cell(cs, Vec2{p.x + mid * ux, p.y + mid * uy})) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

double polygon_radius(const CellShape& cs, double angle) {
  const int m = sector_of(cs, angle);
  const Vec2 u{std::cos(angle), std::sin(angle)};
  const double t = ray_segment(cs.site.p, u, vertex(cs, m), vertex(cs, m + 1));
  return t > 0 ? t : std::min(cs.vertex_r[m], cs.vertex_r[(m + 1) % cs.vertex_r.size()]);
}

double beziercell(const CellShape& cs, double angle) {
  const int m = sector_of(cs, angle);
  const Vec2 u{std::cos(angle), std::sin(angle)};
  auto mid = [&](int a) {
    const Vec2 A = vertex(cs, a), B = vertex(cs, a + 1);
    return Vec2{(A.x + B.x) / 2, (A.y + B.y) / 2};
  };
  // the ray crosses the curve around vertex m or the one around vertex m + 1
  double best = -1;
  for (int v : {m, m + 1}) {
    const double r = ray_bezier(cs.site.p, u, mid(v - 1), vertex(cs, v), mid(v));
    if (r > 0 && (best < 0 || r < best)) best = r;
  }
  return best > 0 ? best : polygon_radius(cs, angle);
}

double cellular_value(const CellShape& cs, Vec2 x, double wsmooth) {
  const Vec2 dv{x.x - cs.site.p.x, x.y - cs.site.p.y};
  const double r = std::hypot(dv.x, dv.y);
  if (r < 1e-12) return 1.0;
  const double ux = dv.x / r, uy = dv.y / r;
  const double angle = std::atan2(uy, ux);
  auto cv_of = [&](double border) { return border > 0 ? 1.0 - r / border : 0.0; };
  double cv;
  if (wsmooth <= 1) {
    const double c0 = wsmooth < 1 ? cv_of(cellborder(cs, ux, uy)) : 0.0;
    const double c1 = wsmooth > 0 ? cv_of(polygon_radius(cs, angle)) : 0.0;
    cv = (1 - wsmooth) * c0 + wsmooth * c1;
  } else {
    const double t = wsmooth - 1;
    const double c1 = t < 1 ? cv_of(polygon_radius(cs, angle)) : 0.0;
    const double c2 = cv_of(beziercell(cs, angle));
    cv = (1 - t) * c1 + t * c2;
  }
  return std::clamp(cv, 0.0, 1.0);
}

double window_w1(double cv, double normblend, double sigw1) {
  return std::max(0.0, normblend * (std::exp((cv - 1.0) * sigw1) - std::exp(-sigw1)));
}

double window_w2(double sddno, double normblend, double sigw2, double footprint) {
  return std::max(0.0, (1.0 - normblend) * (std::exp(-sigw2 * sddno) - std::exp(-sigw2 * footprint)));
}

}  // namespace ppsynth::pptbf_impl
