#pragma once
// Dense, verified correspondence between neighbouring photos of a turntable (SPEC T15), and its
// distillation into the few hundred control points the tween data carries.
//
// Real shop photos defeat sparse landmarks: a plaid, laces or a logo repeat, and a sparse point
// set aligns the outline while the inside cross-fades (doubled detail). Optical flow (DIS)
// computed both ways gives a motion for every pixel; a pixel's flow is kept when following it
// there and back lands within two pixels of where it started (occluded and repeated structure
// fails this; at one pixel too little of a 300-pixel photo was left to place points on). The tween data cannot carry a flow field, so control points are placed where the
// piecewise-affine warp through the points already chosen is furthest from the verified flow,
// weighted by how much detail is there to double: a greedy refinement that spends points on
// textured, non-rigidly moving parts and few on plain ones.
#include <vector>

#include <opencv2/core.hpp>

#include "common/image.hpp"
#include "server/tween/landmarks.hpp"

namespace inkwire {

struct DenseMatches {
  cv::Mat forward;   // CV_32FC2, per pixel of a: where it is in b, minus where it is in a
  cv::Mat backward;  // CV_32FC2, per pixel of b: the same from b to a
  cv::Mat reliable;           // CV_8U, 255 where a's flow is verified (both ways agree, inside both mattes)
  cv::Mat reliable_backward;  // CV_8U, the same for b's flow
};

struct DenseMatchOptions {
  float max_round_trip = 2.0f;  // pixels: forward then backward must land this close to the start
  bool use_mattes = true;       // alpha < 128 is backdrop: no flow is kept there
};

// Flow both ways between two photos of one size (grey, DIS at its medium preset down to full
// resolution), checked forward-backward. (Seeding DIS with verified SIFT matches, or running it
// on photos scaled up twice, measured no better on the spin sets: docs/benchmarks-journal.md.)
DenseMatches dense_matches(const Image& a, const Image& b, const DenseMatchOptions& options = {});

// The same matches read from b to a.
DenseMatches reversed(const DenseMatches& matches);

// Where `matches` place the pixel `p` of a in b (bilinear in the flow).
cv::Point2f flow_at(const cv::Mat& flow, cv::Point2f p);

struct DistilOptions {
  int max_points = 130;          // control points of the pair in all (12 bytes each in the tween data)
  float min_spacing = 7.0f;      // pixels between chosen points
  float tolerance = 0.6f;        // pixels: stop when the weighted warp error is below this everywhere
  int points_per_round = 24;     // added before the error is measured again
};

// A point of photo a followed into the other photos of its cell (a pair's second photo; a
// triangle's row neighbour and the photo above or below).
struct Track {
  glm::vec2 source;
  std::vector<glm::vec2> targets;  // one per flow, in the flows' order
  glm::vec2 bulge{0.0f};           // a pair's: its halfway place off the straight line's midpoint (from a shape)
};
// Control points for a cell from a's verified flows into its other photos: `anchors` (outline
// points, kept as they are, first) plus points where the warps through the points so far err
// most (error x detail). A pixel counts where every flow is verified, and errs by the worst of
// its warps.
std::vector<Track> distil_tracks(const std::vector<const DenseMatches*>& flows, const Image& a, std::vector<Track> anchors,
                                 const DistilOptions& options = {});

// The quality reference for tweens (the benchmark's "flow" rows): what a dense method gets with
// everything on the client. Flow both ways, each photo warped part of the way (a to t, b to
// 1 - t, backward warping with the flow at the view's pixel), blended by t. RGBA, alpha as the
// photos' (mattes warp with their photos).
Image flow_interpolation(const Image& a, const Image& b, float t);

// Two photos warped backward, each read at every pixel x at x + reach * its flow (x), and
// blended by t: (1 - t) a's + t b's. flow_interpolation's last step; the benchmark's bound warps
// by the flows from the held-out photo, reach 1.
Image blend_along_flows(const Image& a, const cv::Mat& flow_a, float reach_a, const Image& b, const cv::Mat& flow_b, float reach_b, float t);

// The flow of the piecewise-linear warp through `points` (source -> target) at every pixel of a
// `size` image, triangulated on the sources; pixels outside every triangle get zero flow.
cv::Mat warp_flow(const std::vector<Landmark>& points, cv::Size size);

}  // namespace inkwire
