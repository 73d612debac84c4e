#include "client/render/face/conference_view.hpp"

#include <algorithm>
#include <cmath>

#include "client/gl/gl.hpp"
#include "client/render/backdrop.hpp"
#include "client/render/face/comic_photo.hpp"
#include "common/face/landmarks_file.hpp"

namespace inkwire {

ConferenceView::ConferenceView(const std::filesystem::path& photo, const std::filesystem::path& landmarks)
    : face_(load_image(photo), load_landmarks(landmarks)) {}

void ConferenceView::set_expression(ExpressionState state) {
  if (state == face_.expression()) pending_.reset();
  else pending_ = state;
}

void ConferenceView::set_style(const std::string& renderer, const std::vector<std::string>& settings) {
  comic_ = renderer.rfind("comic", 0) == 0;
  if (renderer != "painterly") {
    painter_.reset();
    painting_.reset();
    return;
  }
  auto painter = make_video_painter(settings, face_.width(), face_.height());
  painter_ = std::move(painter);
  painting_.emplace(face_.width(), face_.height(), 1);
  painted_ = gl::Texture::from_image(Image(face_.width(), face_.height()));
  const FramebufferBinding restore;
  painting_->bind();
  Backdrop(BackdropSpec::parse("canvas")).draw();
}

void ConferenceView::draw(glm::ivec2 viewport, double time_seconds) {
  // The viewport may be a tile of a larger picture (a call's grid): the face goes inside it.
  glm::ivec4 origin;
  gl::glGetIntegerv(GL_VIEWPORT, &origin.x);
  if (pending_) {
    face_.set_expression(*pending_, time_seconds);
    pending_.reset();
  }
  face_.render(time_seconds);
  const float scale = std::min(float(viewport.x) / float(face_.width()), float(viewport.y) / float(face_.height()));
  const glm::ivec2 size(std::lround(float(face_.width()) * scale), std::lround(float(face_.height()) * scale));
  const glm::ivec4 rect(origin.x + (viewport.x - size.x) / 2, origin.y + (viewport.y - size.y) / 2, size.x, size.y);
  if (comic_) {
    Image face = face_.read();
    comic_photo(face);
    if (comic_face_.width() != face.width || comic_face_.height() != face.height) comic_face_ = gl::Texture::from_image(face);
    else comic_face_.update(face);
    gl::glDisable(GL_DEPTH_TEST);
    gl::glEnable(GL_BLEND);
    gl::glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    rect_image_.draw(comic_face_, comic_face_, {rect.x, rect.y, rect.z, rect.w}, false, 1.0f);
    gl::glDisable(GL_BLEND);
    gl::glEnable(GL_DEPTH_TEST);
    return;
  }
  if (!painter_) {
    face_.composite(glm::vec4(rect));
    return;
  }
  {
    const FramebufferBinding restore;  // painting and reading back bind the painting's canvas
    painting_->bind();
    painter_->paint(face_.read());
    // Through a texture: the bound framebuffer may be multisampled, which a blit cannot scale into.
    painted_.update(painting_->read());
  }
  gl::glDisable(GL_BLEND);
  gl::glDisable(GL_DEPTH_TEST);
  rect_image_.draw(painted_, painted_, {rect.x, rect.y, rect.z, rect.w}, false, 1.0f);
  gl::glEnable(GL_DEPTH_TEST);
}

}  // namespace inkwire
