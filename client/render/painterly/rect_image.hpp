#pragma once
// Draws an image over a capture rectangle, inside the object's matte: the brushes' base coat
// and the oil filter's output both go down this way, and a painting's glow without one.
#include "client/gl/resources.hpp"
#include "client/render/painterly/reference_capture.hpp"

namespace inkwire {

class RectImage {
 public:
  // How the matte clips: Hard, by its alpha (pixels under half covered are not drawn at all, so
  // a stencil write the caller sets up marks exactly the object); Soft, by a wash map's red
  // (wash_map.hpp: paint fading across the outline); None: no matte, the image premultiplied
  // and scaled by the opacity (a glow, for additive blending).
  enum class Clip { Hard = 0, Soft = 1, None = 2 };
  RectImage();
  // `image` and `matte` are stored top row first. With `premultiplied` the image's colour is
  // divided by its alpha (coarse base coats without dark fringes). Blending is the caller's.
  void draw(const gl::Texture& image, const gl::Texture& matte, PixelRect rect, bool premultiplied, float opacity,
            Clip clip = Clip::Hard) const;

 private:
  gl::Program program_;
  gl::VertexArray empty_vao_;
};

}  // namespace inkwire
