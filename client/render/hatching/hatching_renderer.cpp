#include "client/render/hatching/hatching_renderer.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include "client/render/backdrop.hpp"
#include "client/render/hatching/hatch_tones.hpp"
#include "client/render/styles.hpp"
#include "common/error.hpp"

namespace inkwire {

using namespace gl;

namespace {

constexpr glm::vec3 kGraphite(40.0f / 255.0f, 40.0f / 255.0f, 46.0f / 255.0f);  // as the tone layers are inked
constexpr int kThresholdLayers = 64;     // layers folded into the threshold image: finer tone steps
constexpr int kMaxThresholdSize = 256;  // larger tiles magnify it (64 layers of it are drawn to fold)
constexpr float kToneGamma = 0.8f;      // tones darken a little faster than N.L falls

}  // namespace

// The shade lookup (S7): the light tone above N.L = `lightness` (a few strokes, so the lit
// surface keeps its extent on the paper), darkening to full tone facing away from the light...
float ShadeLookup::tone_at(float n_dot_l) const {
  return light_tone + (1.0f - light_tone) * std::pow(std::clamp((lightness - n_dot_l) / (lightness + 1.0f), 0.0f, 1.0f), kToneGamma);
}

// ...and back: the N.L below which the surface reaches `tone` (every N.L for the light tone).
float ShadeLookup::n_dot_l_at(float tone) const {
  if (tone <= light_tone) return 1.0f;
  return lightness - (lightness + 1.0f) * std::pow((tone - light_tone) / (1.0f - light_tone), 1.0f / kToneGamma);
}

namespace {

// The threshold image with its tones turned into N.L through the lookup's inverse, so the
// shader compares N.L directly and reads no lookup: the same function, folded in once.
Image in_n_dot_l(Image thresholds, const ShadeLookup& shade) {
  for (size_t i = 0; i < thresholds.pixels.size(); i += 4)
    for (size_t c : {size_t(0), size_t(2)}) {
      const float n_dot_l = shade.n_dot_l_at(float(thresholds.pixels[i + c]) / 255.0f);
      thresholds.pixels[i + c] = uint8_t(std::clamp((n_dot_l + 1.0f) / 2.0f, 0.0f, 1.0f) * 255.0f + 0.5f);
    }
  return thresholds;
}

}  // namespace

std::vector<ParamSpec> HatchingRenderer::params() {
  return {
      choice_param("variant", "threshold", {"threshold", "3d-texture", "multipass"},
                   "one pass over a threshold image, one pass over a 3D tone texture, or one pass per tone"),
      int_param("tones", "16", 2, 64, "threshold and 3d-texture: tone steps a stroke fades in over (3D texture layers)"),
      int_param("passes", "4", 1, 32, "multipass: densities, one pass each"),
      float_param("angle", "0", -180, 180, "rotation of the hatching, degrees"),
      float_param("scale", "96", 8, 1024, "size of one hatch tile on screen, pixels"),
      float_param("lightness", "0.85", -1, 1, "N.L above which the surface has only the light tone"),
      float_param("light_tone", "0.15", 0, 0.5, "the tone of the lit surface: a few strokes that keep its extent (0: bare paper)"),
      float_param("cross_below", "0.3", -1, 1, "N.L below which a second stroke direction crosses the first"),
      choice_param("outline", "sketch-pencil", outline_styles(), "the lines around the hatching: a sketcher's strokes, exact lines, or none"),
      float_param("strength", "0.9", 0, 1, "ink opacity"),
  };
}

std::vector<std::string> HatchingRenderer::outline_styles() { return {"sketch-pencil", "sketch-charcoal", "hidden-line", "none"}; }

void HatchingRenderer::configure(const StyleParams& p) {
  const std::string variant = p.get_text("variant");
  const int tones = p.get_int("tones"), passes = p.get_int("passes");
  const ShadeLookup shade{p.get_float("lightness"), p.get_float("light_tone")};
  const float cross_below = p.get_float("cross_below");
  if (variant != variant_ || tones != tone_layers_ || passes != passes_wanted_ || shade.lightness != shade_.lightness ||
      shade.light_tone != shade_.light_tone || cross_below != cross_below_)
    tones_.reset();  // rebuilt on the next draw
  variant_ = variant;
  tone_layers_ = tones;
  passes_wanted_ = passes;
  shade_ = shade;
  cross_below_ = cross_below;
  const std::string outline = p.get_text("outline");
  if (outline != outline_name_) {
    outline_ = outline == "none" ? nullptr : make_renderer(outline);
    outline_name_ = outline;
    if (outline_ && object_) outline_->prepare(*object_);
  }
  angle_ = glm::radians(p.get_float("angle"));
  const int size = threshold_size();
  scale_px_ = p.get_float("scale");
  if (variant_ == "threshold" && threshold_size() != size) tones_.reset();  // drawn at the tile's size
  // A new angle only changes how the threshold image is read, not the image.
  if (tones_ && variant_ == "threshold") tones_->set_filter(!pixel_exact());
  strength_ = p.get_float("strength");
}

void HatchingRenderer::prepare(const SceneObject& object) {
  object_ = &object;
  mesh_ = std::make_unique<GpuMesh>(object);
  if (outline_) outline_->prepare(object);
}

int HatchingRenderer::threshold_size() const { return std::clamp(int(std::lround(scale_px_)), 16, kMaxThresholdSize); }

bool HatchingRenderer::pixel_exact() const {
  const float quarter_turns = angle_ / glm::half_pi<float>();
  return float(threshold_size()) == scale_px_ && std::abs(quarter_turns - std::round(quarter_turns)) < 1e-5f;
}

void HatchingRenderer::build_textures() {
  // No mipmaps for the 3D texture and the thresholds: they would average tones. The multipass
  // layers are a separate, coarser set (bare paper plus one layer per pass), made from the same
  // stroke list, so they nest the same way.
  // Strokes cross where the surface is darker than the tone at N.L = cross_below.
  const float cross_tone = shade_.tone_at(cross_below_);
  if (variant_ == "threshold") {
    // Drawn at the tile's size on screen. Unturned (or turned by quarter turns) at that size, a
    // texel is a pixel: the nearest texel is what filtering would give, for a quarter of the reads.
    tones_ = std::make_unique<Texture>(
        Texture::from_image(in_n_dot_l(tone_thresholds(make_hatch_tones(kThresholdLayers, threshold_size(), 3, cross_tone)), shade_),
                            {.repeat = true, .mipmaps = false, .linear = !pixel_exact()}));
  } else if (variant_ == "3d-texture") {
    tones_ = std::make_unique<Texture>(
        Texture::stack_from_images(make_hatch_tones(tone_layers_, 128, 3, cross_tone).layers, GL_TEXTURE_3D, {.repeat = true, .mipmaps = false, .linear = true}));
  } else {
    tones_ = std::make_unique<Texture>(Texture::stack_from_images(make_hatch_tones(passes_wanted_ + 1, 128, 3, cross_tone).layers, GL_TEXTURE_2D_ARRAY,
                                                                  {.repeat = true, .mipmaps = true, .linear = true}));
  }
  if (variant_ == "threshold") return;  // the lookup is folded into the thresholds
  std::vector<glm::u8vec4> lookup(256);
  for (size_t i = 0; i < lookup.size(); ++i) {
    const uint8_t v = uint8_t(shade_.tone_at(-1.0f + 2.0f * float(i) / float(lookup.size() - 1)) * 255.0f + 0.5f);
    lookup[i] = {v, v, v, 255};
  }
  tone_lookup_ = std::make_unique<Texture>(Texture::lookup_row(lookup, true));
}

const Program& HatchingRenderer::program(const std::string& under_define) {
  const std::string key = variant_ + "/" + under_define;
  auto it = programs_.find(key);
  if (it != programs_.end()) return it->second;
  std::vector<std::string> defines;
  if (variant_ == "threshold") defines.push_back("THRESHOLD 1");
  if (variant_ == "3d-texture") defines.push_back("VOLUME 1");
  if (!under_define.empty()) defines.push_back(under_define + " 1");
  return programs_.emplace(key, Program::from_files({"hatching/hatch.vert", "hatching/hatch.frag"}, defines)).first->second;
}

void HatchingRenderer::draw(const FrameState& frame) {
  if (!mesh_) throw Error("HatchingRenderer::draw(): prepare() was not called");
  if (!tones_) build_textures();
  const glm::mat4 mvp = frame.model_view_projection();
  const bool multipass = variant_ == "multipass";
  opaque_ = frame.backdrop && !multipass;
  const Program& p = program(opaque_ ? frame.backdrop->under_define() : "");
  if (opaque_) {
    // The nearest surface wins by depth like any opaque one; its pixels carry the backdrop.
    // Its depth is laid as hidden-line removal lays it, so outlines drawn over it (hatching +
    // a sketcher) meet the same surface they would after a separate depth pass.
    HiddenLineRemoval::begin_surface_depth();
    glDisable(GL_BLEND);
  } else {
    hlr_.lay_depth(*mesh_, frame);
    HiddenLineRemoval::begin_lines();  // only the visible surface is hatched
  }
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glm::vec2 turn(std::cos(angle_), std::sin(angle_));
  if (pixel_exact()) turn = glm::round(turn);  // quarter turns exactly, or texels drift off pixels
  const float c = turn.x / scale_px_, s = turn.y / scale_px_;
  p.use();
  p.set("model_view_projection", mvp);
  p.set("light_object", frame.light_in_object_space());
  p.set("screen_to_tile", glm::mat2(c, s, -s, c));
  p.set("strength", strength_);
  p.set("tones", 0);
  tones_->bind(0);
  if (variant_ != "threshold") {  // the threshold variant has the lookup folded into its image
    p.set("tone_lookup", 1);
    tone_lookup_->bind(1);
  }
  if (opaque_) frame.backdrop->set_under(p, 2);
  mesh_->bind();
  if (multipass) {
    p.set("layer_count", float(passes_wanted_ + 1));
    for (int layer = 1; layer <= passes_wanted_; ++layer) {  // layer 0 is bare paper
      p.set("layer", float(layer));
      mesh_->draw_all();
    }
    passes_ = size_t(passes_wanted_);
  } else {
    if (variant_ == "threshold") {
      // A stroke fades in over 1/tones of the tone range: about that share of N.L's range.
      const float softness = (shade_.lightness + 1.0f) / float(tone_layers_);
      p.set("threshold_scale", 2.0f / softness);
      p.set("ink_colour", kGraphite);
    }
    mesh_->draw_all();
    passes_ = 1;
  }
  if (opaque_) {
    HiddenLineRemoval::end_surface_depth();
  } else {
    HiddenLineRemoval::end_lines();
  }
  if (!outline_) return;
  // Over the opaque surface, whose depth was laid as the outline's own pass would lay it.
  FrameState over = frame;
  over.depth_laid = over.depth_laid || left_line_depth();
  outline_->draw(over);
}

std::map<std::string, double> HatchingRenderer::counters() const {
  // Geometry passes: the depth pass counts when the ink is blended.
  std::map<std::string, double> figures = {{"passes", double(passes_)}, {"geometry_passes", double(passes_ + (opaque_ ? 0 : 1))}};
  if (outline_) figures.merge(outline_->counters());  // the outline's own (edges drawn), hatching's kept
  return figures;
}

}  // namespace inkwire
