#include "server/products/matte.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "common/percentile.hpp"

namespace inkwire {
namespace {

float colour_distance(const uint8_t* a, const cv::Vec3f& b) {
  const float dr = float(a[0]) - b[0], dg = float(a[1]) - b[1], db = float(a[2]) - b[2];
  return std::sqrt(dr * dr + dg * dg + db * db);
}

std::vector<const uint8_t*> border_pixels(const Image& photo) {
  const int w = photo.width, h = photo.height, band = border_band(w, h);
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
    out[c] = float(median_in_place(std::span<uint8_t>(v)).value_or(0));
  }
  return out;
}

// Pixels of the floor the object shades: darker than the backdrop by about the same share in
// every channel (a shadow takes light, not colour), and smooth (a shadow's edge is soft; the
// grey sole of a shoe has edges).
cv::Mat floor_shade(const Image& photo, const cv::Vec3f& backdrop) {
  const int w = photo.width, h = photo.height;
  cv::Mat grey(h, w, CV_32F), shade(h, w, CV_8U, cv::Scalar(0));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t* p = photo.at(x, y);
      grey.at<float>(y, x) = (float(p[0]) + float(p[1]) + float(p[2])) / 3.0f;
    }
  cv::Mat gx, gy, slope;
  cv::GaussianBlur(grey, grey, {0, 0}, 1.0);
  cv::Sobel(grey, gx, CV_32F, 1, 0, 3, 1.0 / 8.0);
  cv::Sobel(grey, gy, CV_32F, 0, 1, 3, 1.0 / 8.0);
  cv::magnitude(gx, gy, slope);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t* p = photo.at(x, y);
      float low = 2.0f, high = 0.0f, mean = 0.0f;
      for (int c = 0; c < 3; ++c) {
        const float r = float(p[c]) / std::max(backdrop[c], 1.0f);
        low = std::min(low, r), high = std::max(high, r), mean += r / 3.0f;
      }
      if (mean > 0.3f && mean < 0.97f && high - low < 0.08f && slope.at<float>(y, x) < 12.0f) shade.at<uint8_t>(y, x) = 255;
    }
  return shade;
}

// Pixels further than `threshold` from the backdrop's colour.
cv::Mat unlike_backdrop(const Image& photo, const cv::Vec3f& backdrop, float threshold) {
  cv::Mat out(photo.height, photo.width, CV_8U);
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x) out.at<uint8_t>(y, x) = colour_distance(photo.at(x, y), backdrop) > threshold ? 255 : 0;
  return out;
}

// The connected pieces of `mask` that have a pixel in `touching`.
cv::Mat pieces_touching(const cv::Mat& mask, const cv::Mat& touching) {
  cv::Mat pieces;
  const int count = cv::connectedComponents(mask, pieces, 8);
  std::vector<uint8_t> keep(size_t(count), 0);
  for (int y = 0; y < mask.rows; ++y)
    for (int x = 0; x < mask.cols; ++x)
      if (mask.at<uint8_t>(y, x) && touching.at<uint8_t>(y, x)) keep[size_t(pieces.at<int>(y, x))] = 255;
  keep[0] = 0;
  cv::Mat out(mask.size(), CV_8U);
  for (int y = 0; y < mask.rows; ++y)
    for (int x = 0; x < mask.cols; ++x) out.at<uint8_t>(y, x) = keep[size_t(pieces.at<int>(y, x))];
  return out;
}

// The largest piece of `mask` with the holes it encloses filled (a hole the colour of the
// backdrop inside an object is far more often paint than air), and its area.
cv::Mat largest_piece(const cv::Mat& mask, int* area) {
  const int w = mask.cols, h = mask.rows;
  cv::Mat object;
  cv::morphologyEx(mask, object, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_ELLIPSE, {3, 3}));
  cv::Mat flooded(h + 2, w + 2, CV_8U, cv::Scalar(0));
  object.copyTo(flooded(cv::Rect(1, 1, w, h)));
  cv::floodFill(flooded, cv::Point(0, 0), 128);
  const cv::Mat filled = flooded(cv::Rect(1, 1, w, h)) != 128;
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(filled, labels, stats, centroids, 8);
  int largest = 0;
  *area = 0;
  for (int i = 1; i < n; ++i)
    if (stats.at<int>(i, cv::CC_STAT_AREA) > *area) largest = i, *area = stats.at<int>(i, cv::CC_STAT_AREA);
  if (largest == 0) return cv::Mat(h, w, CV_8U, cv::Scalar(0));
  return labels == largest;
}

// Keys `photo` by `matte` (its alpha) and `floor` (where the floor layer is, 255): the
// backdrop's part taken out of edge pixels, the floor layer divided by the backdrop's colour,
// the rest white. Returns how many pixels the floor layer covers.
int apply_key(Image& photo, const cv::Mat& matte, const cv::Mat& floor, const cv::Vec3f& backdrop) {
  int layer_pixels = 0;
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x) {
      uint8_t* p = photo.at(x, y);
      p[3] = matte.at<uint8_t>(y, x);
      if (p[3] >= 32 && p[3] < 255) {
        // An edge pixel is part object, part backdrop: the backdrop's part taken out, or the
        // object would wear a rim of the studio's colour on any other backdrop.
        const float a = float(p[3]) / 255.0f;
        for (int c = 0; c < 3; ++c) p[c] = uint8_t(std::clamp(std::round((float(p[c]) - (1.0f - a) * backdrop[c]) / a), 0.0f, 255.0f));
      }
      if (p[3] != 0) continue;
      const bool layer = floor.at<uint8_t>(y, x) != 0;
      layer_pixels += layer;
      for (int c = 0; c < 3; ++c) p[c] = layer ? uint8_t(std::min(255.0f, std::round(float(p[c]) * 255.0f / std::max(backdrop[c], 1.0f)))) : 255;
    }
  return layer_pixels;
}

}  // namespace

int border_band(int width, int height) { return std::max(2, std::min(width, height) / 50); }

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
  // Object: clearly unlike the backdrop, and not floor the object darkens (SPEC T16). Speckles
  // are opened away; the outline is what the backdrop, flooded from the border, does not reach.
  const float threshold = std::max(24.0f, 2.5f * noise);
  const cv::Mat unlike = unlike_backdrop(photo, backdrop, threshold);
  int area = 0;
  const cv::Mat with_shade = largest_piece(unlike, &area);
  result.object_fraction = double(area) / double(w * h);
  if (area == 0 || result.object_fraction < 0.005) {
    result.reason = "nothing stands out from its background";
    return result;
  }
  if (result.object_fraction > 0.95) {
    result.reason = "the object fills the whole photo, so no background is left to key";
    return result;
  }
  // The shadow is taken out of the object only in its lower half (of what stands out, shadow
  // included) and where it fades into the backdrop (a plain grey part of the object is shut off
  // from the backdrop by its own edge), and only where that leaves most of the object and what
  // it takes lies under the rest: a grey product is not its own shadow. (A plain grey part low
  // down that meets the shadow can go with it.)
  cv::Mat shade = floor_shade(photo, backdrop);
  const cv::Rect box = cv::boundingRect(with_shade);
  shade(cv::Rect(0, 0, w, box.y + box.height / 2)).setTo(0);
  cv::Mat backdrop_near;
  cv::dilate(~unlike & ~shade, backdrop_near, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
  shade = pieces_touching(shade, backdrop_near);
  int core_area = 0;
  cv::Mat matte = largest_piece(unlike & ~shade, &core_area);
  const cv::Moments core = cv::moments(matte, true), under = cv::moments(with_shade & ~matte, true);
  if (core_area >= area / 2 && under.m00 > 0 && under.m01 / under.m00 > core.m01 / core.m00)
    result.object_fraction = double(core_area) / double(w * h);
  else
    matte = with_shade;
  // The floor layer: what differs from the backdrop next to the object, kept as it would look on
  // white (a shadow, a reflection); the rest of the backdrop becomes white.
  cv::Mat near;
  cv::dilate(matte, near, cv::getStructuringElement(cv::MORPH_ELLIPSE, {7, 7}));
  const cv::Mat floor = pieces_touching(unlike_backdrop(photo, backdrop, std::max(8.0f, 1.5f * noise)) & ~matte, near);
  cv::Mat soft = matte.clone();
  cv::GaussianBlur(soft, soft, {3, 3}, 0.7);  // a pixel of soft edge against stair steps
  const int layer_pixels = apply_key(photo, soft, floor, backdrop);
  result.floor_fraction = double(layer_pixels) / double(w * h);
  result.backdrop = median;
  result.keyed = true;
  return result;
}

void key_like(Image& larger, const Image& keyed, const glm::vec3& backdrop) {
  const int w = larger.width, h = larger.height;
  // The matte, and the floor layer where the keyed photo's matte is 0 and its colour not white,
  // each as grey, scaled up exactly as clients scale the matte they take the level off again by.
  Image matte_grey(keyed.width, keyed.height), floor_grey(keyed.width, keyed.height);
  for (int y = 0; y < keyed.height; ++y)
    for (int x = 0; x < keyed.width; ++x) {
      const uint8_t* p = keyed.at(x, y);
      matte_grey.at(x, y)[0] = p[3];
      floor_grey.at(x, y)[0] = p[3] == 0 && (p[0] != 255 || p[1] != 255 || p[2] != 255) ? 255 : 0;
    }
  const Image matte_up = matte_scaled_up(matte_grey, w, h), floor_up = matte_scaled_up(floor_grey, w, h);
  cv::Mat matte(h, w, CV_8U), floor(h, w, CV_8U);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      matte.at<uint8_t>(y, x) = matte_up.at(x, y)[0];
      floor.at<uint8_t>(y, x) = floor_up.at(x, y)[0] > 127 ? 255 : 0;
    }
  apply_key(larger, matte, floor, cv::Vec3f(backdrop.r, backdrop.g, backdrop.b));
}

Image laid_on_white(const Image& keyed) {
  Image out = keyed;
  for (size_t i = 0; i < out.pixels.size(); i += 4) {
    const int a = out.pixels[i + 3];
    if (a != 0)
      for (size_t c = 0; c < 3; ++c) out.pixels[i + c] = uint8_t((out.pixels[i + c] * a + 255 * (255 - a) + 127) / 255);
    out.pixels[i + 3] = 255;
  }
  return out;
}

}  // namespace inkwire

