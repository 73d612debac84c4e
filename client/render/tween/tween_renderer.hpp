#pragma once
// The super-realistic renderer (SPEC T2-T5): views synthesised from sample images by warping
// them along their control points. Samples come either from a mesh (rendered once in prepare(),
// in any style, on a ring or a geodesic sphere, with exact control points) or from outside
// (photos with tween data: use_model()). Methods:
//   nearest    the closest sample, unwarped (the baseline that jumps between views)
//   crossfade  the cell's samples blended by proximity, unwarped
//   linear     the closest sample warped to the view
//   bilinear   both samples of a ring pair warped to the view and blended
//   trilinear  the three samples of a sphere triangle warped to the view and blended
// (on a sphere, bilinear and trilinear both warp all three samples of the triangle).
// A view is drawn in one pass reading every contributing sample (the default), or as the study
// drew it: one pass per sample into an off-screen view, laid over the frame afterwards.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "client/render/renderer.hpp"
#include "client/render/tween/image_warper.hpp"
#include "common/image.hpp"
#include "common/topology.hpp"
#include "common/tween/tween_data.hpp"

namespace inkwire {

// Everything a view is synthesised from.
struct TweenModel {
  TweenData data;
  std::vector<Image> images;        // one per sample, data.width x data.height
  float distance_diagonals = 1.4f;  // how far the samples' camera stood (for zooming the view)
  float fov_y_degrees = 45.0f;      // the samples' vertical field of view
  Bounds bounds;                    // the object's box (its centre is what the samples looked at)
};

// Checks that images and data agree (count, sizes). Throws inkwire::Error naming the mismatch.
// With `partial`, images may be empty (not there yet) and cells may be missing.
void validate(const TweenModel& model, bool partial = false);

class TweenRenderer final : public Renderer {
 public:
  static std::vector<ParamSpec> params();
  void configure(const StyleParams& params) override;
  // Renders the sample set from the mesh (ring, or sphere for trilinear) and its tween data.
  void prepare(const SceneObject& object) override;
  // Uses samples from outside instead (photos + tween data); replaces any prepared mesh.
  void use_model(TweenModel model);
  // The same, arriving piece by piece (a product over the network, SPEC T12): `model` names the
  // samples' directions and size, its images may be empty and its cells few or none; the rest
  // comes through set_sample() and add_cell(). Until a view's cell and both its samples are
  // there, the nearest sample that is shows.
  void begin_model(TweenModel model);
  void set_sample(int index, const Image& image);
  void add_cell(TweenCell cell);
  int samples_loaded() const;
  // Zoom (SPEC T18): sample `index` at a finer level (larger, of the sample's shape, framed
  // alike; with its matte scaled up), drawn instead of the first level while use_finer() is on.
  // Throws inkwire::Error if the index or the shape is wrong.
  void set_finer_sample(int index, const Image& image);
  void drop_finer_sample(int index);
  void use_finer(bool use) { use_finer_ = use; }
  // How many of the last view's samples were drawn from a finer level.
  int finer_in_view() const;
  // The samples a view from `direction` (from the object toward the eye) is drawn from once they
  // are there: its cell's and the nearest sample.
  std::vector<int> view_samples(const glm::vec3& direction) const;
  const TweenModel& model() const { return model_; }
  void draw(const FrameState& frame) override;
  std::map<std::string, double> counters() const override;

  // The last view at the samples' resolution, upright, premultiplied RGBA (for measuring).
  Image last_view() const;

 private:
  // What a view is made of: the cell's mesh drawn at `positions`, read from `sources`; a single
  // sample drawn as it is says which.
  struct View {
    int mesh = -1;
    glm::vec3 positions{0.0f};
    std::vector<WarpSource> sources;
    int sample = -1;
  };
  // Sample `index` as a view reads it: its finer level while finer views are asked for.
  WarpSource source_of(int index, int position, float weight) const;
  void build_from_mesh();
  void upload();
  View plan(const FrameState& frame);
  View nearest_loaded(const glm::vec3& direction);
  void add_cell_mesh(const TweenCell& cell);
  std::string method_ = "bilinear", layout_ = "auto";
  bool one_pass_ = true;
  OverlapMode overlap_ = OverlapMode::Layered;
  int ring_samples_ = 24, sphere_level_ = 2, points_ = 65, sample_size_ = 256;
  std::string sample_style_ = "default";
  std::string built_for_;  // the sampling the current model was made with ("" = from outside)
  const SceneObject* object_ = nullptr;
  TweenModel model_;
  std::unique_ptr<ImageWarper> warper_;
  std::vector<std::unique_ptr<gl::Texture>> textures_;  // per sample; null until its image is there
  struct Finer {
    Image image;  // kept to make the texture again when the compose mode changes
    std::unique_ptr<gl::Texture> texture;
    float scale = 1.0f;
  };
  std::map<int, Finer> finer_;  // by sample
  bool use_finer_ = false;
  std::vector<int> meshes_;  // per cell
  int plain_mesh_ = -1;      // the border alone: a sample drawn as it is
  bool matte_ = true;
  View last_view_;
  int last_cell_ = -1, last_passes_ = 0;
};

}  // namespace inkwire
