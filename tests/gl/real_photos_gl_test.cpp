// Products made from photos as a shop makes them (SPEC T15, T19), with the photos rendered so the
// truth is known: a textured mesh rendered over white at known azimuths, saved as JPEGs, made
// into a product by add-product's code. Midway views move detail instead of fading it: the tween
// beats the cross-fade of the same photos by a stated margin.
#include <cmath>
#include <cstdio>

#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "client/render/styles.hpp"
#include "client/render/tween/mesh_samples.hpp"
#include "client/render/tween/tween_renderer.hpp"
#include "common/image_metrics.hpp"
#include "gl_test_support.hpp"
#include "server/products/product.hpp"
#include "../unit/test_data.hpp"

using namespace inkwire;
namespace fs = std::filesystem;

namespace {

const fs::path kTruck = "/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf";

glm::vec3 direction_at(float azimuth_degrees) {
  const float a = glm::radians(azimuth_degrees);
  return {std::sin(a), 0.0f, std::cos(a)};
}

// The object photographed over white at each azimuth, as JPEGs named in turning order.
fs::path photograph(const SceneObject& object, const std::vector<float>& azimuths, int size, const std::string& name) {
  const fs::path folder = test::scratch_dir() / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  for (size_t i = 0; i < azimuths.size(); ++i) {
    const Image photo = over_colour(render_mesh_view(object, direction_at(azimuths[i]), size, 1.4f), {255, 255, 255}, false);
    char file[32];
    std::snprintf(file, sizeof file, "photo_%02zu.jpg", i);
    save_image(photo, folder / file, false);
  }
  return folder;
}

}  // namespace

TEST(RealPhotosGLTest, MidwayViewsOfAPhotographedProductMoveDetailInsteadOfFadingIt) {
  test::offscreen_context();
  INKWIRE_REQUIRE_FILE(kTruck);
  const SceneObject truck = load_scene_object(kTruck);
  const int size = 256, kept = 12;
  std::vector<float> azimuths;
  for (int i = 0; i < kept; ++i) azimuths.push_back(float(i) * 360.0f / float(kept));
  PhotoProductOptions options;
  options.step_degrees = 360.0f / float(kept);  // evenly spaced: this test is about the warp
  const Product product = product_from_photos(photograph(truck, azimuths, size, "photos"), options);
  ASSERT_TRUE(product.matted);
  TweenModel model;
  model.data = product.data;
  model.images = product.images;
  const float half = kSceneDiagonal / (2.0f * std::sqrt(3.0f));
  model.bounds = {.min = glm::vec3(-half), .max = glm::vec3(half)};
  model.distance_diagonals = product.distance_diagonals;
  TweenRenderer renderer;
  renderer.use_model(model);
  Canvas canvas(size, size);
  double fade_sum = 0, tween_sum = 0;
  std::vector<Image> panels;
  for (int i = 0; i < kept; ++i) {
    const float az = (float(i) + 0.5f) * 360.0f / float(kept);
    const Image truth = over_colour(render_mesh_view(truck, direction_at(az), size, 1.4f), {255, 255, 255}, false);
    FrameState frame;
    frame.viewport = {size, size};
    frame.camera.position = direction_at(az) * model.distance_diagonals * kSceneDiagonal;
    frame.camera.target = glm::vec3(0.0f);
    double scores[2];
    const char* methods[2] = {"crossfade", "bilinear"};
    for (int m = 0; m < 2; ++m) {
      renderer.configure(style_params("tween", {std::string("method=") + methods[m], m == 0 ? "compose=sum" : "compose=matte"}).front());
      canvas.bind();
      renderer.draw(frame);
      const Image view = over_colour(renderer.last_view(), {255, 255, 255}, true);
      scores[m] = psnr(view, truth);
      if (i == 2) panels.push_back(view);
    }
    if (i == 2) panels.insert(panels.begin(), truth);
    std::printf("azimuth %5.1f: cross-fade %.2f dB, tween %.2f dB\n", az, scores[0], scores[1]);
    fade_sum += scores[0], tween_sum += scores[1];
  }
  save_image(side_by_side(panels, {"truth", "cross-fade", "tween"}), fs::path(INKWIRE_TEST_OUTPUT_DIR) / "real-photos-midway.png", false);
  const double fade = fade_sum / kept, tween = tween_sum / kept;
  std::printf("mean over %d midway views 30 degrees from their photos: cross-fade %.2f dB, tween %.2f dB\n", kept, fade, tween);
  // Measured 2026-11-26: cross-fade 17.7 dB, tween 19.4 dB (+1.6); with the sparse NCC landmarks
  // products had before, +1.2, which this margin refuses. (Every step here is deterministic: the
  // same JPEGs, the same flow, llvmpipe's same pixels.)
  EXPECT_GT(tween, fade + 1.4);
}
