#include "client/render/face/comic_photo.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace inkwire {

void comic_photo(Image& image, int bands) {
  if (image.width < 8 || image.height < 8) return;
  bands = std::clamp(bands, 2, 8);
  cv::Mat rgba(image.height, image.width, CV_8UC4, image.pixels.data());
  cv::Mat rgb, smooth, tmp;
  cv::cvtColor(rgba, rgb, cv::COLOR_RGBA2RGB);
  // Flat areas, sharp borders: two small bilateral passes on a half-size copy.
  cv::Mat half;
  cv::resize(rgb, half, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
  cv::bilateralFilter(half, tmp, 7, 40, 5);
  cv::bilateralFilter(tmp, half, 7, 40, 5);
  cv::resize(half, smooth, rgb.size(), 0, 0, cv::INTER_LINEAR);
  // Tone bands on the luminance, the darkest band a quarter darker still; colour kept.
  cv::Mat lab;
  cv::cvtColor(smooth, lab, cv::COLOR_RGB2Lab);
  for (int y = 0; y < lab.rows; ++y)
    for (int x = 0; x < lab.cols; ++x) {
      cv::Vec3b& p = lab.at<cv::Vec3b>(y, x);
      const int band = std::min(bands - 1, p[0] * bands / 256);
      float l = (float(band) + 0.5f) * 255.0f / float(bands);
      if (band == 0) l *= 0.76f;
      p[0] = uint8_t(l);
    }
  cv::cvtColor(lab, smooth, cv::COLOR_Lab2RGB);
  // Ink: the strong edges of the grey photo, a little thickened.
  cv::Mat grey, edges;
  cv::cvtColor(rgb, grey, cv::COLOR_RGB2GRAY);
  cv::medianBlur(grey, grey, 5);
  cv::Canny(grey, edges, 40, 110);
  cv::dilate(edges, edges, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2, 2)));
  for (int y = 0; y < rgba.rows; ++y)
    for (int x = 0; x < rgba.cols; ++x) {
      cv::Vec4b& out = rgba.at<cv::Vec4b>(y, x);
      const cv::Vec3b c = edges.at<uint8_t>(y, x) ? cv::Vec3b(25, 20, 20) : smooth.at<cv::Vec3b>(y, x);
      out[0] = c[0], out[1] = c[1], out[2] = c[2];
    }
}

}  // namespace inkwire
