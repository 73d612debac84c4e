#include "server/products/silhouette_cut.hpp"

#include <algorithm>
#include <cstdint>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "server/products/matte.hpp"

namespace inkwire {
namespace {

inline constexpr int kIterations = 5;             // GrabCut's rounds of fitting the colour models and cutting again
inline constexpr double kLeastObject = 0.005;     // of the photo: less is nothing standing out
inline constexpr double kMostObject = 0.9;        // of the photo: more leaves no backdrop to tell it from
inline constexpr double kMostEdgeTouched = 0.25;  // of the cut's frame: an object on more of it runs off the photo
inline constexpr int kBackdropColours = 6;        // the border's colours, clustered (a cloth's folds, a floor's light)
inline constexpr float kStandsOut = 30;           // of 441: a pixel this far from every one of them starts as likely object
inline constexpr uint64_t kCutSeed = 0x1a2b3c4d;  // OpenCV's random generator, set alike for every cut

// The colours the border band of `band` pixels of `picture` holds, clustered (k-means): rows of
// three floats.
cv::Mat backdrop_colours(const cv::Mat& picture, int band) {
  cv::Mat border_pixels;
  for (int y = 0; y < picture.rows; ++y)
    for (int x = 0; x < picture.cols; ++x)
      if (x < band || y < band || x >= picture.cols - band || y >= picture.rows - band) {
        const cv::Vec3b c = picture.at<cv::Vec3b>(y, x);
        border_pixels.push_back(cv::Vec3f(c[0], c[1], c[2]));
      }
  border_pixels = border_pixels.reshape(1, border_pixels.rows);
  cv::Mat labels, centres;
  cv::kmeans(border_pixels, std::min(kBackdropColours, border_pixels.rows), labels,
             cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 20, 1.0), 2, cv::KMEANS_PP_CENTERS, centres);
  return centres;
}

// Per pixel of `picture`, how far its colour lies from the nearest of `colours`.
cv::Mat distance_from(const cv::Mat& picture, const cv::Mat& colours) {
  cv::Mat out(picture.size(), CV_32F);
  for (int y = 0; y < picture.rows; ++y)
    for (int x = 0; x < picture.cols; ++x) {
      const cv::Vec3b c = picture.at<cv::Vec3b>(y, x);
      float nearest = 1e9f;
      for (int i = 0; i < colours.rows; ++i)
        nearest = std::min(nearest, float(cv::norm(cv::Vec3f(c[0], c[1], c[2]) - cv::Vec3f(colours.at<float>(i, 0), colours.at<float>(i, 1), colours.at<float>(i, 2)))));
      out.at<float>(y, x) = nearest;
    }
  return out;
}

}  // namespace

SilhouetteCut cut_silhouette(const Image& photo) {
  SilhouetteCut out;
  const int w = photo.width, h = photo.height;
  if (w < 16 || h < 16) {
    out.reason = "the photo is too small to cut";
    return out;
  }
  // k-means and GrabCut draw from OpenCV's random generator: started alike for every photo, the
  // same photo is cut the same way whatever ran before it (a product is made once and found again).
  const uint64_t outside_state = cv::theRNG().state;
  cv::theRNG().state = kCutSeed;
  struct Restore {
    uint64_t state;
    ~Restore() { cv::theRNG().state = state; }
  } restore{outside_state};
  const double scale = std::min(1.0, double(kCutSide) / double(std::max(w, h)));
  cv::Mat rgb(h, w, CV_8UC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t* p = photo.at(x, y);
      rgb.at<cv::Vec3b>(y, x) = {p[2], p[1], p[0]};
    }
  cv::Mat small;
  cv::resize(rgb, small, {std::max(8, int(w * scale + 0.5)), std::max(8, int(h * scale + 0.5))}, 0, 0, cv::INTER_AREA);
  // The outer 2% is backdrop for certain (as the plain keyer takes it); inside it, what is near one
  // of its colours starts as likely backdrop and the rest as likely object (a small object in a
  // large picture would otherwise leave the likely object mostly the backdrop's own colours).
  const int band = border_band(small.cols, small.rows);
  const cv::Rect frame(band, band, small.cols - 2 * band, small.rows - 2 * band);
  const cv::Mat unlike = distance_from(small, backdrop_colours(small, band));
  cv::Mat mask(small.size(), CV_8U, cv::Scalar(cv::GC_BGD));
  int likely_object = 0;
  for (int y = frame.y; y < frame.br().y; ++y)
    for (int x = frame.x; x < frame.br().x; ++x) {
      const bool stands_out = unlike.at<float>(y, x) > kStandsOut;
      mask.at<uint8_t>(y, x) = stands_out ? cv::GC_PR_FGD : cv::GC_PR_BGD;
      likely_object += stands_out;
    }
  if (likely_object < kLeastObject * double(small.total())) {
    out.reason = "nothing stands out from its backdrop's colours";
    return out;
  }
  cv::Mat background, object;
  cv::grabCut(small, mask, frame, background, object, kIterations, cv::GC_INIT_WITH_MASK);
  cv::Mat cut = (mask == cv::GC_FGD) | (mask == cv::GC_PR_FGD);
  // Speckles of the backdrop's cloth taken for object are opened away; the largest piece is the object.
  cv::morphologyEx(cut, cut, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_ELLIPSE, {3, 3}));
  cv::Mat labels, stats, centroids;
  const int pieces = cv::connectedComponentsWithStats(cut, labels, stats, centroids, 8);
  int largest = 0, area = 0;
  for (int i = 1; i < pieces; ++i)
    if (stats.at<int>(i, cv::CC_STAT_AREA) > area) largest = i, area = stats.at<int>(i, cv::CC_STAT_AREA);
  const double share = double(area) / double(small.total());
  if (largest == 0 || share < kLeastObject) {
    out.reason = "nothing stands out from its backdrop";
    return out;
  }
  if (share > kMostObject) {
    out.reason = "the object fills the photo, so no backdrop is left to tell it from";
    return out;
  }
  const cv::Mat piece = labels == largest;
  int touched = 0;
  for (int x = frame.x; x < frame.br().x; ++x) touched += (piece.at<uint8_t>(frame.y, x) != 0) + (piece.at<uint8_t>(frame.br().y - 1, x) != 0);
  for (int y = frame.y; y < frame.br().y; ++y) touched += (piece.at<uint8_t>(y, frame.x) != 0) + (piece.at<uint8_t>(y, frame.br().x - 1) != 0);
  if (double(touched) > kMostEdgeTouched * 2.0 * double(frame.width + frame.height)) {
    out.reason = "the object runs off the photo's edges (" + std::to_string(100 * touched / (2 * (frame.width + frame.height))) + "% of them)";
    return out;
  }
  cv::Mat full;
  cv::resize(piece, full, {w, h}, 0, 0, cv::INTER_LINEAR);
  out.silhouette = {.width = w, .height = h, .inside = std::vector<uint8_t>(size_t(w) * size_t(h), 0)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) out.silhouette.inside[size_t(y * w + x)] = full.at<uint8_t>(y, x) > 127;
  return out;
}

}  // namespace inkwire
