// Products as a turntable shows them (SPEC T11-T14), rendered headless: views midway between
// mesh-rendered samples show one outline where the truth has it (matte IoU), not a ghost of
// both samples' edges; a product arriving piece by piece shows the nearest photo it has until a
// view's cell and both its photos are there.
#include <cstdio>

#include <gtest/gtest.h>

#include "client/render/tween/mesh_samples.hpp"
#include "client/render/tween/tween_renderer.hpp"
#include "common/image_metrics.hpp"
#include "common/tween/view_sphere.hpp"
#include "gl_test_support.hpp"
#include "../unit/test_data.hpp"

using namespace inkwire;

namespace {

// `object` made into a product as the benchmark makes one (24 samples on a ring) at `size` pixels.
void prepare_product(TweenRenderer& tween, const SceneObject& object, int size) {
  StyleParams params(TweenRenderer::params());
  params.set("sample_size", std::to_string(size));
  tween.configure(params);
  tween.prepare(object);
}

Image midway_view(TweenRenderer& tween, const std::string& compose, const FrameState& frame, Canvas& canvas) {
  StyleParams params(TweenRenderer::params());
  params.set("compose", compose);
  tween.configure(params);
  canvas.bind();
  tween.draw(frame);
  return tween.last_view();
}

}  // namespace

TEST(TurntableGLTest, MidwayViewsOfAMeshProductShowOneOutline) {
  test::offscreen_context();
  // The textured duck of assimp-testmodels, a product-like object. (The truck's hardest views,
  // near head-on, have a test of their own below.)
  const std::filesystem::path duck_file = "/usr/share/assimp/models/Collada/duck.dae";
  INKWIRE_REQUIRE_FILE(duck_file);
  const SceneObject duck = load_scene_object(duck_file);
  const int size = 256;
  Canvas canvas(size, size);
  TweenRenderer tween;
  prepare_product(tween, duck, size);
  double iou_min[2] = {1.0, 1.0}, ghost_max[2] = {0.0, 0.0}, psnr_sum[2] = {0.0, 0.0};
  int views = 0;
  const char* composes[2] = {"matte", "sum"};
  for (float az = 7.5f; az < 360.0f; az += 45.0f) {
    const FrameState frame = test::view_of(duck, canvas, az, 0.0f, 1.4f);
    const Image truth = render_mesh_view(duck, frame.camera.position - duck.topology.bounds.centre(), size, 1.4f);
    std::vector<Image> panels = {over_colour(truth, {255, 255, 255}, false)};
    for (int c = 0; c < 2; ++c) {
      const Image view = midway_view(tween, composes[c], frame, canvas);
      panels.push_back(over_colour(view, {255, 255, 255}, true));
      std::printf("azimuth %5.1f %s: IoU %.4f, ghost %.4f\n", az, composes[c], matte_iou(view, truth), ghost_fraction(view));
      iou_min[c] = std::min(iou_min[c], matte_iou(view, truth));
      ghost_max[c] = std::max(ghost_max[c], ghost_fraction(view));
      psnr_sum[c] += psnr(over_colour(view, {255, 255, 255}, true), over_colour(truth, {255, 255, 255}, false));
    }
    // For looking at: truth | composed by mattes | plain sum.
    save_image(side_by_side(panels), std::filesystem::path(INKWIRE_TEST_OUTPUT_DIR) / ("turntable-midway-" + std::to_string(int(az)) + ".png"));
    ++views;
  }
  std::printf("matte: IoU min %.4f, ghost max %.4f, PSNR over white %.2f dB; sum: IoU min %.4f, ghost max %.4f, %.2f dB\n",
              iou_min[0], ghost_max[0], psnr_sum[0] / views, iou_min[1], ghost_max[1], psnr_sum[1] / views);
  // The target: the outline where the truth has it at every midway view.
  EXPECT_GE(iou_min[0], 0.97);
  // A ghosted edge is see-through pixels beyond the antialiased rim; composed by mattes there
  // are next to none, and fewer than the plain sum leaves (which is what made doubled legs).
  EXPECT_LT(ghost_max[0], 0.01);
  EXPECT_LT(ghost_max[0], ghost_max[1]);
  // One outline costs nothing in fidelity.
  EXPECT_GT(psnr_sum[0], psnr_sum[1] - 0.5 * views);
}

TEST(TurntableGLTest, TheTrucksMirrorsStandFreeOfTheCabNearHeadOn) {
  test::offscreen_context();
  // The hardest views of the benchmark's product (24 samples at 512 px, as a shop would make
  // it): within 15 degrees of head-on the side mirrors stand free of the cab with background
  // between, while the neighbouring sample sees the cab's flank right behind each mirror. A warp
  // maps that gap to flank pixels of that sample; the composed matte must still call it
  // background where the nearer sample does (it did not: 0.966 at 83 degrees).
  const std::filesystem::path truck_file = test::kAssimpModels / "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf";
  INKWIRE_REQUIRE_FILE(truck_file);
  const SceneObject truck = load_scene_object(truck_file);
  const int size = 512;
  Canvas canvas(size, size);
  TweenRenderer tween;
  prepare_product(tween, truck, size);
  double iou_min = 1.0;
  for (float az = 76.0f; az <= 104.0f; az += 2.0f) {
    if (az == 90.0f) continue;  // a sample's own view
    const FrameState frame = test::view_of(truck, canvas, az, 0.0f, 1.4f);
    const Image truth = render_mesh_view(truck, frame.camera.position - truck.topology.bounds.centre(), size, 1.4f);
    canvas.bind();
    tween.draw(frame);
    const double iou = matte_iou(tween.last_view(), truth);
    std::printf("azimuth %5.1f: IoU %.4f\n", az, iou);
    iou_min = std::min(iou_min, iou);
  }
  EXPECT_GE(iou_min, 0.97);
}

TEST(TurntableGLTest, AProductArrivingPieceByPieceShowsTheNearestPhotoUntilItsCellIsThere) {
  test::offscreen_context();
  INKWIRE_REQUIRE_FILE(test::cgal_mesh("cow.off"));
  const SceneObject cow = load_scene_object(test::cgal_mesh("cow.off"));
  const int size = 128;
  const std::vector<glm::vec3> directions = ring_directions(24);
  const MeshSamples samples = render_mesh_samples(cow, directions, size, 1.4f);
  const TweenData full = exact_tween_data(samples, cow, ring_cells(24), 65);
  Canvas canvas(size, size);
  TweenRenderer tween;
  tween.configure(StyleParams(TweenRenderer::params()));
  TweenModel header;
  header.data.width = header.data.height = size;
  header.data.directions = directions;
  header.bounds = cow.topology.bounds;
  tween.begin_model(header);
  const FrameState frame = test::view_of(cow, canvas, 6.0f, 0.0f, 1.4f);  // between samples 0 and 1, nearer 0
  auto draw = [&] {
    canvas.bind();
    tween.draw(frame);
    return tween.last_view();
  };
  // Nothing yet: nothing drawn, no crash.
  canvas.bind();
  tween.draw(frame);
  EXPECT_EQ(tween.counters().at("samples_loaded"), 0.0);
  // The farther photo first: it shows, as it is.
  tween.set_sample(1, without_floor(samples.images[1]));  // as a stored photo: white around it
  EXPECT_EQ(tween.counters().at("cell"), -1.0);
  const Image only_far = draw();
  EXPECT_GT(matte_iou(only_far, samples.images[1]), 0.99);
  // A style change while photos arrive (regression: it re-made textures of samples not there).
  StyleParams sum(TweenRenderer::params());
  sum.set("compose", "sum");
  EXPECT_NO_THROW(tween.configure(sum));
  EXPECT_NO_THROW(tween.configure(StyleParams(TweenRenderer::params())));
  EXPECT_GT(matte_iou(draw(), samples.images[1]), 0.99);
  // The nearer one: now it shows.
  tween.set_sample(0, without_floor(samples.images[0]));
  const Image nearest = draw();
  EXPECT_GT(matte_iou(nearest, samples.images[0]), 0.99);
  EXPECT_EQ(tween.counters().at("cell"), -1.0);
  // The pair's cell: the view is tweened, closer to the truth than the nearest photo.
  tween.add_cell(full.cells[0]);
  const Image tweened = draw();
  EXPECT_EQ(tween.counters().at("cell"), 0.0);
  const Image truth = render_mesh_view(cow, frame.camera.position - cow.topology.bounds.centre(), size, 1.4f);
  const double near_db = psnr_covered(nearest, truth), tween_db = psnr_covered(tweened, truth);
  std::printf("nearest %.2f dB, tweened %.2f dB\n", near_db, tween_db);
  EXPECT_GT(tween_db, near_db + 2.0);
  EXPECT_THROW(tween.set_sample(2, Image(size / 2, size / 2)), Error);
  EXPECT_THROW(tween.add_cell(TweenCell{.samples = {0, 99}, .points = {}}), Error);
}
