#pragma once
// Colors shared by every plot so a class has the same color in every figure:
// class k -> Tableau-10 (cycled), continuous values -> a viridis ramp, signed values -> a
// blue-white-red diverging ramp. All channels in [0,1] (cairo's convention).
namespace ppsynth::render {

struct Rgb {
  double r = 0, g = 0, b = 0;
};

// Tableau-10 color of class k (k >= 0; cycles after 10).
Rgb class_color(int k);
// Viridis approximation, t clamped to [0,1] (0 = dark purple, 1 = yellow).
Rgb viridis(double t);
// Diverging ramp, t clamped to [-1,1]: -1 blue, 0 white, +1 red.
Rgb diverging(double t);
// Gray level t in [0,1] (0 black, 1 white).
Rgb gray(double t);

}  // namespace ppsynth::render
