#include "client/render/painterly/rect_image.hpp"

#include "client/gl/gl.hpp"

namespace inkwire {

using namespace gl;

RectImage::RectImage() : program_(Program::from_files({"painterly/rect.vert", "painterly/rect.frag"})), empty_vao_(VertexArray::create()) {}

void RectImage::draw(const Texture& image, const Texture& matte, PixelRect rect, bool premultiplied, float opacity, Clip clip) const {
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  program_.use();
  program_.set("viewport", glm::vec4(viewport[0], viewport[1], viewport[2], viewport[3]));
  program_.set("rect", glm::vec4(rect.x, rect.y, rect.width, rect.height));
  program_.set("image", 0);
  program_.set("matte", 1);
  program_.set("premultiplied", int(premultiplied));
  program_.set("clip", int(clip));
  program_.set("opacity", opacity);
  image.bind(0);
  matte.bind(1);
  empty_vao_.bind();
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glBindVertexArray(0);
}

}  // namespace inkwire
