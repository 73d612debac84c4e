// The GL layer: both backends from one binary, entry points from the current context, and
// read-backs that come out the right way up.
#include <gtest/gtest.h>

#include "client/gl/canvas.hpp"
#include "client/gl/gl.hpp"
#include "common/error.hpp"
#include "gl_test_support.hpp"
#include "../unit/test_data.hpp"

using namespace inkwire;
using namespace inkwire::gl;

namespace {

// Blue everywhere, red in the top-left quarter: any flip or mirror moves the red.
Image draw_asymmetric(int w, int h) {
  Canvas canvas(w, h);
  canvas.bind();
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, h / 2, w / 2, h - h / 2);  // GL's y runs upward: the top half starts at h/2
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  return canvas.read();
}

void expect_upright(const Image& img) {
  EXPECT_EQ(img.rgba(1, 1), glm::u8vec4(255, 0, 0, 255)) << "top-left should be red";
  EXPECT_EQ(img.rgba(img.width - 2, 1), glm::u8vec4(0, 0, 255, 255)) << "top-right should be blue";
  EXPECT_EQ(img.rgba(1, img.height - 2), glm::u8vec4(0, 0, 255, 255)) << "bottom-left should be blue";
}

}  // namespace

TEST(ContextGLTest, OsmesaGivesCoreProfile45) {
  Context& ctx = test::offscreen_context();
  EXPECT_EQ(ctx.backend(), "osmesa");
  EXPECT_NE(ctx.gl_version().find("4.5"), std::string::npos) << ctx.gl_version();
  // Wide lines need a context that is not forward-compatible: check the driver allows > 1.
  GLfloat range[2] = {0, 0};
  glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, range);
  EXPECT_GT(range[1], 4.0f);
}

TEST(ContextGLTest, SavedPngIsUpright) {
  test::offscreen_context();
  const Image img = draw_asymmetric(40, 30);
  expect_upright(img);
  const auto file = test::write_temp("upright.png", "");
  save_image(img, file);
  expect_upright(load_image(file));
}

TEST(ContextGLTest, MultisampledCanvasResolvesUpright) {
  test::offscreen_context();
  Canvas canvas(40, 30, 4);
  EXPECT_EQ(canvas.samples(), 4);
  expect_upright(draw_asymmetric(40, 30));
}

TEST(ContextGLTest, ShaderErrorsCarryTheDriverLog) {
  test::offscreen_context();
  try {
    Program::from_sources({{"broken.frag", "void main() { this is not glsl; }\n"}});
    FAIL() << "compiled a broken shader";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("Program::compile(): broken.frag: ", 0), 0u) << what;
    EXPECT_GT(what.size(), 40u) << "driver log missing: " << what;
  }
  EXPECT_THROW(Program::from_files({"no/such.vert"}), Error);
}

TEST(ContextGLTest, GlfwWindowInTheSameBinary) {
  if (!window_system_available()) GTEST_SKIP() << "no display (CI runs this under xvfb-run)";
  auto window = create_window_context(64, 48, "inkwire test", false);
  EXPECT_EQ(window->backend(), "glfw");
  EXPECT_NE(window->gl_version().find("4.5"), std::string::npos) << window->gl_version();
  expect_upright(draw_asymmetric(40, 30));
  {
    // A canvas shown in the window lands in its default framebuffer the right way up.
    Canvas canvas(64, 48);
    canvas.bind();
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 24, 32, 24);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    canvas.present_to_default(window->framebuffer_size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    const glm::ivec2 size = window->framebuffer_size();
    uint8_t top_left[4] = {}, bottom_right[4] = {};
    glReadPixels(1, size.y - 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, top_left);  // GL rows run upward
    glReadPixels(size.x - 2, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bottom_right);
    EXPECT_EQ(top_left[0], 255);
    EXPECT_EQ(bottom_right[2], 255);
    window->present();
  }
  // Switching back must reload entry points from OSMesa and keep drawing correctly.
  test::offscreen_context();
  expect_upright(draw_asymmetric(40, 30));
}

TEST(ContextGLTest, EglSurfacelessInTheSameBinary) {
  std::unique_ptr<Context> egl;
  try {
    egl = create_offscreen_context(64, 48, "egl");
  } catch (const Error& e) {
    GTEST_SKIP() << "EGL surfaceless unavailable here: " << e.what();
  }
  EXPECT_EQ(egl->backend(), "egl");
  EXPECT_NE(egl->gl_version().find("4.5"), std::string::npos) << egl->gl_version();
  expect_upright(draw_asymmetric(40, 30));
  egl.reset();
  test::offscreen_context();
  expect_upright(draw_asymmetric(40, 30));
}
