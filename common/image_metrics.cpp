#include "common/image_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>

#include "common/error.hpp"
#include "common/luminance.hpp"

namespace inkwire {
namespace {

void check_sizes(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.empty())
    throw Error("cannot compare a " + std::to_string(a.width) + "x" + std::to_string(a.height) + " image with a " +
                std::to_string(b.width) + "x" + std::to_string(b.height) + " one");
}

double psnr_of(const Image& a, const Image& b, bool covered_only) {
  check_sizes(a, b);
  double sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 4) {
    if (covered_only && a.pixels[i + 3] == 0 && b.pixels[i + 3] == 0) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = double(a.pixels[i + c]) - double(b.pixels[i + c]);
      sum += d * d;
    }
    n += 3;
  }
  if (n == 0 || sum == 0.0) return 99.0;
  return std::min(99.0, 10.0 * std::log10(255.0 * 255.0 / (sum / double(n))));
}

cv::Mat luma(const Image& image) {
  cv::Mat out(image.height, image.width, CV_64F);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.at(x, y);
      out.at<double>(y, x) = rec601_luma<double>(p[0], p[1], p[2]);
    }
  return out;
}

}  // namespace

double psnr(const Image& a, const Image& b) { return psnr_of(a, b, false); }
double psnr_covered(const Image& a, const Image& b) { return psnr_of(a, b, true); }

double ssim(const Image& a, const Image& b) {
  check_sizes(a, b);
  const double c1 = std::pow(0.01 * 255, 2), c2 = std::pow(0.03 * 255, 2);
  const cv::Mat x = luma(a), y = luma(b);
  auto blur = [](const cv::Mat& m) {
    cv::Mat out;
    cv::GaussianBlur(m, out, cv::Size(11, 11), 1.5);
    return out;
  };
  const cv::Mat mx = blur(x), my = blur(y);
  const cv::Mat mx2 = mx.mul(mx), my2 = my.mul(my), mxy = mx.mul(my);
  const cv::Mat sx2 = blur(x.mul(x)) - mx2, sy2 = blur(y.mul(y)) - my2, sxy = blur(x.mul(y)) - mxy;
  cv::Mat numerator = (2 * mxy + c1).mul(2 * sxy + c2);
  cv::Mat denominator = (mx2 + my2 + c1).mul(sx2 + sy2 + c2);
  cv::Mat map;
  cv::divide(numerator, denominator, map);
  return cv::mean(map)[0];
}

double matte_iou(const Image& a, const Image& b) {
  check_sizes(a, b);
  size_t both = 0, either = 0;
  for (size_t i = 3; i < a.pixels.size(); i += 4) {
    const bool in_a = a.pixels[i] >= 128, in_b = b.pixels[i] >= 128;
    both += in_a && in_b;
    either += in_a || in_b;
  }
  return either == 0 ? 1.0 : double(both) / double(either);
}

double ghost_fraction(const Image& image) {
  const int w = image.width, h = image.height;
  auto alpha = [&](int x, int y) { return image.at(std::clamp(x, 0, w - 1), std::clamp(y, 0, h - 1))[3]; };
  size_t object = 0, ghost = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int a = alpha(x, y);
      if (a <= 25) continue;
      ++object;
      if (a >= 230) continue;
      // An antialiased edge pixel has a fully covered and an empty pixel within one step.
      bool full = false, empty = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          full = full || alpha(x + dx, y + dy) >= 230;
          empty = empty || alpha(x + dx, y + dy) <= 25;
        }
      if (!(full && empty)) ++ghost;
    }
  return object == 0 ? 0.0 : double(ghost) / double(object);
}

Image over_colour(const Image& image, glm::u8vec3 colour, bool premultiplied) {
  Image out = image;
  for (size_t i = 0; i < out.pixels.size(); i += 4) {
    const int a = image.pixels[i + 3];
    for (int c = 0; c < 3; ++c) {
      const int src = premultiplied ? image.pixels[i + size_t(c)] : (image.pixels[i + size_t(c)] * a + 127) / 255;
      out.pixels[i + size_t(c)] = uint8_t(std::min(255, src + (colour[c] * (255 - a) + 127) / 255));
    }
    out.pixels[i + 3] = 255;
  }
  return out;
}

}  // namespace inkwire
