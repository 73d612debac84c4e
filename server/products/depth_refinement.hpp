#pragma once
// The hull's depth maps taken in where the photos say the surface is deeper (SPEC T25): a visual
// hull holds the object but bulges past it wherever no silhouette saw the surface edge-on (a
// concavity, and between the views of a sparse ring every facet's corners). Along each pixel's ray
// the true surface lies at or behind the hull's; a plane sweep tries depths from the hull's
// (less one cell, for the hull's own steps) to kSweepCells cells behind it, each warping the
// photo's row neighbours onto it, and keeps the depth where the pictures agree best over a 5 x 5
// window, taking the better-agreeing neighbour (the other may not see the point). A pixel keeps
// the hull's depth unless another agrees clearly better (plain paint agrees at every depth).
#include <vector>

#include <opencv2/core.hpp>

#include "common/image.hpp"
#include "server/products/turntable_camera.hpp"

namespace inkwire {

inline constexpr float kSweepCells = 8, kSweepStep = 0.5f;  // how far behind the hull, in steps of its cells
inline constexpr float kClearlyAgrees = 0.8f;               // a depth's disagreement against the hull depth's

// How far `to` (grey), warped onto `from` by `map` (per pixel of `from`, where to read `to`; off
// `to` reads as far off any grey), disagrees with `from` at each pixel: the 5 x 5 mean of the
// absolute differences.
cv::Mat warp_disagreement(const cv::Mat& from, const cv::Mat& to, const cv::Mat& map);

// `depth[v]` (distance ahead of photo v's camera, 0 off the object) refined against the photos'
// row neighbours; `cell` the hull's cell size. Photos RGBA, of the camera's size.
void refine_depth(std::vector<std::vector<float>>& depth, const TurntableCamera& camera, const std::vector<PhotoView>& views,
                  const std::vector<const Image*>& photos, int columns, float cell);

}  // namespace inkwire
