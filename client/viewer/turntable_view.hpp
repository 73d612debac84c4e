#pragma once
// A turntable session drawn from its product (SPEC T11-T13): sample photos warped along the
// product's tween data into every view in between. The photos arrive one at a time, nearest the
// visitor's view first; the tween cells come with the snapshot. The visitor's view is their
// own: turning it sends nothing. Needs a current GL context.
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "client/render/tween/tween_renderer.hpp"
#include "client/viewer/photo_fetch.hpp"
#include "common/image.hpp"
#include "protocol/messages.hpp"

namespace inkwire {

// A visitor's view of a product: azimuth from the first sample's direction (turning as the
// samples do), elevation, and zoom (1: the photos' own scale).
struct TurntableOrbit {
  // How far a visitor zooms, in the window, the element (client/web/common/turntable_pose.js,
  // pinned by tests/golden/warp-vectors.json) and shared poses alike: from half the photos' own
  // scale (the whole product with room round it) to four times (a 2048-pixel level's detail).
  static constexpr float kMinZoom = 0.5f, kMaxZoom = 4.0f;
  float azimuth = 0.0f, elevation = 0.0f, zoom = 1.0f;
  glm::vec3 direction() const;
  // The view from unit direction `d` (the inverse of direction()), at zoom 1.
  static TurntableOrbit from_direction(const glm::vec3& d);
  bool operator==(const TurntableOrbit&) const = default;

  // Presenter mode (SPEC T13): this view shared with the session as the pose that turns the
  // product (without roll) so that the first sample's direction sees it as this view does, the
  // zoom as its scale; and a shared pose back as a view.
  protocol::ObjectPose pose(uint32_t sequence) const;
  static TurntableOrbit from_pose(const protocol::ObjectPose& pose);
};

class TurntableView {
 public:
  // Starts on the product a snapshot describes. Throws inkwire::Error if it is malformed.
  TurntableView(const protocol::Snapshot& state);

  using PhotoFetch = inkwire::PhotoFetch;
  // What to fetch next for `orbit`'s view on the display last drawn (or set_display()): the
  // first level of the photos the view is drawn from, then their finer level when the view shows
  // them larger than the first (wanted_level()), then the other photos' first level, nearest
  // first; nothing when all of that is there.
  std::optional<PhotoFetch> next_fetch(const TurntableOrbit& orbit) const;
  // The level `orbit`'s view needs on the display (photo_fetch.hpp wanted_level()).
  int wanted_level(const TurntableOrbit& orbit) const;
  void set_display(glm::ivec2 viewport) { display_ = viewport; }
  // A sample photo made ready to draw, with its matte when the product has them (empty path if
  // not; a finer level's photo takes its first-level matte scaled up). Touches no GL, so it runs
  // where the photo was fetched, off the render thread. Throws inkwire::Error naming the file if
  // it cannot be used.
  static Image sample_image(const std::filesystem::path& photo, const std::filesystem::path& matte);
  // Sample `index` at `level` (an image from sample_image(), of that level's size) is there. At
  // most kFinerKept samples keep a finer level (photo_fetch.hpp finer_to_drop()).
  void add_sample(int index, const Image& image, int level = 0);
  int finer_loaded() const { return int(finer_level_.size()); }
  int finer_in_view() const { return renderer_.finer_in_view(); }  // of the last view's photos
  // Cells of tween data not seen before are decoded and added; a malformed one is refused
  // (error() says why) and the views it would serve show the nearest photo.
  void add_cells(const std::map<uint16_t, protocol::Bytes>& cells);
  // Applies the session's tween settings (method, compose); keeps the previous on a bad one.
  void set_style(const std::vector<std::string>& settings);

  void draw(glm::ivec2 viewport, const TurntableOrbit& orbit);

  int samples() const { return int(product_.directions.size()); }
  int samples_loaded() const { return loaded_; }
  int cells() const { return product_.cells; }
  int cells_loaded() const { return int(cells_seen_.size()); }
  bool complete() const { return loaded_ == samples() && cells_loaded() == cells(); }
  // The lowest and highest elevation of the samples (degrees): one ring's alone, a few rows'
  // (SPEC T17), or nearly -90..90 on a geodesic sphere. Views are kept between them: outside,
  // nothing is there to synthesise from.
  glm::vec2 elevation_range() const;
  // The elevation of the nearest row of samples above (`rows` > 0) or below `elevation`, `rows`
  // rows on; the range's end when there are no more.
  float row_elevation(float elevation, int rows) const;
  // The sample whose direction is nearest `orbit`'s, for stepping one sample at a time.
  int nearest_sample(const TurntableOrbit& orbit) const;
  // The azimuth and elevation of sample `index`, in TurntableOrbit's terms.
  glm::vec2 sample_angles(int index) const;
  const std::string& error() const { return error_; }
  std::map<std::string, double> counters() const { return renderer_.counters(); }

 private:
  protocol::Product product_;
  TweenRenderer renderer_;
  std::vector<bool> has_;
  std::map<int, int> finer_level_;  // samples holding a finer level: which
  glm::ivec2 display_{0};
  std::map<uint16_t, bool> cells_seen_;
  int loaded_ = 0;
  std::string error_;
  std::vector<float> row_heights_;  // the samples' distinct elevations, lowest first
};

}  // namespace inkwire
