// The OSMesa backend. This is the only file that includes Mesa's headers (they declare the
// global gl* prototypes that inkwire::gl deliberately shadows).
#include <GL/osmesa.h>

#include <vector>

#include "client/gl/context.hpp"
#include "client/gl/loader.hpp"
#include "common/error.hpp"

namespace inkwire {
namespace {

void* osmesa_proc(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }

class OsmesaContext final : public Context {
 public:
  OsmesaContext(int width, int height) : width_(width), height_(height), buffer_(size_t(width) * height * 4) {
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_STENCIL_BITS,
                           8,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           4,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           5,
                           0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!context_) throw Error("OSMesa could not create a GL 4.5 core context");
    make_current();
  }
  ~OsmesaContext() override { OSMesaDestroyContext(context_); }

  void make_current() override {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
      throw Error("OSMesa could not make its context current");
    gl::load_functions(osmesa_proc);
  }
  std::string backend() const override { return "osmesa"; }
  glm::ivec2 framebuffer_size() const override { return {width_, height_}; }

 private:
  int width_, height_;
  std::vector<unsigned char> buffer_;
  OSMesaContext context_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> create_osmesa_context(int width, int height) { return std::make_unique<OsmesaContext>(width, height); }

}  // namespace inkwire
