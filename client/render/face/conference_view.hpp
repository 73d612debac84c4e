#pragma once
// A face drawn from expression codes alone (SPEC F5, F11, F16): a neutral photo and its
// landmarks deformed to each expression, tweened, and fitted into the viewport: the speaker of a
// conference session, a member's tile of a call (client/call/call_grid.hpp), natively and in the
// browser's module alike. The drawn styles cut the person from the photo's wall once
// (common/face/person_matte.hpp) and lay it on their ground: "painterly" (with its settings) on
// the canvas, painting the person with brushes, each frame over the last so strokes persist; a
// comic style ("comic", "comic-extended") on the paper, drawn as a cartoonist draws a face
// (render/face/comic_face.hpp) once, the face then moving with its ink. Any other style shows
// the photo as it came, wall and all.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "client/gl/canvas.hpp"
#include "client/render/face/face_reconstructor.hpp"
#include "client/render/painterly/rect_image.hpp"
#include "client/render/painterly/video_painter.hpp"
#include "common/face/person_matte.hpp"

namespace inkwire {

class ConferenceView {
 public:
  // Throws inkwire::Error when the photo or the landmarks are unreadable or do not fit together.
  ConferenceView(const std::filesystem::path& photo, const std::filesystem::path& landmarks);
  // The same from a photo and landmarks in memory (throws as FaceReconstructor does).
  ConferenceView(Image photo, const FaceLandmarks& landmarks);

  // The tween to `state` starts at the next drawn frame: a face's layers and pose, or one code
  // (a session-wide speaker's; the head keeps its pose).
  void set_face(const FaceState& state);
  void set_expression(ExpressionState state);
  // Throws inkwire::Error for painterly settings the painter does not take (the previous look
  // is kept).
  void set_style(const std::string& renderer, const std::vector<std::string>& settings);
  // Into the bound framebuffer's current viewport (`viewport` its size), centred, as large as fits.
  void draw(glm::ivec2 viewport, double time_seconds);

  ExpressionState expression() const { return face_->expression(); }
  const FaceState& face() const { return face_->face(); }
  // Whether the picture changes by itself, frame after frame (a painterly face's brushes move).
  bool animates() const { return painter_ != nullptr; }
  // Frames painted since the painterly style was set (0 in other styles): the painting after as
  // many frames is the same wherever it is drawn (the brushes' moves come from the style's seed).
  int painted_frames() const { return painted_frames_; }

 private:
  Image photo_;  // as it came: a comic style draws from a copy
  FaceLandmarks landmarks_;
  std::optional<FaceReconstructor> face_;
  std::optional<std::variant<ExpressionState, FaceState>> pending_;
  std::unique_ptr<VideoPainter> painter_;  // painterly style only
  int painted_frames_ = 0;
  bool drawn_ = false;
  enum class Look { Photo, Comic, Painted };
  Look look_ = Look::Photo;
  std::optional<PersonMatte> matte_;       // found when a drawn style first needs it
  std::optional<Canvas> painting_;         // what the painter paints over, frame after frame
  gl::Texture painted_;                    // its latest frame, to lay into the viewport
  RectImage rect_image_;
};

}  // namespace inkwire
