#include "client/render/hatching/hatching_renderer.hpp"

#include <algorithm>
#include <cmath>

#include <glm/trigonometric.hpp>

#include "client/render/hatching/hatch_tones.hpp"
#include "common/error.hpp"

namespace inkwire {

using namespace gl;

HatchingRenderer::HatchingRenderer()
    : volume_program_(Program::from_files({"hatching/hatch.vert", "hatching/hatch.frag"}, {"VOLUME 1"})),
      layer_program_(Program::from_files({"hatching/hatch.vert", "hatching/hatch.frag"})) {}

std::vector<ParamSpec> HatchingRenderer::params() {
  return {
      choice_param("variant", "3d-texture", {"3d-texture", "multipass"}, "one pass over a 3D tone texture, or one pass per tone"),
      int_param("tones", "16", 2, 64, "3d-texture: tone layers along the depth axis"),
      int_param("passes", "4", 1, 32, "multipass: densities, one pass each"),
      float_param("angle", "0", -180, 180, "rotation of the hatching, degrees"),
      float_param("scale", "96", 8, 1024, "size of one hatch tile on screen, pixels"),
      float_param("lightness", "0.85", -1, 1, "N.L above which the surface stays paper-white"),
      float_param("strength", "0.9", 0, 1, "ink opacity"),
  };
}

void HatchingRenderer::configure(const StyleParams& p) {
  multipass_ = p.get_text("variant") == "multipass";
  const int tones = p.get_int("tones"), passes = p.get_int("passes");
  const float lightness = p.get_float("lightness");
  if (tones != tone_layers_ || passes != passes_wanted_ || lightness != lightness_) volume_.reset();  // rebuilt on the next draw
  tone_layers_ = tones;
  passes_wanted_ = passes;
  lightness_ = lightness;
  angle_ = glm::radians(p.get_float("angle"));
  scale_px_ = p.get_float("scale");
  strength_ = p.get_float("strength");
}

void HatchingRenderer::prepare(const SceneObject& object) {
  object_ = &object;
  mesh_ = std::make_unique<GpuMesh>(object);
}

void HatchingRenderer::build_textures() {
  // No mipmaps for the 3D texture: they would halve the tone axis too, averaging tones. The
  // multipass layers are a separate, coarser set (bare paper plus one layer per pass), made
  // from the same stroke list, so they nest the same way.
  const HatchTones tones = make_hatch_tones(tone_layers_);
  volume_ = std::make_unique<Texture>(Texture::stack_from_images(tones.layers, GL_TEXTURE_3D, {.repeat = true, .mipmaps = false, .linear = true}));
  const HatchTones densities = make_hatch_tones(passes_wanted_ + 1);
  layers_ = std::make_unique<Texture>(Texture::stack_from_images(densities.layers, GL_TEXTURE_2D_ARRAY, {.repeat = true, .mipmaps = true, .linear = true}));
  // Tone by N.L: paper above `lightness`, darkening to full tone facing away from the light.
  std::vector<glm::u8vec4> lookup(256);
  for (size_t i = 0; i < lookup.size(); ++i) {
    const float n_dot_l = -1.0f + 2.0f * float(i) / float(lookup.size() - 1);
    const float tone = std::clamp((lightness_ - n_dot_l) / (lightness_ + 1.0f), 0.0f, 1.0f);
    const uint8_t v = uint8_t(std::pow(tone, 0.8f) * 255.0f + 0.5f);
    lookup[i] = {v, v, v, 255};
  }
  tone_lookup_ = std::make_unique<Texture>(Texture::lookup_1d(lookup, true));
}

void HatchingRenderer::draw(const FrameState& frame) {
  if (!mesh_) throw Error("HatchingRenderer::draw(): prepare() was not called");
  if (!volume_) build_textures();
  const glm::mat4 mvp = frame.model_view_projection();
  hlr_.lay_depth(*mesh_, mvp);
  HiddenLineRemoval::begin_lines(/*translucent=*/true);  // only the visible surface is hatched
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  const float c = std::cos(angle_) / scale_px_, s = std::sin(angle_) / scale_px_;
  const glm::mat2 screen_to_tile(c, s, -s, c);
  const Program& program = multipass_ ? layer_program_ : volume_program_;
  program.use();
  program.set("model_view_projection", mvp);
  program.set("light_object", frame.light_in_object_space());
  program.set("screen_to_tile", screen_to_tile);
  program.set("strength", strength_);
  program.set("tone_lookup", 1);
  program.set("tones", 0);
  tone_lookup_->bind(1);
  mesh_->bind();
  if (multipass_) {
    layers_->bind(0);
    program.set("layer_count", float(passes_wanted_ + 1));
    for (int layer = 1; layer <= passes_wanted_; ++layer) {  // layer 0 is bare paper
      program.set("layer", float(layer));
      mesh_->draw_all();
    }
    passes_ = size_t(passes_wanted_);
  } else {
    volume_->bind(0);
    mesh_->draw_all();
    passes_ = 1;
  }
  HiddenLineRemoval::end_lines();
}

std::map<std::string, double> HatchingRenderer::counters() const { return {{"passes", double(passes_)}}; }

}  // namespace inkwire
