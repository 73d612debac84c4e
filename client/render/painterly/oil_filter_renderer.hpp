#pragma once
// "oil-filter" (SPEC P2): the convolution baseline. The reference capture is filtered on the
// CPU (oil_filter.hpp) and laid back inside the object's matte.
#include <memory>
#include <string>

#include "client/render/painterly/rect_image.hpp"
#include "client/render/painterly/reference_capture.hpp"
#include "client/render/renderer.hpp"

namespace inkwire {

class OilFilterRenderer final : public Renderer {
 public:
  OilFilterRenderer();
  static std::vector<ParamSpec> params();
  void configure(const StyleParams& params) override;
  void prepare(const SceneObject& object) override;
  void draw(const FrameState& frame) override;
  std::map<std::string, double> counters() const override;

 private:
  ReferenceCapture capture_;
  RectImage rect_image_;
  gl::Texture filtered_, matte_;
  int radius_ = 5, levels_ = 20;
};

}  // namespace inkwire
