#pragma once
// Draws an image over a capture rectangle, inside the object's matte: the brushes' base coat
// and the oil filter's output both go down this way.
#include "client/gl/resources.hpp"
#include "client/render/painterly/reference_capture.hpp"

namespace inkwire {

class RectImage {
 public:
  RectImage();
  // `image` and `matte` are stored top row first; `matte`'s alpha clips: pixels under half
  // covered are not drawn at all, so a stencil write the caller sets up marks exactly the
  // object. With `premultiplied` the image's colour is divided by its alpha (coarse base coats
  // without dark fringes). Blending is the caller's.
  void draw(const gl::Texture& image, const gl::Texture& matte, PixelRect rect, bool premultiplied, float opacity) const;

 private:
  gl::Program program_;
  gl::VertexArray empty_vao_;
};

}  // namespace inkwire
