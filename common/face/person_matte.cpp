#include "common/face/person_matte.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/polygon.hpp"

namespace inkwire {
namespace {

// The cut is found at a size where the eyes are about this far apart: enough for hair's outline,
// small enough that a camera photo costs a few milliseconds.
constexpr float kWorkingEyeDistance = 28;
constexpr int kIterations = 4;  // colour models re-estimated this often (GrabCut converges in a few)
constexpr float kHeadCore = 0.75f;  // of the head's ellipse: about the outline of a head with short hair
constexpr float kSurelyWall = 0.1f;  // a belief below this is the wall even in the head's core

// Where the person is likely to be, in the face frame (units of the eye distance, y down): the
// head an ellipse from above the hair to the chin, the body widening below it.
struct Layout {
  std::vector<glm::vec2> hull;  // the jaw and the forehead above the brows: surely the person
  glm::vec2 hull_centre{0};
  glm::vec2 head_centre{0}, head_radii{1};
  float chin = 1.7f, jaw_half_width = 1;

  explicit Layout(const FaceLandmarks& face) {
    float top = 0;
    chin = face[face_index::kJawFirst].y;
    float left = face[face_index::kJawFirst].x, right = left;
    for (int i = face_index::kJawFirst; i <= face_index::kJawLast; ++i) {
      hull.push_back(face[size_t(i)]);
      chin = std::max(chin, face[size_t(i)].y);
      left = std::min(left, face[size_t(i)].x), right = std::max(right, face[size_t(i)].x);
    }
    // The forehead: the brows raised by a third of the eye distance, right to left to close the ring.
    for (int i = face_index::kBrowRightLast; i >= face_index::kBrowLeftFirst; --i) {
      hull.push_back(face[size_t(i)] - glm::vec2(0, 0.35f));
      top = std::min(top, hull.back().y);
    }
    for (const glm::vec2& p : hull) hull_centre += p / float(hull.size());
    jaw_half_width = std::max(0.5f, (right - left) / 2);
    const float head_top = top - 1.5f;  // hair stands above the forehead
    head_centre = {(left + right) / 2, (head_top + chin + 0.1f) / 2};
    head_radii = {jaw_half_width * 1.45f, (chin + 0.1f - head_top) / 2};
  }

  // The neck just under the chin: surely the person, whatever its collar's colour.
  bool in_neck(glm::vec2 p) const {
    return p.y > chin && p.y < chin + 0.6f && std::abs(p.x - head_centre.x) < jaw_half_width * 0.45f;
  }

  bool in_hull(glm::vec2 p, float shrink) const {
    return inside_polygon(hull, hull_centre + (p - hull_centre) / shrink);
  }

  // How far out of the head's ellipse: below 1 inside.
  float head_reach(glm::vec2 p) const {
    const glm::vec2 d = (p - head_centre) / head_radii;
    return std::sqrt(d.x * d.x + d.y * d.y);  // IEEE rounds sqrt exactly: the same everywhere
  }

  // How far out of the person's likely place: below 1 inside the head's ellipse or the body.
  float reach(glm::vec2 p) const {
    float r = head_reach(p);
    if (p.y > chin - 0.3f) {
      const float half_width = jaw_half_width * 0.75f + std::max(0.0f, p.y - chin) * 2.0f;  // to the shoulders
      r = std::min(r, std::abs(p.x - head_centre.x) / half_width);
    }
    return r;
  }
};

// A separable box blur of radius `radius`, clamped at the borders, in place.
void box_blur(std::vector<float>& plane, int width, int height, int radius) {
  std::vector<float> line;
  const auto pass = [&](int count, int length, auto at) {
    line.resize(size_t(length));
    for (int c = 0; c < count; ++c) {
      for (int i = 0; i < length; ++i) line[size_t(i)] = at(c, i);
      for (int i = 0; i < length; ++i) {
        float sum = 0;
        for (int k = -radius; k <= radius; ++k) sum += line[size_t(std::clamp(i + k, 0, length - 1))];
        at(c, i) = sum / float(2 * radius + 1);
      }
    }
  };
  pass(height, width, [&](int y, int x) -> float& { return plane[size_t(y) * size_t(width) + size_t(x)]; });
  pass(width, height, [&](int x, int y) -> float& { return plane[size_t(y) * size_t(width) + size_t(x)]; });
}

constexpr int kLevels = 16;  // per channel in the colour models
size_t colour_bin(const uint8_t* rgb) { return size_t(rgb[0] >> 4) * kLevels * kLevels + size_t(rgb[1] >> 4) * kLevels + size_t(rgb[2] >> 4); }

// A colour model: a smoothed 16x16x16 histogram, normalised.
std::vector<float> colour_model(const std::vector<size_t>& bins, const std::vector<uint8_t>& label, uint8_t which) {
  std::vector<float> h(size_t(kLevels * kLevels * kLevels), 0.0f);
  for (size_t i = 0; i < bins.size(); ++i)
    if (label[i] == which) h[bins[i]] += 1;
  // Smoothed over neighbouring bins (a 3x3x3 box), so a colour next to a seen one is not unseen.
  for (const size_t stride : {size_t(1), size_t(kLevels), size_t(kLevels * kLevels)}) {
    std::vector<float> out(h.size());
    for (size_t i = 0; i < h.size(); ++i) {
      const size_t level = (i / stride) % kLevels;
      out[i] = h[i] + (level > 0 ? h[i - stride] : 0.0f) + (level + 1 < kLevels ? h[i + stride] : 0.0f);
    }
    h = std::move(out);
  }
  float total = 0;
  for (const float v : h) total += v;
  if (total > 0)
    for (float& v : h) v /= total;
  return h;
}

// The 4-connected region of `label` == `value` reachable from `seeds`.
std::vector<uint8_t> reachable(const std::vector<uint8_t>& label, int width, int height, uint8_t value, const std::vector<size_t>& seeds) {
  std::vector<uint8_t> seen(label.size(), 0);
  std::vector<size_t> stack;
  for (const size_t s : seeds)
    if (label[s] == value && !seen[s]) seen[s] = 1, stack.push_back(s);
  while (!stack.empty()) {
    const size_t i = stack.back();
    stack.pop_back();
    const int x = int(i % size_t(width)), y = int(i / size_t(width));
    for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
      const size_t n = size_t(ny) * size_t(width) + size_t(nx);
      if (label[n] == value && !seen[n]) seen[n] = 1, stack.push_back(n);
    }
  }
  return seen;
}

}  // namespace

PersonMatte person_matte(const Image& photo, const FaceLandmarks& landmarks) {
  const FaceFrame frame = face_frame(landmarks);
  const int step = std::max(1, int(frame.scale / kWorkingEyeDistance));
  const int width = std::max(1, photo.width / step), height = std::max(1, photo.height / step);
  const size_t count = size_t(width) * size_t(height);
  const Layout layout(to_face(landmarks, frame));

  // The photo at the working size (each pixel the mean of its step x step block), its colours'
  // bins, and each pixel's place: sure person (2), sure wall (0) or to be decided (1), with a prior.
  std::vector<size_t> bins(count);
  std::vector<uint8_t> known(count), label(count), head_core(count);
  std::vector<float> prior(count);
  std::vector<size_t> face_pixels;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::array<uint32_t, 3> sum{};
      for (int dy = 0; dy < step; ++dy)
        for (int dx = 0; dx < step; ++dx) {
          const uint8_t* p = photo.at(std::min(x * step + dx, photo.width - 1), std::min(y * step + dy, photo.height - 1));
          for (int c = 0; c < 3; ++c) sum[size_t(c)] += p[c];
        }
      const uint8_t mean[3] = {uint8_t(sum[0] / uint32_t(step * step)), uint8_t(sum[1] / uint32_t(step * step)),
                               uint8_t(sum[2] / uint32_t(step * step))};
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      bins[i] = colour_bin(mean);
      const glm::vec2 at = frame.to_face(glm::vec2((float(x) + 0.5f) * float(step), (float(y) + 0.5f) * float(step)));
      const float reach = layout.reach(at);
      head_core[i] = layout.head_reach(at) < kHeadCore;
      if (layout.in_hull(at, 0.9f) || layout.in_neck(at)) {
        known[i] = 2;
        face_pixels.push_back(i);
      } else {
        known[i] = reach >= 1.5f ? 0 : 1;
      }
      prior[i] = std::clamp(0.75f - 1.2f * (reach - 0.8f), 0.15f, 0.75f);
      label[i] = known[i] == 2 || (known[i] == 1 && reach < 1.3f) ? 1 : 0;
    }
  if (face_pixels.empty()) {
    // A face smaller than a working pixel: its landmarks' nearest pixel is the person.
    const glm::vec2 centre = frame.to_image(layout.hull_centre) / float(step);
    const size_t i = size_t(std::clamp(int(centre.y), 0, height - 1)) * size_t(width) + size_t(std::clamp(int(centre.x), 0, width - 1));
    known[i] = 2, label[i] = 1;
    face_pixels.push_back(i);
  }

  const int smoothing = std::max(1, int(std::lround(0.1f * frame.scale / float(step))));
  std::vector<float> belief(count);
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    const std::vector<float> person = colour_model(bins, label, 1), wall = colour_model(bins, label, 0);
    for (size_t i = 0; i < count; ++i) {
      const float p = prior[i] * person[bins[i]], w = (1 - prior[i]) * wall[bins[i]];
      belief[i] = p + w > 0 ? p / (p + w) : prior[i];
    }
    box_blur(belief, width, height, smoothing);
    box_blur(belief, width, height, smoothing);
    for (size_t i = 0; i < count; ++i) label[i] = known[i] == 2 || (known[i] == 1 && belief[i] > 0.5f) ? 1 : 0;
  }

  // A head is there unless the colours are sure it is not: hair as dark as the room behind it is
  // still hair, so the head's core (its likely place, a little drawn in) is the person where the
  // wall's colours do not clearly explain it (a bald head before a pale wall keeps its outline).
  for (size_t i = 0; i < count; ++i)
    if (head_core[i] && belief[i] > kSurelyWall) label[i] = 1;
  // One person: the part joined to the face, its holes filled (the wall is what the border reaches).
  const std::vector<uint8_t> person = reachable(label, width, height, 1, face_pixels);
  std::vector<size_t> border;
  for (int x = 0; x < width; ++x) border.push_back(size_t(x)), border.push_back(size_t(height - 1) * size_t(width) + size_t(x));
  for (int y = 0; y < height; ++y) border.push_back(size_t(y) * size_t(width)), border.push_back(size_t(y) * size_t(width) + size_t(width - 1));
  const std::vector<uint8_t> wall = reachable(person, width, height, 0, border);
  std::vector<float> cut(count);
  for (size_t i = 0; i < count; ++i) cut[i] = wall[i] ? 0.0f : 1.0f;
  box_blur(cut, width, height, 1);  // a soft edge of about a working pixel

  PersonMatte matte{photo.width, photo.height, std::vector<uint8_t>(size_t(photo.width) * size_t(photo.height))};
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x) {
      const float fx = std::clamp((float(x) + 0.5f) / float(step) - 0.5f, 0.0f, float(width - 1));
      const float fy = std::clamp((float(y) + 0.5f) / float(step) - 0.5f, 0.0f, float(height - 1));
      const int x0 = int(fx), y0 = int(fy), x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
      const float tx = fx - float(x0), ty = fy - float(y0);
      const auto c = [&](int cx, int cy) { return cut[size_t(cy) * size_t(width) + size_t(cx)]; };
      const float v = (c(x0, y0) * (1 - tx) + c(x1, y0) * tx) * (1 - ty) + (c(x0, y1) * (1 - tx) + c(x1, y1) * tx) * ty;
      matte.alpha[size_t(y) * size_t(photo.width) + size_t(x)] = uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    }
  return matte;
}

void lay_on_ground(Image& image, const PersonMatte& matte, glm::u8vec3 ground) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      uint8_t* p = image.at(x, y);
      const int a = matte.at(x, y);
      for (int c = 0; c < 3; ++c) p[c] = uint8_t((int(ground[c]) * (255 - a) + int(p[c]) * a + 127) / 255);
    }
}

}  // namespace inkwire
