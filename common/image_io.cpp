// Image files and encodings through OpenImageIO and OpenCV (native builds; the WebAssembly build
// decodes with stb_image instead: common/image_io_web.cpp).
#include <algorithm>
#include <cstring>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "common/error.hpp"
#include "common/image.hpp"

namespace inkwire {

namespace {

Image read_all(OIIO::ImageInput& in, const std::string& name) {
  const OIIO::ImageSpec& spec = in.spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.width > kMaxImageSide || spec.height > kMaxImageSide)
    throw Error(name + ": image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                " is outside 1.." + std::to_string(kMaxImageSide));
  if (spec.nchannels < 1 || spec.nchannels > 16) throw Error(name + ": image has an unsupported channel count");
  const int channels = spec.nchannels;
  std::vector<uint8_t> raw(size_t(spec.width) * spec.height * channels);
  if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data()))
    throw Error(name + ": " + in.geterror());
  Image img(spec.width, spec.height);
  for (size_t i = 0, n = size_t(spec.width) * spec.height; i < n; ++i) {
    const uint8_t* s = &raw[i * channels];
    uint8_t* d = &img.pixels[i * 4];
    if (channels >= 3) {
      d[0] = s[0], d[1] = s[1], d[2] = s[2];
    } else {
      d[0] = d[1] = d[2] = s[0];
    }
    d[3] = channels == 2 ? s[1] : channels >= 4 ? s[3] : 255;
  }
  return img;
}

}  // namespace

Image load_image(const std::filesystem::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw Error(file.string() + ": " + OIIO::geterror());
  return read_all(*in, file.string());
}

std::vector<uint8_t> encode_image(const Image& image, const std::string& format, int quality, int first_channel, int channels) {
  if (image.width <= 0 || image.height <= 0 || image.pixels.size() != size_t(image.width) * size_t(image.height) * 4)
    throw Error("encode_image: empty or inconsistent image");
  if ((channels != 1 && channels != 3) || first_channel < 0 || first_channel + channels > 4) throw Error("encode_image: bad channels");
  const cv::Mat rgba(image.height, image.width, CV_8UC4, const_cast<uint8_t*>(image.pixels.data()));
  cv::Mat pixels;
  if (channels == 3) {
    cv::cvtColor(rgba, pixels, cv::COLOR_RGBA2BGR);
  } else {
    pixels.create(image.height, image.width, CV_8UC1);
    cv::extractChannel(rgba, pixels, first_channel);
  }
  std::vector<int> parameters;
  if (format == "jpg") parameters = {cv::IMWRITE_JPEG_QUALITY, std::clamp(quality, 1, 100)};
  std::vector<uint8_t> out;
  bool ok = false;
  try {
    ok = cv::imencode("." + format, pixels, out, parameters);
  } catch (const cv::Exception& e) {
    throw Error(std::string("cannot encode ") + format + ": " + e.what());
  }
  if (!ok) throw Error("cannot encode " + format);
  return out;
}

Image load_image_from_memory(std::span<const uint8_t> encoded, const std::string& name) {
  // OpenCV decodes from memory by the bytes' magic number (PNG, JPEG, BMP, ...); OpenImageIO's
  // memory readers do not work for every format in the packaged build.
  if (encoded.empty()) throw Error(name + ": no image bytes");
  const cv::Mat bytes(1, int(std::min<size_t>(encoded.size(), INT32_MAX)), CV_8U, const_cast<uint8_t*>(encoded.data()));
  cv::Mat decoded;
  try {
    decoded = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception&) {  // decoders throw on some malformed data instead of failing
  }
  if (decoded.empty()) throw Error(name + ": not an image in a format that can be read (PNG, JPEG, BMP, ...)");
  if (decoded.cols > kMaxImageSide || decoded.rows > kMaxImageSide)
    throw Error(name + ": image size " + std::to_string(decoded.cols) + "x" + std::to_string(decoded.rows) + " is outside 1.." +
                std::to_string(kMaxImageSide));
  if (decoded.depth() == CV_16U) decoded.convertTo(decoded, CV_8U, 1.0 / 257.0);
  if (decoded.depth() != CV_8U) throw Error(name + ": image samples are not 8 or 16 bits");
  cv::Mat rgba;
  switch (decoded.channels()) {
    case 1: cv::cvtColor(decoded, rgba, cv::COLOR_GRAY2RGBA); break;
    case 3: cv::cvtColor(decoded, rgba, cv::COLOR_BGR2RGBA); break;
    case 4: cv::cvtColor(decoded, rgba, cv::COLOR_BGRA2RGBA); break;
    default: throw Error(name + ": image has an unsupported channel count");
  }
  Image img(rgba.cols, rgba.rows);
  for (int y = 0; y < rgba.rows; ++y) std::memcpy(&img.pixels[size_t(y) * rgba.cols * 4], rgba.ptr(y), size_t(rgba.cols) * 4);
  return img;
}

void save_image(const Image& image, const std::filesystem::path& file, bool keep_alpha) {
  if (image.empty()) throw Error(file.string() + ": refusing to write an empty image");
  auto out = OIIO::ImageOutput::create(file.string());
  if (!out) throw Error(file.string() + ": " + OIIO::geterror());
  const int channels = keep_alpha ? 4 : 3;
  OIIO::ImageSpec spec(image.width, image.height, channels, OIIO::TypeDesc::UINT8);
  if (!out->open(file.string(), spec)) throw Error(file.string() + ": " + out->geterror());
  // Strides let OpenImageIO skip the alpha byte when it is not wanted.
  const OIIO::stride_t xstride = 4, ystride = OIIO::stride_t(image.width) * 4;
  if (!out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data(), xstride, ystride) || !out->close())
    throw Error(file.string() + ": " + out->geterror());
}

Image resized(const Image& image, int width, int height) {
  if (width <= 0 || height <= 0 || image.width <= 0 || image.height <= 0) throw Error("resized(): empty image or size");
  Image out(width, height);
  const cv::Mat source(image.height, image.width, CV_8UC4, const_cast<uint8_t*>(image.pixels.data()));
  cv::Mat target(height, width, CV_8UC4, out.pixels.data());
  const bool shrinking = width < image.width || height < image.height;
  cv::resize(source, target, target.size(), 0, 0, shrinking ? cv::INTER_AREA : cv::INTER_LINEAR);
  return out;
}

Image side_by_side(const std::vector<Image>& panels, const std::vector<std::string>& captions) {
  const Image pictures = side_by_side(panels);
  constexpr int kStrip = 28;
  Image out(pictures.width, pictures.height + kStrip, glm::u8vec4(32, 32, 36, 255));
  std::copy(pictures.pixels.begin(), pictures.pixels.end(), out.pixels.begin() + ptrdiff_t(size_t(out.width) * kStrip * 4));
  static const std::string font = std::filesystem::exists("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf")
                                      ? "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf" : "";
  OIIO::ImageBuf strip(OIIO::ImageSpec(out.width, kStrip, 4, OIIO::TypeDesc::UINT8), out.pixels.data());
  const float white[4] = {1, 1, 1, 1};
  int x = 0;
  for (size_t i = 0; i < panels.size(); ++i) {
    // Cut to what fits its panel (about 8 pixels a letter at this size), so captions never run together.
    const size_t fits = size_t(std::max(panels[i].width - 16, 0) / 8);
    if (i < captions.size() && !captions[i].empty() && fits > 0)
      OIIO::ImageBufAlgo::render_text(strip, x + 8, 19, captions[i].substr(0, fits), 15, font, white);
    x += panels[i].width;
  }
  return out;
}

}  // namespace inkwire
