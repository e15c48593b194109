#pragma once
// Mirrored edges for the Gabor maps (output.border "mirror", core/output_shape.hpp).
//
// The published maps are plane: a point near a raster's edge loses the part of its
// influence that falls outside, and outputs collect points on their border (border
// parking, docs/method.md). Reflecting every point within `reach` of an edge across it
// gives that point its missing half, as a reflecting boundary does for an image filter,
// and makes a point ON the edge coincide with its own image: the losses see a doubled
// point there, which they avoid as they avoid coincident pairs. The exemplar is reflected
// the same way at its own edges, so the targets and the output agree at every edge.
//
// Edges are given in the raster's coordinates and need not be the raster's own: a window of
// a large output reflects only at the canvas edges it touches (inside the canvas the frozen
// neighbours are real points). Each axis is reflected in turn, so a corner gets three images.
#include <torch/torch.h>

namespace ppsynth {

struct MirrorEdges {
  // The edges' coordinates; an edge at +-infinity is not reflected.
  double x0, y0, x1, y1;
};

struct MirroredPoints {
  torch::Tensor points;   // the points, then their images (differentiable in the points)
  torch::Tensor weights;  // the weight rows in the same order (undefined when given undefined)
};

// Points (N x 2) and their images across each finite edge, for the points within `reach`
// of it; weights (N x A or undefined) follow their points.
MirroredPoints mirror_edges(const torch::Tensor& points, const torch::Tensor& weights, const MirrorEdges& edges, double reach);

}  // namespace ppsynth
