#include "client/call/call_captions.hpp"

#include <opencv2/imgproc.hpp>

namespace inkwire {

void draw_call_captions(Image& frame, const std::vector<CallGrid::Tile>& tiles) {
  cv::Mat pixels(frame.height, frame.width, CV_8UC4, frame.pixels.data());
  for (const CallGrid::Tile& t : tiles) {
    const cv::Point at(t.rect.x + 2, t.rect.y + t.rect.w + 16);
    const cv::Scalar colour = t.speaking ? cv::Scalar(90, 230, 120, 255) : cv::Scalar(235, 235, 235, 255);
    // As large as reads well, smaller when the caption would run past its tile.
    const std::string text = caption_of(t);
    double scale = 0.45;
    int baseline = 0;
    const int width = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline).width;
    if (width > t.rect.z) scale *= double(t.rect.z) / width;
    cv::putText(pixels, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
  }
}

}  // namespace inkwire
