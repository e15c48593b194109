#pragma once
// The 2-D power spectrum of a point set (core/metrics/periodogram.hpp) as a heat map: log10
// of the power in the viridis ramp, frequency axes fx (right) and fy (up) labeled in cycles
// per coordinate unit, a color bar with the power's decades. The DC term (removed by the
// periodogram) is drawn gray. The color range runs from the 1st percentile of the power (at
// least 1e-6 of the maximum: a lattice's empty frequencies are ~1e-25) to its maximum, so
// white noise (P ~ 1) is mid-ramp and isolated peaks (tiles, seams) are the brightest pixels.
// Output format by extension: .png, .svg, .pdf (render/canvas.hpp); atomic writes.
#include <string>

#include "core/metrics/periodogram.hpp"

namespace ppsynth {

// `frame_px`: side of the square heat map (>= 64; the image adds axes, title and color bar).
void plot_spectrum(const std::string& path, const Periodogram& p, const std::string& title = "",
                   int frame_px = 560);

}  // namespace ppsynth
