#include "client/render/painterly/brush_painter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/common.hpp>

#include "client/gl/gl.hpp"
#include "client/render/backdrop.hpp"
#include "client/render/painterly/brush_shapes.hpp"
#include "client/render/painterly/glow.hpp"
#include "client/render/painterly/wash_map.hpp"
#include "common/error.hpp"
#include "common/luminance.hpp"
#include "common/noise.hpp"

namespace inkwire {

using namespace gl;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr int kToothSize = 512;  // the paper's grain at one texel per pixel, as the paper backdrop lies

// The difference between two stroke angles, folded into (-pi/2, pi/2]: a stroke turned half a
// circle is the same stroke, so a brush never spins round to reach its new direction.
float stroke_angle_difference(float to, float from) {
  float d = std::fmod(to - from, kPi);
  if (d > kPi / 2) d -= kPi;
  if (d <= -kPi / 2) d += kPi;
  return d;
}

float luminance_at(const Image& image, int x, int y) {
  x = std::clamp(x, 0, image.width - 1), y = std::clamp(y, 0, image.height - 1);
  const uint8_t* p = image.at(x, y);
  return rec709_luminance<float>(p[0], p[1], p[2]) / 255.0f;
}

// The premultiplied mean colour of the object pixels in each cell of `cell` x `cell` pixels,
// in the palette's colours; alpha is the cell's object fraction. Drawn with linear filtering
// and divided by alpha in the shader, it is a blurred base coat without dark fringes.
Image coarse_base_coat(const Image& reference, int cell, const Palette& palette) {
  const int w = (reference.width + cell - 1) / cell, h = (reference.height + cell - 1) / cell;
  Image coarse(w, h);
  for (int cy = 0; cy < h; ++cy)
    for (int cx = 0; cx < w; ++cx) {
      glm::vec3 sum(0);
      int object = 0, all = 0;
      for (int y = cy * cell; y < std::min((cy + 1) * cell, reference.height); ++y)
        for (int x = cx * cell; x < std::min((cx + 1) * cell, reference.width); ++x, ++all) {
          const uint8_t* p = reference.at(x, y);
          if (p[3] < 128) continue;
          sum += glm::vec3(p[0], p[1], p[2]);
          ++object;
        }
      uint8_t* out = coarse.at(cx, cy);
      if (object == 0) continue;
      const float coverage = float(object) / float(all);
      const glm::vec3 paint = palette.apply(sum / (255.0f * float(object))) * coverage;
      for (int c = 0; c < 3; ++c) out[c] = uint8_t(std::clamp(paint[c], 0.0f, 1.0f) * 255.0f + 0.5f);
      out[3] = uint8_t(coverage * 255.0f + 0.5f);
    }
  return coarse;
}

}  // namespace

BrushPainter::BrushPainter()
    : shapes_(Texture::stack_from_images(make_brush_textures(), GL_TEXTURE_2D_ARRAY, {.repeat = false, .mipmaps = true, .linear = true})),
      matte_(Texture::from_image(Image(1, 1, {0, 0, 0, 255}), {.repeat = false, .mipmaps = false, .linear = true})),
      coarse_(Texture::from_image(Image(1, 1), {.repeat = false, .mipmaps = false, .linear = true})),
      medium_(Texture::from_image(Image(1, 1), {.repeat = false, .mipmaps = false, .linear = true})),
      glow_(Texture::from_image(Image(1, 1), {.repeat = false, .mipmaps = false, .linear = true})),
      instance_buffer_(Buffer::create(sizeof(Instance), nullptr, GL_STREAM_DRAW)),
      brush_vao_(VertexArray::create()) {
  constexpr GLsizei stride = sizeof(Instance);
  brush_vao_.attribute(0, instance_buffer_, 2, stride, offsetof(Instance, centre));
  brush_vao_.attribute(1, instance_buffer_, 2, stride, offsetof(Instance, half_size));
  brush_vao_.attribute(2, instance_buffer_, 1, stride, offsetof(Instance, angle));
  brush_vao_.attribute(3, instance_buffer_, 1, stride, offsetof(Instance, layer));
  brush_vao_.attribute(4, instance_buffer_, 4, stride, offsetof(Instance, colour), GL_UNSIGNED_BYTE, true);
  brush_vao_.bind();
  for (GLuint i = 0; i <= 4; ++i) glVertexAttribDivisor(i, 1);  // one brush per instance
  glBindVertexArray(0);
}

void BrushPainter::set_style(const PaintStyle& style, uint64_t seed) {
  style_ = style;
  seed_ = seed;
  field_ = std::make_unique<BrushField>(size_t(style.brushes), style.motion, seed, style.colour_frames);
  looks_.assign(size_t(style.brushes), Look{});
}

void BrushPainter::choose_look(size_t index, const Brush& brush) {
  Look& look = looks_[index];
  look.rule = -1;
  for (size_t r = 0; r < style_.regions.size(); ++r)
    if (style_.regions[r].matches(brush.colour)) {
      look.rule = int(r);
      break;
    }
  const std::vector<BrushShape>& shapes = look.rule >= 0 && !style_.regions[size_t(look.rule)].shapes.empty() ? style_.regions[size_t(look.rule)].shapes : style_.shapes;
  Random random(mix_seed(seed_, index, uint64_t(brush.position.x * 1e6f)));
  look.shape = shapes[random.next() % shapes.size()];
  look.flipped = random.next() & 1;
  look.jitter = {random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)};
}

float BrushPainter::target_angle(size_t index, const Brush& brush, const Image& reference, const StrokeOrientation& o) const {
  const float jitter = (float(mix_seed(seed_, index, 7) >> 40) / float(1u << 24) - 0.5f) * 2.0f * o.jitter_degrees * kPi / 180.0f;
  const float offset = o.angle_degrees * kPi / 180.0f + jitter;
  // Angles are in image space (x right, y down) here; the shader turns them onto the screen.
  auto by_position = [&] {
    static const TileableNoise field(8, 4049);
    return field.at(brush.position.x * 8.0f, brush.position.y * 8.0f) * 2.0f * kPi;
  };
  switch (o.kind) {
    case OrientationKind::Constant: return offset;
    case OrientationKind::Random: return by_position() + offset;
    case OrientationKind::Circular: return std::atan2(brush.position.y - 0.5f, brush.position.x - 0.5f) + kPi / 2 + offset;
    case OrientationKind::Gradient: {
      const int x = int(brush.position.x * float(reference.width)), y = int(brush.position.y * float(reference.height));
      const float gx = luminance_at(reference, x + 2, y) - luminance_at(reference, x - 2, y);
      const float gy = luminance_at(reference, x, y + 2) - luminance_at(reference, x, y - 2);
      // Along the contour, across the gradient; where the image is flat, any slant will do.
      if (gx * gx + gy * gy < 0.03f * 0.03f) return by_position() + offset;
      return std::atan2(gy, gx) + kPi / 2 + offset;
    }
  }
  return offset;
}

const Program& BrushPainter::brush_program(bool soft, bool glaze) {
  const bool wet = style_.wet_edges > 0.0f, grain = style_.granulation > 0.0f && tooth_;
  const int key = int(soft) | int(wet) << 1 | int(grain) << 2 | int(glaze) << 3;
  auto it = brush_programs_.find(key);
  if (it != brush_programs_.end()) return it->second;
  std::vector<std::string> defines;
  if (soft) defines.push_back("SOFT_EDGES 1");
  if (wet) defines.push_back("WET_EDGES 1");
  if (grain) defines.push_back("GRANULATION 1");
  if (glaze) defines.push_back("GLAZE 1");
  return brush_programs_.emplace(key, Program::from_files({"painterly/brush.vert", "painterly/brush.frag"}, defines)).first->second;
}

void BrushPainter::draw_underpaint(const Image& reference, PixelRect rect) {
  const int cell = std::max(4, std::min(rect.width, rect.height) / 24);
  coarse_.update(coarse_base_coat(reference, cell, style_.palette));
  const bool soft = style_.edge_softness > 0.0f;
  rect_image_.draw(coarse_, soft ? medium_ : matte_, rect, /*premultiplied=*/true, style_.underpaint,
                   soft ? RectImage::Clip::Soft : RectImage::Clip::Hard);
}

void BrushPainter::draw_glow(const Image& reference, PixelRect rect) {
  // At a quarter of the resolution, grown by the glow's reach so the light is not cut off at
  // the capture's edges.
  constexpr int kScale = 4;
  const int radius = std::max(kScale, int(std::lround(style_.glow_radius * float(std::max(rect.width, rect.height)))));
  const int margin = 2 * radius;
  const Image glow = glow_image(reference, style_.palette, radius, margin, kScale);
  glow_.update(glow);
  const PixelRect grown{rect.x - margin, rect.y - margin, glow.width * kScale, glow.height * kScale};
  // Light adds to what is there (the backdrop and the paint); alpha too, so a transparent
  // ground keeps the glow.
  glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  rect_image_.draw(glow_, glow_, grown, /*premultiplied=*/false, style_.glow, RectImage::Clip::None);
}

void BrushPainter::lay_matte(const Image& reference, PixelRect rect, bool underpaint) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(rect.x, rect.y, rect.width, rect.height);
  glStencilMask(0xff);
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  if (underpaint && style_.underpaint > 0.0f) {
    draw_underpaint(reference, rect);
  } else {
    // The stencil alone: the object, or with soft edges as far as paint fades beyond it (no
    // brush fragment further out is shaded).
    const bool soft = style_.edge_softness > 0.0f;
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    rect_image_.draw(soft ? medium_ : matte_, soft ? medium_ : matte_, rect, /*premultiplied=*/false, 1.0f,
                     soft ? RectImage::Clip::Soft : RectImage::Clip::Hard);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
}

void BrushPainter::paint(const Image& reference, PixelRect rect, bool underpaint, int settle, bool opaque_ground) {
  if (!field_) throw Error("BrushPainter::paint(): no style set");
  if (reference.empty() || rect.empty()) return;
  const Matte matte = Matte::from_alpha(reference);
  for (int i = 0; i < settle; ++i) field_->step(matte);
  field_->step(matte);
  field_->sample_colours(reference);
  matte_.update(reference);
  side_ = automatic_brush_side(matte, field_->last_step().visible, style_.coverage);
  const bool soft = style_.edge_softness > 0.0f, glaze = style_.glaze && opaque_ground;
  // The medium is needed for soft edges and for wet edges; its soft matte reaches as far as a
  // share of a brush beyond the outline.
  if (soft || style_.wet_edges > 0.0f) medium_.update(wash_mapper_.make(reference, std::max(1.0f, style_.edge_softness * side_), style_.wet_edges > 0.0f));
  if (style_.granulation > 0.0f && !tooth_)
    tooth_.emplace(Texture::from_image(paper_tooth(kToothSize), {.repeat = true, .mipmaps = false, .linear = false}));

  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  // The glow lights the ground around the object first; the paint then covers it where it lies,
  // so the strokes keep their own colours and the light spills out from behind them.
  if (style_.glow > 0.0f) draw_glow(reference, rect);
  // Alpha accumulates as "covered" so a transparent backdrop ends up opaque under paint.
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  lay_matte(reference, rect, underpaint);

  const glm::vec2 origin(rect.x, rect.y), size(rect.width, rect.height);
  std::vector<Brush>& brushes = field_->brushes();
  instances_.clear();
  for (size_t i = 0; i < brushes.size(); ++i) {
    Brush& b = brushes[i];
    if (!b.visible) continue;
    if (!b.styled) choose_look(i, b);
    const Look& look = looks_[i];
    const RegionRule* rule = look.rule >= 0 ? &style_.regions[size_t(look.rule)] : nullptr;
    const StrokeOrientation& orientation = rule && rule->orientation ? *rule->orientation : style_.orientation;
    const float target = target_angle(i, b, reference, orientation);
    b.angle = b.styled ? b.angle + 0.3f * stroke_angle_difference(target, b.angle) : target;  // turn, don't snap
    b.styled = true;
    const Palette& palette = rule && rule->palette ? *rule->palette : style_.palette;
    const float opacity = rule && rule->opacity ? *rule->opacity : style_.opacity;
    const float aspect = shape_aspect(look.shape, style_.aspect);
    const float side = side_ * (rule ? rule->size : 1.0f);
    const glm::vec3 paint = palette.apply(b.colour + look.jitter * style_.colour_jitter);
    Instance instance;
    // Image rows run down, GL rows up: flip y for the centre and the turning direction.
    instance.centre = origin + glm::vec2(b.position.x, 1.0f - b.position.y) * size;
    instance.half_size = 0.5f * glm::vec2(side * std::sqrt(aspect), side / std::sqrt(aspect) * (look.flipped ? -1.0f : 1.0f));
    instance.angle = -b.angle;
    instance.layer = float(look.shape);
    instance.colour = glm::u8vec4(glm::clamp(glm::vec4(paint, opacity), 0.0f, 1.0f) * 255.0f + 0.5f);
    instances_.push_back(instance);
  }
  if (!instances_.empty()) {
    instance_buffer_.upload(instances_.size() * sizeof(Instance), instances_.data());
    const Program& program = brush_program(soft, glaze);
    program.use();
    program.set("viewport", glm::vec4(viewport[0], viewport[1], viewport[2], viewport[3]));
    program.set("shapes", 0);
    program.set("medium", 1);
    program.set("tooth", 2);
    program.set("rect", glm::vec4(rect.x, rect.y, rect.width, rect.height));
    program.set("wet_edges", style_.wet_edges);
    program.set("granulation", tooth_ ? style_.granulation : 0.0f);
    program.set("tooth_size", glm::vec2(float(kToothSize), float(kToothSize)));
    shapes_.bind(0);
    medium_.bind(1);
    if (tooth_) tooth_->bind(2);
    // Glazing multiplies what is there by the pigment's transmittance; coverage still adds up.
    if (glaze) glBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    // The mipmap level trilinear filtering would pick (where the stroke's narrow side squeezes
    // the texture most), once for all brushes: a trilinear read per fragment cost about a fifth
    // of the brush pass under llvmpipe, for a picture that differs only in its finest streaks.
    const float across = side_ / std::sqrt(std::max(style_.aspect, 1.0f));
    shapes_.sample_level(int(std::floor(std::log2(float(kBrushTextureSize) / std::max(across, 1.0f)))));
    brush_vao_.bind();
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(instances_.size()));
  }
  glBindVertexArray(0);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ZERO);
}

}  // namespace inkwire
