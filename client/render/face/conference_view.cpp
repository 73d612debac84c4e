#include "client/render/face/conference_view.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include "client/gl/gl.hpp"
#include "client/render/backdrop.hpp"
#include "client/render/face/comic_face.hpp"
#include "common/face/landmarks_file.hpp"

namespace inkwire {

ConferenceView::ConferenceView(const std::filesystem::path& photo, const std::filesystem::path& landmarks)
    : ConferenceView(load_image(photo), load_landmarks(landmarks)) {}

ConferenceView::ConferenceView(Image photo, const FaceLandmarks& landmarks) : photo_(std::move(photo)), landmarks_(landmarks) {
  face_.emplace(photo_, landmarks_);
}

void ConferenceView::set_face(const FaceState& state) {
  if (state == face_->face()) pending_.reset();
  else pending_ = state;
}

void ConferenceView::set_expression(ExpressionState state) {
  if (state == face_->expression()) pending_.reset();
  else pending_ = state;
}

void ConferenceView::set_style(const std::string& renderer, const std::vector<std::string>& settings) {
  const Look look = renderer.rfind("comic", 0) == 0 ? Look::Comic : renderer == "painterly" ? Look::Painted : Look::Photo;
  if (look != look_) {
    // The face is made again from the drawn photo (or the plain one), showing what it showed.
    Image source = photo_;
    if (look != Look::Photo && !matte_) matte_ = person_matte(photo_, landmarks_);
    const auto ground = [](glm::vec3 base) { return glm::u8vec3(glm::round(base * 255.0f)); };
    if (look == Look::Comic) comic_face(source, landmarks_, *matte_, ground(kPaperBase));
    if (look == Look::Painted) lay_on_ground(source, *matte_, ground(kCanvasBase));
    const FaceState shown = face_->face();
    const ExpressionState code = face_->expression();
    face_.emplace(source, landmarks_);
    face_->set_face(shown, 0);
    if (code != dominant_expression(shown.layers)) face_->set_expression(code, 0);
    look_ = look;
  }
  painted_frames_ = 0;
  if (renderer != "painterly") {
    painter_.reset();
    painting_.reset();
    return;
  }
  auto painter = make_video_painter(settings, face_->width(), face_->height());
  painter_ = std::move(painter);
  painting_.emplace(face_->width(), face_->height(), 1);
  painted_ = gl::Texture::from_image(Image(face_->width(), face_->height()));
  const FramebufferBinding restore;
  painting_->bind();
  Backdrop(BackdropSpec::parse("canvas")).draw();
}

void ConferenceView::draw(glm::ivec2 viewport, double time_seconds) {
  // The viewport may be a tile of a larger picture (a call's grid): the face goes inside it.
  glm::ivec4 origin;
  gl::glGetIntegerv(GL_VIEWPORT, &origin.x);
  if (pending_) {
    // A face shown for the first time shows the expression it joined at, not a tween from neutral
    // (a painted face would keep strokes of the tween).
    const double from = drawn_ ? time_seconds : time_seconds - 1.0;
    if (const auto* code = std::get_if<ExpressionState>(&*pending_)) face_->set_expression(*code, from);
    else face_->set_face(std::get<FaceState>(*pending_), from);
    pending_.reset();
  }
  drawn_ = true;
  face_->render(time_seconds);
  const float scale = std::min(float(viewport.x) / float(face_->width()), float(viewport.y) / float(face_->height()));
  const glm::ivec2 size(std::lround(float(face_->width()) * scale), std::lround(float(face_->height()) * scale));
  const glm::ivec4 rect(origin.x + (viewport.x - size.x) / 2, origin.y + (viewport.y - size.y) / 2, size.x, size.y);
  if (!painter_) {
    face_->composite(glm::vec4(rect));
    return;
  }
  {
    const FramebufferBinding restore;  // painting and reading back bind the painting's canvas
    painting_->bind();
    painter_->paint(face_->read());
    ++painted_frames_;
    // Through a texture: the bound framebuffer may be multisampled, which a blit cannot scale into.
    painted_.update(painting_->read());
  }
  gl::glDisable(GL_BLEND);
  gl::glDisable(GL_DEPTH_TEST);
  rect_image_.draw(painted_, painted_, {rect.x, rect.y, rect.z, rect.w}, false, 1.0f);
  gl::glEnable(GL_DEPTH_TEST);
}

}  // namespace inkwire
