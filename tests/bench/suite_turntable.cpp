// --suite turntable (SPEC T11-T14): a product as a shop would show it, against the peer a shop
// would use instead, a 360-degree spin viewer (N photos, the nearest one shown). A textured
// product rendered into N samples at 512x512 (N = 12, 18, 24, 36, 72) and stored as the server
// stores products (JPEG photos, PNG mattes, tween data); the truth rendered at every degree.
// Per N: mean and worst PSNR / SSIM over the 360 truth views of the spin viewer, a cross-fade
// and the tween (every view drawn from the decoded stored photos), the worst matte IoU of the
// tween, the bytes each client downloads, and the bytes and milliseconds until a first view on
// loopback (a real server, a real client). With ../shared/data/templeRing: the same on real
// photos, the even photos made into a product and the odd ones held out as the truth; with
// --photos DIR (repeatable), the same on those folders instead, with the optical-flow
// interpolation of the two photos as the quality reference (SPEC T15).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <optional>
#include <random>
#include <thread>

#include <unistd.h>

#include <glm/trigonometric.hpp>

#include "common/camera.hpp"
#include "protocol/framing.hpp"

#include "bench_harness.hpp"
#include "client/net/asset_cache.hpp"
#include "client/net/session_client.hpp"
#include "client/render/styles.hpp"
#include "client/render/tween/mesh_samples.hpp"
#include "client/render/tween/tween_renderer.hpp"
#include "common/error.hpp"
#include "common/image_metrics.hpp"
#include "common/tween/view_sphere.hpp"
#include "server/products/matte.hpp"
#include "server/products/photo_folder.hpp"
#include "server/products/product.hpp"
#include "server/products/product_store.hpp"
#include "server/products/turn_angles.hpp"
#include "server/tween/dense_matches.hpp"
#include "server/server.hpp"

namespace inkwire::bench {
namespace {

namespace fs = std::filesystem;
constexpr int kSize = 512;
constexpr float kDistance = 1.4f;
const fs::path kTruck = "/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf";

// A stored asset decoded as a client decodes it: from a file (OpenImageIO's JPEG reader here
// reads files only).
Image decode_asset(const server::AssetStore& store, const protocol::AssetAnnounce& asset) {
  const fs::path file = fs::temp_directory_path() / ("inkwire-bench-" + std::to_string(::getpid()) + "-" + asset.name);
  const protocol::Bytes bytes = store.read_verified(asset.hash);
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  Image image = load_image(file);
  fs::remove(file);
  return image;
}

// Decoded stored photos (with their mattes) of a product, as a client gets them.
std::vector<Image> stored_photos(const server::AssetStore& store, const protocol::Snapshot& state) {
  std::vector<Image> photos, mattes;
  for (const auto& a : state.assets) {
    if (a.kind == protocol::AssetKind::Samples) photos.push_back(decode_asset(store, a));
    if (a.kind == protocol::AssetKind::Matte) mattes.push_back(decode_asset(store, a));
  }
  for (size_t i = 0; i < mattes.size(); ++i)
    for (size_t p = 0; p < photos[i].pixels.size(); p += 4) photos[i].pixels[p + 3] = mattes[i].pixels[p];
  return photos;
}

uint64_t bytes_of(const protocol::Snapshot& state, protocol::AssetKind kind) {
  uint64_t n = 0;
  for (const auto& a : state.assets)
    if (a.kind == kind) n += a.size;
  return n;
}

struct Scores {
  std::vector<double> psnr, ssim, iou;
  void add(const Image& view, const Image& truth, bool premultiplied) {
    const Image a = over_colour(view, {255, 255, 255}, premultiplied), b = over_colour(truth, {255, 255, 255}, false);
    psnr.push_back(inkwire::psnr(a, b));
    ssim.push_back(inkwire::ssim(a, b));
    iou.push_back(matte_iou(view, truth));
  }
  static double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / double(std::max<size_t>(v.size(), 1)); }
  static double min(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }
};

Result row(const std::string& variant, const std::string& object, int samples, const Scores& s, bool with_iou) {
  Result r;
  r.suite = "turntable", r.renderer = "turntable", r.variant = variant, r.object = object;
  r.counters = {{"samples", samples}, {"psnr_mean", Scores::mean(s.psnr)}, {"psnr_min", Scores::min(s.psnr)}, {"ssim_mean", Scores::mean(s.ssim)}};
  if (with_iou) r.counters["matte_iou_min"] = Scores::min(s.iou);
  return r;
}

// The view `renderer` synthesises for `frame` by `method` composed by `compose`, at the samples'
// resolution (premultiplied).
Image synthesised(TweenRenderer& renderer, Canvas& canvas, const FrameState& frame, const std::string& method, const std::string& compose) {
  renderer.configure(style_params("tween", {"method=" + method, "compose=" + compose}).front());
  canvas.bind();
  renderer.draw(frame);
  return renderer.last_view();
}

// The time and bytes until a client has what a first view needs, on loopback: the snapshot,
// then the first photo (and its matte). A real server on the stored data, a real client.
std::pair<double, double> first_view(const fs::path& data, const std::string& session) {
  asio::io_context io(1);
  server::ServerConfig config;
  config.port = 0;
  config.data_dir = data;
  config.sessions.clear();
  server::Server server(io, config);
  server.start();
  std::thread thread([&] { io.run(); });
  double ms = 0, bytes = 0;
  {
    const fs::path cache_dir = data / ("cache-" + session);
    fs::remove_all(cache_dir);
    AssetCache cache(cache_dir);
    const auto start = std::chrono::steady_clock::now();
    SessionClient client("127.0.0.1:" + std::to_string(server.port()), "bench");
    const protocol::Snapshot state = client.join(session, "");
    // As the client does: the small matte, then its photo (a spin viewer's photo is an image).
    for (protocol::AssetKind kind : {protocol::AssetKind::Matte, protocol::AssetKind::Samples, protocol::AssetKind::Image})
      for (const auto& a : state.assets)
        if (a.kind == kind) {
          client.fetch_asset(a, cache);
          break;
        }
    ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    // The tween data follows the first photo and may be in the same reads as its last bytes: it
    // is not what the first view waited for.
    double tween_bytes = 0;
    for (const auto& [index, cell] : client.tween_cells()) tween_bytes += double(protocol::kHeaderBytes + 2 + 4 + cell.size());
    bytes = double(client.bytes_received()) - tween_bytes;
  }
  asio::post(io, [&] { server.stop(); });
  thread.join();
  return {ms, bytes};
}

// A spin viewer's product: the N photos over white as JPEGs, in a session of their own.
protocol::Snapshot store_spin(server::AssetStore& store, const std::vector<Image>& photos, const std::string& name) {
  Product spin;
  spin.data.width = photos[0].width, spin.data.height = photos[0].height;
  spin.data.directions = ring_directions(int(photos.size()));
  spin.data.cells = {TweenCell{.samples = {0, 1}, .points = {}}};
  for (const Image& p : photos) spin.images.push_back(over_colour(p, {255, 255, 255}, false));
  protocol::Snapshot state = server::store_product(store, spin, name);
  std::erase_if(state.assets, [](const auto& a) { return a.kind != protocol::AssetKind::Samples; });
  for (auto& a : state.assets) a.kind = protocol::AssetKind::Image;
  state.kind = protocol::SessionKind::Scene;
  state.product = {};
  store.save_session({.token = "", .editor_token = "", .state = state});
  return state;
}

// Spin-viewer photos carry a watermark in the bottom-right corner (../shared/data/spins/mini-rows):
// the corner is left out of every score (painted one colour in the view and the truth alike).
Image without_watermark_corner(Image image, glm::u8vec3 colour) {
  for (int y = image.height - std::max(1, image.height / 20); y < image.height; ++y)
    for (int x = image.width - image.width / 4; x < image.width; ++x) {
      uint8_t* p = image.at(x, y);
      p[0] = colour.r, p[1] = colour.g, p[2] = colour.b, p[3] = 255;
    }
  return image;
}

// The bound of any tween that warps two photos and blends them: each warped onto the held-out
// photo by the optical flow from it (the truth's own correspondences, found with the truth in
// hand), blended as the flow reference is. What stays wrong is what neither photo shows where the
// held-out one does (parts turned into sight, light that moved over the surface), and the flow's
// own misses.
Image flow_from_truth(const Image& truth, const Image& a, const Image& b, float t) {
  DenseMatchOptions whole;
  whole.use_mattes = false;
  return blend_along_flows(a, dense_matches(truth, a, whole).forward, 1.0f, b, dense_matches(truth, b, whole).forward, 1.0f, t);
}

// Which photos of a set make the product and which are held out: every other photo of a row
// (and with rows, every other row: the held-out rows lie between kept ones, so their views are
// tweened up and down as well as round).
struct HeldOut {
  PhotoFolder kept;
  std::vector<size_t> truths;  // indices into the set of the held-out photos within the kept ones' reach
};

HeldOut hold_out(const PhotoFolder& all) {
  HeldOut h;
  const int columns = all.columns(), kept_columns = (columns + 1) / 2, kept_rows = (all.rows + 1) / 2;
  const int last_row = 2 * (kept_rows - 1);  // the highest kept row: views above it have nothing to come from
  // The ring closes when the photos go all the way round and the last held-out one lies between
  // the last kept one and the first.
  h.kept.closed = all.closed && columns % 2 == 0;
  h.kept.folder = all.folder;
  h.kept.finest = all.finest;
  h.kept.calibration = all.calibration;
  if (h.kept.calibration) h.kept.calibration->poses.clear();  // the kept photos' own, below
  for (int r = 0; r < all.rows; ++r)
    for (int c = 0; c < columns; ++c) {
      const size_t i = size_t(r * columns + c);
      if (r % 2 == 0 && c % 2 == 0) {
        h.kept.names.push_back(all.names[i]);
        h.kept.photos.push_back(all.photos[i]);
        h.kept.directions.push_back(all.directions[i]);
        if (h.kept.calibration) h.kept.calibration->poses.push_back(all.calibration->poses[i]);
      } else if (r <= last_row && (h.kept.closed || c < 2 * (kept_columns - 1))) {
        h.truths.push_back(i);
      }
    }
  h.kept.rows = kept_rows;
  if (kept_rows > 1) {
    h.kept.cells = row_triangles(kept_rows, kept_columns, h.kept.closed);
  } else {
    for (int i = 0; i + 1 < kept_columns; ++i) h.kept.cells.push_back({uint16_t(i), uint16_t(i + 1)});
    if (h.kept.closed) h.kept.cells.push_back({uint16_t(kept_columns - 1), 0});
  }
  return h;
}

// Real photos: a folder's even photos made into a product as add-product makes one, the odd ones
// held out as the truth (each lies between product photos; with rows, the odd rows too). Per
// held-out photo: the spin viewer's nearest product photo as it was shot, a cross-fade and the
// tween of the stored product over the photo's own backdrop colour, and the optical-flow
// interpolation of the two product photos it lies between (everything on the client: the
// quality reference). Views are written beside the truth for looking at:
// [truth | spin | cross-fade | tween | flow | tween with the shape | flow from the truth] in
// DIR/turntable-NAME-K.png.
std::vector<Result> photo_set_rows(Canvas& canvas, const fs::path& folder, const fs::path& output_dir, bool even_turn) {
  const std::string name = folder.filename().empty() ? folder.parent_path().filename().string() : folder.filename().string();
  PhotoFolder all = read_photo_folder(folder, {});
  // As add-product: the turn found from the matches unless given (on the whole set, before the
  // odd photos are held out: their azimuths are the truth the views are drawn at).
  const bool turn_found = all.even_turn_assumed && !even_turn;
  if (turn_found)
    find_turn_from_matches(all, [&](int, int, const std::string& line) { std::fprintf(stderr, "inkwire-bench: %s: %s\n", name.c_str(), line.c_str()); });
  const HeldOut held = hold_out(all);
  const PhotoFolder& kept = held.kept;
  const int n = int(kept.photos.size());
  // Today's control points (matched), and with the shape where the mattes give one.
  const auto made = std::chrono::steady_clock::now();
  const Product product = product_from_photo_folder(kept, PhotoProductOptions{.shape = "off"});
  const double seconds_to_make = std::chrono::duration<double>(std::chrono::steady_clock::now() - made).count();
  const auto started = std::chrono::steady_clock::now();
  std::optional<Product> shaped = product_from_photo_folder(kept, PhotoProductOptions{.shape = "auto"},
                                                            [&](int done, int, const std::string& line) {
                                                              if (done == 0) std::fprintf(stderr, "inkwire-bench: %s: %s\n", name.c_str(), line.c_str());
                                                            });
  const double seconds_with_shape = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!shaped->shape) shaped.reset();  // no shape found: its product is today's
  const fs::path data = fs::temp_directory_path() / ("inkwire-bench-photos-" + std::to_string(::getpid()));
  fs::remove_all(data);
  protocol::Snapshot state, shaped_state;
  {
    server::AssetStore store(data);
    state = server::store_product(store, product, "photos");
    if (shaped) shaped_state = server::store_product(store, *shaped, "photos-shape");
  }
  server::AssetStore store(data);
  const auto model_of = [&](const Product& p, const protocol::Snapshot& stored) {
    TweenModel model;
    model.data = p.data;
    model.images = stored_photos(store, stored);
    const float half = kSceneDiagonal / (2.0f * std::sqrt(3.0f));
    model.bounds = {.min = glm::vec3(-half), .max = glm::vec3(half)};
    model.distance_diagonals = p.distance_diagonals;
    return model;
  };
  const TweenModel model = model_of(product, state);
  TweenRenderer renderer, shaped_renderer;
  renderer.configure(style_params("tween").front());
  renderer.use_model(model);
  if (shaped) {
    shaped_renderer.configure(style_params("tween").front());
    shaped_renderer.use_model(model_of(*shaped, shaped_state));
  }
  Scores spin, fade, tween, flow, tween_shape, bound;
  auto score = [](Scores& s, const Image& view, const Image& truth) {
    s.psnr.push_back(psnr(view, truth));
    s.ssim.push_back(ssim(view, truth));
  };
  for (const size_t k : held.truths) {
    const glm::vec3 backdrop = backdrop_colour(all.photos[k]);
    const glm::u8vec3 colour(backdrop);
    const Image truth = without_watermark_corner(all.photos[k], colour);
    const glm::vec3 d = all.directions[k];
    FrameState frame;
    frame.viewport = {model.data.width, model.data.height};
    frame.camera.position = d * model.distance_diagonals * kSceneDiagonal;
    frame.camera.target = glm::vec3(0.0f);
    // The two product photos the held-out view lies between (round one ring: its neighbours in
    // the ring; among rows: the two nearest), and where it lies between them.
    const auto angle_to = [&](int i) { return std::acos(std::clamp(glm::dot(d, kept.directions[size_t(i)]), -1.0f, 1.0f)); };
    int before = int(k) / 2, after = (before + 1) % n;
    if (all.rows > 1) {
      std::vector<int> order(size_t(n), 0);
      std::iota(order.begin(), order.end(), 0);
      std::partial_sort(order.begin(), order.begin() + 2, order.end(), [&](int l, int r) { return angle_to(l) < angle_to(r); });
      before = order[0], after = order[1];
    }
    const float t = angle_to(before) / std::max(angle_to(before) + angle_to(after), 1e-6f);
    const Image& nearest = kept.photos[size_t(t <= 0.5f ? before : after)];
    const Image spin_view = without_watermark_corner(nearest, colour);
    const Image fade_view = without_watermark_corner(over_colour(synthesised(renderer, canvas, frame, "crossfade", "sum"), colour, true), colour);
    const Image tween_view = without_watermark_corner(over_colour(synthesised(renderer, canvas, frame, "bilinear", "matte"), colour, true), colour);
    const Image flow_view = without_watermark_corner(flow_interpolation(kept.photos[size_t(before)], kept.photos[size_t(after)], t), colour);
    score(spin, spin_view, truth);
    score(fade, fade_view, truth);
    score(tween, tween_view, truth);
    score(flow, flow_view, truth);
    const Image bound_view = without_watermark_corner(flow_from_truth(all.photos[k], kept.photos[size_t(before)], kept.photos[size_t(after)], t), colour);
    score(bound, bound_view, truth);
    std::vector<Image> views = {truth, spin_view, fade_view, tween_view, flow_view};
    std::vector<std::string> labels = {"held out", "spin", "cross-fade", "tween", "flow"};
    if (shaped) {
      views.push_back(without_watermark_corner(over_colour(synthesised(shaped_renderer, canvas, frame, "bilinear", "matte"), colour, true), colour));
      labels.push_back("tween, shape");
      score(tween_shape, views.back(), truth);
    }
    views.push_back(bound_view);
    labels.push_back("flow from the truth");
    if (!output_dir.empty()) save_image(side_by_side(views, labels), output_dir / ("turntable-" + name + "-" + std::to_string(k) + ".png"), false);
  }
  const uint64_t photo_bytes = bytes_of(state, protocol::AssetKind::Samples), matte_bytes = bytes_of(state, protocol::AssetKind::Matte),
                 tween_bytes = bytes_of(state, protocol::AssetKind::Tween);
  const std::string suffix = ",n=" + std::to_string(n) + ",data=" + name;
  std::vector<Result> rows = {row("spin" + suffix, name, n, spin, false), row("crossfade" + suffix, name, n, fade, false),
                              row("tween" + suffix, name, n, tween, false), row("flow" + suffix, name, n, flow, false),
                              row("flow-from-truth" + suffix, name, n, bound, false)};
  rows[0].counters["bytes_total"] = double(photo_bytes);
  rows[2].counters["bytes_total"] = double(photo_bytes + matte_bytes + tween_bytes);
  rows[2].counters["bytes_tween"] = double(tween_bytes);
  rows[2].counters["bytes_per_pair"] = double(tween_bytes) / double(std::max<size_t>(product.data.cells.size(), 1));
  rows[2].counters["tween_share"] = double(tween_bytes) / double(photo_bytes + matte_bytes + tween_bytes);
  rows[2].counters["seconds_add_product"] = seconds_to_make;
  rows[2].counters["turn_from_matches"] = turn_found;
  if (shaped) {
    rows.push_back(row("tween-shape" + suffix, name, n, tween_shape, false));
    rows.back().counters["seconds_add_product"] = seconds_with_shape;
    rows.back().counters["bytes_tween"] = double(bytes_of(shaped_state, protocol::AssetKind::Tween));
    const ShapeReport& found = *shaped->shape;
    rows.back().counters["hull_iou_min"] = found.iou_worst;
    rows.back().counters["silhouettes_cut"] = found.source == SilhouetteSource::Cut;
    rows.back().counters["mattes_filled"] = found.source == SilhouetteSource::FilledMattes;
    if (found.found) {  // a calibration came with the photos: the camera the silhouettes gave against it
      rows.back().counters["focal_error"] = double(found.found->focal_px / found.camera.focal_px) - 1.0;
      rows.back().counters["elevation_error_deg"] = double(found.found->elevations_deg[0] - found.camera.elevations_deg[0]);
    }
  }
  // Zoom (SPEC T18): each finer level's size and bytes, fetched only zoomed in (a few photos of
  // it at a time), so not in the share above.
  const std::vector<uint64_t> level_bytes = server::zoom_level_bytes(state);
  std::string levels_said = "first level " + std::to_string(product.data.width) + "x" + std::to_string(product.data.height) + " " +
                            std::to_string(photo_bytes / uint64_t(n)) + " B a photo";
  for (size_t l = 0; l < level_bytes.size(); ++l) {
    const std::string key = "level" + std::to_string(l + 1);
    rows[2].counters[key + "_side"] = double(std::max(state.product.levels[l].width, state.product.levels[l].height));
    rows[2].counters[key + "_bytes_per_photo"] = double(level_bytes[l]) / double(n);
    levels_said += ", " + std::to_string(state.product.levels[l].width) + "x" + std::to_string(state.product.levels[l].height) + " " +
                   std::to_string(level_bytes[l] / uint64_t(n)) + " B a photo";
  }
  std::fprintf(stderr, "inkwire-bench: turntable %s zoom levels: %s\n", name.c_str(), levels_said.c_str());
  std::fprintf(stderr,
               "inkwire-bench: turntable %s (%zu held out): spin %.2f dB, cross-fade %.2f dB, tween %.2f dB, flow %.2f dB, %.0f B a pair; "
               "tween with the shape %s; warped by the flow from the held-out photo %.2f dB\n",
               name.c_str(), spin.psnr.size(), Scores::mean(spin.psnr), Scores::mean(fade.psnr), Scores::mean(tween.psnr),
               Scores::mean(flow.psnr), rows[2].counters["bytes_per_pair"],
               shaped ? (std::to_string(Scores::mean(tween_shape.psnr)) + " dB").c_str() : "none (no shape found)", Scores::mean(bound.psnr));
  fs::remove_all(data);
  return rows;
}

// Angles from the matches (SPEC T19) on the truck photographed over white at azimuths known and
// uneven: turned by hand (each photo up to 30% of a step off even) and on a turntable that speeds
// up and slows down (steps 65-135% of even, the second photo a degree after the first). Per set:
// the mean and worst azimuth error of the turn found, and of taking the photos as even.
std::vector<Result> turn_rows(const SceneObject& truck) {
  std::vector<Result> out;
  for (const int n : {24, 36})
    for (const std::string pattern : {"hand", "turntable"}) {
      const float step = 360.0f / float(n);
      std::vector<float> truth, even;
      std::mt19937 random{static_cast<uint32_t>(n)};
      std::uniform_real_distribution<float> jitter(-0.3f * step, 0.3f * step);
      for (int i = 0; i < n; ++i) {
        even.push_back(step * float(i));
        truth.push_back(step * float(i) + (pattern == "hand" ? jitter(random) : 0.35f * step * std::sin(0.9f * float(i))));
      }
      if (pattern == "turntable") truth[1] = truth[0] + 1.0f;
      PhotoFolder photos;
      for (int i = 0; i < n; ++i) {
        const glm::vec3 d(std::sin(glm::radians(truth[size_t(i)])), 0.0f, std::cos(glm::radians(truth[size_t(i)])));
        photos.photos.push_back(over_colour(render_mesh_view(truck, d, kSize, kDistance), {255, 255, 255}, false));
        photos.names.push_back("photo" + std::to_string(i));
        photos.directions.push_back({std::sin(glm::radians(even[size_t(i)])), 0.0f, std::cos(glm::radians(even[size_t(i)]))});
      }
      photos.finest = {kSize, kSize};
      photos.closed = photos.even_turn_assumed = true;
      const auto started = std::chrono::steady_clock::now();
      find_turn_from_matches(photos);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      std::vector<float> found;
      for (const glm::vec3& d : photos.directions) found.push_back(glm::degrees(std::atan2(d.x, d.z)));
      const std::vector<double> error = azimuth_errors(found, truth), even_error = azimuth_errors(even, truth);
      const auto mean = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size()); };
      Result r;
      r.suite = "turntable", r.renderer = "turn-from-matches", r.variant = pattern + ",n=" + std::to_string(n), r.object = "truck";
      r.counters = {{"samples", n},
                    {"error_mean_degrees", mean(error)},
                    {"error_worst_degrees", *std::max_element(error.begin(), error.end())},
                    {"even_error_mean_degrees", mean(even_error)},
                    {"even_error_worst_degrees", *std::max_element(even_error.begin(), even_error.end())},
                    {"seconds", seconds}};
      std::fprintf(stderr, "inkwire-bench: turn from the matches, truck %s n=%d: mean error %.2f degrees (worst %.2f); even %.2f (worst %.2f)\n",
                   pattern.c_str(), n, r.counters["error_mean_degrees"], r.counters["error_worst_degrees"], r.counters["even_error_mean_degrees"],
                   r.counters["even_error_worst_degrees"]);
      out.push_back(std::move(r));
    }
  return out;
}

}  // namespace

std::vector<Result> run_turntable_suite(Harness& harness) {
  std::vector<Result> results;
  Canvas canvas(kSize, kSize, 1);
  if (!harness.options().photos.empty()) {  // --photos DIR: those sets alone
    for (const std::string& folder : harness.options().photos)
      for (Result& r : photo_set_rows(canvas, folder, harness.options().output_dir, harness.options().even_turn)) results.push_back(std::move(r));
    return results;
  }
  if (!fs::exists(kTruck)) {
    std::fprintf(stderr, "inkwire-bench: %s is missing (assimp-testmodels): no truck rows\n", kTruck.c_str());
    return {};
  }
  const SceneObject truck = load_scene_object(kTruck);
  const fs::path data = fs::temp_directory_path() / ("inkwire-bench-turntable-" + std::to_string(::getpid()));
  fs::remove_all(data);
  // The truth at every degree.
  std::vector<Image> truth;
  for (int deg = 0; deg < 360; ++deg) truth.push_back(render_mesh_view(truck, ring_directions(360)[size_t(deg)], kSize, kDistance));
  std::fprintf(stderr, "inkwire-bench: turntable truth rendered\n");
  for (int n : {12, 18, 24, 36, 72}) {
    // Made and stored as the server makes a product from a mesh.
    Product product;
    const auto directions = ring_directions(n);
    const MeshSamples samples = render_mesh_samples(truck, directions, kSize, kDistance);
    product.data.width = product.data.height = kSize;
    product.data.directions = directions;
    for (const auto& cell : ring_cells(n)) product.data.cells.push_back(exact_cell(samples, truck, cell, 65));
    for (const Image& image : samples.images) product.images.push_back(without_floor(image));
    product.matted = true;
    const std::string name = "truck" + std::to_string(n);
    protocol::Snapshot state, spin_state;
    {
      server::AssetStore store(data);
      state = server::store_product(store, product, name);
      store.save_session({.token = "", .editor_token = "", .state = state});
      spin_state = store_spin(store, samples.images, "spin" + std::to_string(n));
    }
    server::AssetStore store(data);
    TweenModel model;
    model.data = decode_tween(store.read_verified(std::find_if(state.assets.begin(), state.assets.end(), [](const auto& a) {
                                                    return a.kind == protocol::AssetKind::Tween;
                                                  })->hash));
    model.images = stored_photos(store, state);
    model.bounds = truck.topology.bounds;
    model.distance_diagonals = kDistance;
    std::vector<Image> spin_photos;
    for (const auto& a : spin_state.assets) spin_photos.push_back(decode_asset(store, a));

    Scores spin, fade, tween;
    TweenRenderer renderer;
    renderer.configure(style_params("tween").front());
    renderer.use_model(model);
    for (int deg = 0; deg < 360; ++deg) {
      const glm::vec3 d = ring_directions(360)[size_t(deg)];
      FrameState frame;
      frame.viewport = {kSize, kSize};
      frame.camera = sample_camera(truck.topology.bounds, d, kDistance);
      // The spin viewer: the nearest photo as it is.
      int nearest = int(std::lround(float(deg) * float(n) / 360.0f)) % n;
      const Image& shown = spin_photos[size_t(nearest)];  // over white already: a spin viewer has no matte
      const Image truth_on_white = over_colour(truth[size_t(deg)], {255, 255, 255}, false);
      spin.psnr.push_back(psnr(shown, truth_on_white));
      spin.ssim.push_back(ssim(shown, truth_on_white));
      for (auto [method, compose, scores] : {std::tuple{"crossfade", "sum", &fade}, std::tuple{"bilinear", "matte", &tween}})
        scores->add(synthesised(renderer, canvas, frame, method, compose), truth[size_t(deg)], true);
    }
    const uint64_t photo_bytes = bytes_of(state, protocol::AssetKind::Samples), matte_bytes = bytes_of(state, protocol::AssetKind::Matte),
                   tween_bytes = bytes_of(state, protocol::AssetKind::Tween), spin_bytes = bytes_of(spin_state, protocol::AssetKind::Image);
    const auto [tween_ms, tween_first] = first_view(data, name);
    const auto [spin_ms, spin_first] = first_view(data, "spin" + std::to_string(n));
    Result s = row("spin,n=" + std::to_string(n), "truck", n, spin, false);
    s.counters["bytes_total"] = double(spin_bytes);
    s.counters["bytes_first_view"] = spin_first;
    s.counters["ms_first_view"] = spin_ms;
    Result f = row("crossfade,n=" + std::to_string(n), "truck", n, fade, true);
    f.counters["bytes_total"] = double(spin_bytes);
    Result t = row("tween,n=" + std::to_string(n), "truck", n, tween, true);
    t.counters["bytes_total"] = double(photo_bytes + matte_bytes + tween_bytes);
    t.counters["bytes_photos"] = double(photo_bytes);
    t.counters["bytes_mattes"] = double(matte_bytes);
    t.counters["bytes_tween"] = double(tween_bytes);
    t.counters["bytes_first_view"] = tween_first;
    t.counters["ms_first_view"] = tween_ms;
    t.counters["one_photo_bytes"] = double(photo_bytes) / n;
    for (Result* r : {&s, &f, &t}) results.push_back(std::move(*r));
    std::fprintf(stderr, "inkwire-bench: turntable n=%d: spin %.2f dB, cross-fade %.2f dB, tween %.2f dB (IoU min %.4f)\n", n,
                 Scores::mean(spin.psnr), Scores::mean(fade.psnr), Scores::mean(tween.psnr), Scores::min(tween.iou));
  }
  fs::remove_all(data);
  for (Result& r : turn_rows(truck)) results.push_back(std::move(r));
  (void)harness;  // the suite makes its own canvases at the product's size
  const fs::path temple = fs::path(INKWIRE_SHARED_DATA_DIR) / "templeRing";
  if (fs::exists(temple))
    for (Result& r : photo_set_rows(canvas, temple, harness.options().output_dir, false)) results.push_back(std::move(r));
  else
    std::fprintf(stderr, "inkwire-bench: %s is absent: no templeRing rows\n", temple.c_str());
  return results;
}

}  // namespace inkwire::bench
