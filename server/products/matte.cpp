#include "server/products/matte.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace inkwire {
namespace {

float colour_distance(const uint8_t* a, const cv::Vec3f& b) {
  const float dr = float(a[0]) - b[0], dg = float(a[1]) - b[1], db = float(a[2]) - b[2];
  return std::sqrt(dr * dr + dg * dg + db * db);
}


int border_band(const Image& photo) { return std::max(2, std::min(photo.width, photo.height) / 50); }

std::vector<const uint8_t*> border_pixels(const Image& photo) {
  const int w = photo.width, h = photo.height, band = border_band(photo);
  std::vector<const uint8_t*> border;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (x < band || y < band || x >= w - band || y >= h - band) border.push_back(photo.at(x, y));
  return border;
}

glm::vec3 median_colour(const std::vector<const uint8_t*>& pixels) {
  glm::vec3 out(0.0f);
  for (int c = 0; c < 3; ++c) {
    std::vector<uint8_t> v;
    v.reserve(pixels.size());
    for (const uint8_t* p : pixels) v.push_back(p[c]);
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    out[c] = float(v[v.size() / 2]);
  }
  return out;
}

}  // namespace

glm::vec3 backdrop_colour(const Image& photo) { return median_colour(border_pixels(photo)); }

MatteResult key_plain_background(Image& photo) {
  MatteResult result;
  const int w = photo.width, h = photo.height;
  // The outer 2% of the photo is backdrop.
  const std::vector<const uint8_t*> border = border_pixels(photo);
  const glm::vec3 median = median_colour(border);
  const cv::Vec3f backdrop(median.r, median.g, median.b);
  std::vector<float> distances;
  distances.reserve(border.size());
  for (const uint8_t* p : border) distances.push_back(colour_distance(p, backdrop));
  std::sort(distances.begin(), distances.end());
  const float noise = distances[distances.size() * 9 / 10];  // how far 90% of the backdrop strays
  if (noise > 40.0f) {
    result.reason = "its border is not a plain background (colours stray by " + std::to_string(int(noise)) + " of 441)";
    return result;
  }
  // Object: clearly unlike the backdrop. Speckles are opened away; the outline is what the
  // backdrop, flooded from the border, does not reach.
  const float threshold = std::max(24.0f, 2.5f * noise);
  cv::Mat object(h, w, CV_8U);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) object.at<uint8_t>(y, x) = colour_distance(photo.at(x, y), backdrop) > threshold ? 255 : 0;
  cv::morphologyEx(object, object, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_ELLIPSE, {3, 3}));
  cv::Mat flooded(h + 2, w + 2, CV_8U, cv::Scalar(0));
  object.copyTo(flooded(cv::Rect(1, 1, w, h)));
  cv::floodFill(flooded, cv::Point(0, 0), 128);
  cv::Mat matte(h, w, CV_8U);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) matte.at<uint8_t>(y, x) = flooded.at<uint8_t>(y + 1, x + 1) == 128 ? 0 : 255;
  // Only the largest piece is the object; the rest is dust, reflections and the turntable's edge.
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(matte, labels, stats, centroids, 8);
  int largest = 0, largest_area = 0;
  for (int i = 1; i < n; ++i)
    if (stats.at<int>(i, cv::CC_STAT_AREA) > largest_area) largest = i, largest_area = stats.at<int>(i, cv::CC_STAT_AREA);
  result.object_fraction = double(largest_area) / double(w * h);
  if (largest == 0 || result.object_fraction < 0.005) {
    result.reason = "nothing stands out from its background";
    return result;
  }
  if (result.object_fraction > 0.95) {
    result.reason = "the object fills the whole photo, so no background is left to key";
    return result;
  }
  cv::Mat soft = (labels == largest);
  cv::GaussianBlur(soft, soft, {3, 3}, 0.7);  // a pixel of soft edge against stair steps
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) photo.at(x, y)[3] = soft.at<uint8_t>(y, x);
  result.keyed = true;
  return result;
}

}  // namespace inkwire
