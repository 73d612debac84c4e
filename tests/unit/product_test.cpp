// Products (SPEC T11, T14) without GL: a shop owner's photo folder is read or refused with the
// file named; photos are turned upright by EXIF; a plain backdrop is keyed into a matte that
// matches the object; a stored product is found by its key, checked file by file against its
// hashes, and a corrupted file is refused rather than served.
#include <algorithm>
#include <cmath>
#include <fstream>

#include <OpenImageIO/imageio.h>
#include <sqlite3.h>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "client/render/tween/image_warper.hpp"
#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "common/image_metrics.hpp"
#include "common/random.hpp"
#include "protocol/framing.hpp"
#include "server/products/matte.hpp"
#include "server/products/photo_folder.hpp"
#include "server/products/product_samples.hpp"
#include "server/products/product_store.hpp"
#include "server/tween/outline.hpp"
#include "test_data.hpp"

using namespace inkwire;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = test::scratch_dir() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A product photo: a textured box of `shade` on a plain light-grey studio backdrop with a little
// sensor noise; its alpha is the truth (255 on the object).
Image studio_photo(int w, int h, int shift, uint64_t seed) {
  Random random(seed);
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t* p = image.at(x, y);
      const bool object = std::abs(x - w / 2 - shift) < w / 5 && std::abs(y - h / 2) < h / 4;
      const int noise = int(random.uniform(-4.0f, 4.0f));
      if (object) {
        const bool stripe = ((x - shift) / 6 + y / 9) % 2;
        p[0] = uint8_t(stripe ? 180 : 40), p[1] = uint8_t(60 + noise), p[2] = uint8_t(stripe ? 30 : 140), p[3] = 255;
      } else {
        p[0] = p[1] = p[2] = uint8_t(235 + noise), p[3] = 0;
      }
    }
  return image;
}

void write_photo(const Image& image, const fs::path& file, int orientation = 1) {
  auto out = OIIO::ImageOutput::create(file.string());
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  if (orientation != 1) spec.attribute("Orientation", orientation);
  ASSERT_TRUE(out->open(file.string(), spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data(), 4));
  out->close();
}

fs::path photo_folder(const std::string& name, int count, int w = 96, int h = 64) {
  const fs::path dir = fresh_dir(name);
  for (int i = 0; i < count; ++i) {
    char file[32];
    std::snprintf(file, sizeof file, "IMG_%04d.png", i);
    write_photo(studio_photo(w, h, i, uint64_t(i)), dir / file);
  }
  return dir;
}

}  // namespace

TEST(ProductTest, APhotoFolderIsReadInFileNameOrderRoundAFullTurn) {
  const PhotoFolder f = read_photo_folder(photo_folder("turn", 8), {});
  ASSERT_EQ(f.photos.size(), 8u);
  EXPECT_EQ(f.names.front(), "IMG_0000.png");
  EXPECT_TRUE(f.closed);
  EXPECT_EQ(f.cells.size(), 8u);  // the last photo pairs with the first
  EXPECT_NEAR(glm::degrees(std::acos(glm::dot(f.directions[0], f.directions[1]))), 45.0f, 0.01f);
  EXPECT_TRUE(f.even_turn_assumed);  // nothing said how far each photo turned: add-product finds it
  EXPECT_FALSE(read_photo_folder(photo_folder("stepped", 8), {.step_degrees = 45}).even_turn_assumed);
  // Over a half-turn arc: open, 7 pairs.
  const PhotoFolder arc = read_photo_folder(photo_folder("arc", 8), {.arc_degrees = 180});
  EXPECT_FALSE(arc.closed);
  EXPECT_FALSE(arc.even_turn_assumed);
  EXPECT_EQ(arc.cells.size(), 7u);
  // Scaled to the longer side.
  EXPECT_EQ(read_photo_folder(photo_folder("small", 3, 200, 100), {.max_side = 64}).photos[0].width, 64);
}

TEST(ProductTest, BadFoldersAreRefusedWithTheFileNamed) {
  EXPECT_NE(test::error_of([] { read_photo_folder(fresh_dir("none") / "missing", {}); }).find("is not a folder"), std::string::npos);
  EXPECT_NE(test::error_of([] { read_photo_folder(photo_folder("two", 2), {}); }).find("at least 3"), std::string::npos);
  {
    const fs::path dir = photo_folder("other", 4);
    std::ofstream(dir / "notes.docx") << "price list";
    EXPECT_NE(test::error_of([&] { read_photo_folder(dir, {}); }).find("notes.docx is not a photo"), std::string::npos);
    // Hidden files and text notes are not photos but are no trouble either.
    fs::remove(dir / "notes.docx");
    std::ofstream(dir / ".DS_Store") << "x";
    std::ofstream(dir / "readme.txt") << "x";
    EXPECT_EQ(read_photo_folder(dir, {}).photos.size(), 4u);
  }
  {
    const fs::path dir = photo_folder("broken", 4);
    std::ofstream(dir / "IMG_0002.png", std::ios::trunc) << "\x89PNG not really";
    EXPECT_NE(test::error_of([&] { read_photo_folder(dir, {}); }).find("IMG_0002.png cannot be read"), std::string::npos);
  }
  {
    const fs::path dir = photo_folder("mixed", 4);
    write_photo(studio_photo(64, 96, 0, 9), dir / "IMG_0003.png");  // portrait among landscapes
    EXPECT_NE(test::error_of([&] { read_photo_folder(dir, {}); }).find("IMG_0003.png is 64x96, not the shape"), std::string::npos);
    write_photo(studio_photo(192, 128, 0, 9), dir / "IMG_0003.png");  // the same shape, larger: scaled
    EXPECT_EQ(read_photo_folder(dir, {}).photos[3].width, 96);
  }
  EXPECT_NE(test::error_of([] { read_photo_folder(photo_folder("steps", 8), {.step_degrees = 60}); }).find("more than once round"), std::string::npos);
}

TEST(ProductTest, RowsOfPhotosAreReadFromRowFoldersOrByCountIntoTrianglesBetweenRows) {
  // Three rows of six, in folders row1 (the lowest camera) to row3.
  const fs::path dir = fresh_dir("rows");
  for (int r = 1; r <= 3; ++r) fs::rename(photo_folder("row-" + std::to_string(r), 6), dir / ("row" + std::to_string(r)));
  const PhotoFolder f = read_photo_folder(dir, {});
  ASSERT_EQ(f.rows, 3);
  ASSERT_EQ(f.columns(), 6);
  EXPECT_EQ(f.names[6], "row2/IMG_0000.png");
  EXPECT_TRUE(f.closed);
  // Level, then 15 degrees apart; every row turns from azimuth 0 in the same steps.
  EXPECT_NEAR(glm::degrees(std::asin(f.directions[0].y)), 0.0f, 1e-3f);
  EXPECT_NEAR(glm::degrees(std::asin(f.directions[13].y)), 30.0f, 1e-3f);
  EXPECT_NEAR(glm::degrees(std::atan2(f.directions[13].x, f.directions[13].z)), 60.0f, 1e-3f);
  // Two triangles a quad, six quads round each of the two gaps between rows; every triangle
  // has two photos of one row (its first two) and one of the next or the one before.
  ASSERT_EQ(f.cells.size(), 24u);
  for (const auto& cell : f.cells) {
    ASSERT_EQ(cell.size(), 3u);
    EXPECT_EQ(cell[0] / 6, cell[1] / 6);
    EXPECT_EQ(std::abs(cell[2] / 6 - cell[0] / 6), 1);
  }
  // Given elevations; the same files in one folder with --rows.
  const PhotoFolder given = read_photo_folder(dir, {.elevations = {-10, 20, 50}});
  EXPECT_NEAR(glm::degrees(std::asin(given.directions[17].y)), 50.0f, 1e-3f);
  const fs::path flat = fresh_dir("rows-flat");
  for (const std::string& name : f.names) fs::copy_file(dir / name, flat / (name.substr(0, 4) + name.substr(5)));
  const PhotoFolder counted = read_photo_folder(flat, {.rows = 3});
  EXPECT_EQ(counted.rows, 3);
  EXPECT_EQ(counted.cells, f.cells);
  // What does not fit is refused with the reason.
  EXPECT_NE(test::error_of([&] { read_photo_folder(flat, {.rows = 4}); }).find("do not make 4 rows of one length"), std::string::npos);
  EXPECT_NE(test::error_of([&] { read_photo_folder(dir, {.rows = 2}); }).find("holds 3 row folders"), std::string::npos);
  EXPECT_NE(test::error_of([&] { read_photo_folder(dir, {.elevations = {0, 10}}); }).find("2 elevations given for 3 rows"), std::string::npos);
  EXPECT_NE(test::error_of([&] { read_photo_folder(dir, {.elevations = {0, 30, 20}}); }).find("each higher"), std::string::npos);
  fs::remove(dir / "row3" / "IMG_0005.png");
  EXPECT_NE(test::error_of([&] { read_photo_folder(dir, {}); }).find("row 3 holds 5 photos and row 1 6"), std::string::npos);
  fs::rename(dir / "row3", dir / "row4");
  EXPECT_NE(test::error_of([&] { read_photo_folder(dir, {}); }).find("but no row3"), std::string::npos);
  fs::copy_file(flat / "row1IMG_0000.png", dir / "stray.png");
  EXPECT_NE(test::error_of([&] { read_photo_folder(dir, {}); }).find("stray.png is beside row folders"), std::string::npos);
  fs::create_directory(flat / "extra");
  EXPECT_NE(test::error_of([&] { read_photo_folder(flat, {}); }).find("extra is not a photo"), std::string::npos);
}

TEST(ProductTest, PhotosAreTurnedUprightByTheirExifOrientation) {
  const fs::path dir = fresh_dir("exif");
  Image upright = studio_photo(60, 40, 0, 1);
  for (size_t i = 3; i < upright.pixels.size(); i += 4) upright.pixels[i] = 255;  // a photo has no matte
  // A camera held sideways stores the picture turned and says so (6: turn 90 degrees clockwise
  // to view).
  Image stored(40, 60);
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 40; ++x) std::copy_n(upright.at(59 - y, x), 4, stored.at(x, y));
  write_photo(stored, dir / "sideways.jpg", 6);
  const Image read = load_upright_photo(dir / "sideways.jpg");
  ASSERT_EQ(read.width, 60);
  ASSERT_EQ(read.height, 40);
  EXPECT_GT(psnr(read, upright), 25.0);  // as JPEG
}

TEST(ProductTest, APlainBackdropIsKeyedIntoTheObjectsMatte) {
  Image photo = studio_photo(160, 120, 5, 3);
  const Image truth = photo;
  for (size_t i = 3; i < photo.pixels.size(); i += 4) photo.pixels[i] = 255;
  const MatteResult r = key_plain_background(photo);
  ASSERT_TRUE(r.keyed) << r.reason;
  EXPECT_GT(matte_iou(photo, truth), 0.97);
  // A busy background is refused, not guessed.
  Image busy(160, 120);
  Random random(4);
  for (uint8_t& v : busy.pixels) v = uint8_t(random.uniform(0.0f, 255.0f));
  const MatteResult refused = key_plain_background(busy);
  EXPECT_FALSE(refused.keyed);
  EXPECT_NE(refused.reason.find("not a plain background"), std::string::npos);
}

TEST(ProductTest, TheShadowUnderTheObjectIsKeptAsAFloorLayerNotAsObject) {
  // A red box on a light grey backdrop with a soft grey shadow spreading from its foot, and a grey
  // part (the colour of a shadow, plain) high on its side: the shadow is floor, the grey part is
  // object.
  const glm::vec3 backdrop(230, 228, 225);
  Image photo(200, 150);
  for (int y = 0; y < 150; ++y)
    for (int x = 0; x < 200; ++x) {
      // Darkness 0.45 at the foot (y = 100), fading over 25 pixels down and sideways.
      const float fall = std::max(0.0f, 1.0f - std::hypot((x - 80) / 60.0f, std::max(0, y - 100) / 25.0f));
      const float darkness = y >= 100 ? 0.45f * fall : 0.0f;
      uint8_t* p = photo.at(x, y);
      for (int c = 0; c < 3; ++c) p[c] = uint8_t(std::lround(backdrop[c] * (1.0f - darkness)));
      p[3] = 255;
      if (x >= 40 && x < 120 && y >= 40 && y < 100) p[0] = 200, p[1] = 30, p[2] = 20;       // the red box
      if (x >= 120 && x < 150 && y >= 40 && y < 65) p[0] = p[1] = p[2] = 150;                // the grey part
    }
  Image keyed = photo;
  const MatteResult r = key_plain_background(keyed);
  ASSERT_TRUE(r.keyed) << r.reason;
  EXPECT_EQ(keyed.at(60, 70)[3], 255);   // in the red box
  EXPECT_EQ(keyed.at(135, 50)[3], 255);  // in the grey part
  EXPECT_EQ(keyed.at(80, 110)[3], 0);    // in the shadow: not object
  EXPECT_GT(r.floor_fraction, 0.02);
  // Where the matte is 0, the floor layer as it would look on white: the shadow's darkness kept
  // (0.45 * (1 - 10/25) = 0.27 at 10 pixels below the foot), the plain backdrop white.
  EXPECT_NEAR(keyed.at(80, 110)[1], 255 * (1.0 - 0.27), 6);
  EXPECT_EQ(keyed.at(10, 10)[0], 255);
  EXPECT_EQ(keyed.at(190, 140)[2], 255);
  // Stored as shown: the object on white, the shadow under it.
  const Image stored = laid_on_white(keyed);
  EXPECT_EQ(stored.at(60, 70)[0], 200);
  EXPECT_EQ(stored.at(80, 110)[1], keyed.at(80, 110)[1]);
  EXPECT_EQ(stored.at(10, 10)[3], 255);
}

TEST(ProductTest, AMatteSampleCarriesTheDistanceToTheOutlineBleedsColourOutwardAndKeepsTheFloor) {
  // A product photo as stored: the object, white around it, a shadow on the floor under it.
  Image image(64, 64, {255, 255, 255, 0});
  for (int x = 8; x < 56; ++x) image.at(x, 60)[0] = image.at(x, 60)[1] = image.at(x, 60)[2] = 150;
  for (int y = 8; y < 56; ++y)
    for (int x = 8; x < 56; ++x) {
      uint8_t* p = image.at(x, y);
      p[0] = 200, p[1] = 40, p[2] = 10, p[3] = 255;
    }
  const Image m = matte_sample(image);
  EXPECT_NEAR(m.at(8, 32)[3], 128 + 128 / int(2 * kMatteRange), 3);   // half a pixel inside the edge
  EXPECT_NEAR(m.at(7, 32)[3], 128 - 128 / int(2 * kMatteRange), 3);   // half a pixel outside
  EXPECT_LT(m.at(0, 0)[3], 60);                                          // 11 pixels outside
  EXPECT_EQ(m.at(32, 32)[3], 255);                                       // deep inside
  EXPECT_EQ(int(m.at(7, 32)[0]), 200);  // colour bled out a pixel
  EXPECT_EQ(int(m.at(2, 32)[0]), 255);  // further out, the floor layer: white where there is none
  EXPECT_EQ(int(m.at(32, 60)[0]), 150);  // and the shadow where there is one
}

TEST(ProductTest, AStoredProductIsFoundByItsKeyAndCheckedAgainstItsHashes) {
  const fs::path data = fresh_dir("store");
  server::AssetStore store(data);
  server::ProductSource source;
  source.photos = photo_folder("stored", 6, 96, 64);
  int pairs = 0;
  bool made = false;
  const protocol::Snapshot state = server::find_or_make_product(store, source, "box", [&](int done, int, const std::string&) { pairs += done > 0; }, &made);
  EXPECT_TRUE(made);
  EXPECT_EQ(pairs, 6);
  EXPECT_EQ(state.product.directions.size(), 6u);
  EXPECT_EQ(state.assets.size(), 6u + 6u + 1u);  // photos, mattes, tween data
  const auto messages = server::product_tween_messages(store, state);
  EXPECT_EQ(messages.size(), 6u);
  // The same inputs and settings again: found, not made.
  pairs = 0;
  const protocol::Snapshot again = server::find_or_make_product(store, source, "box-again", {}, &made);
  EXPECT_FALSE(made);
  EXPECT_EQ(pairs, 0);
  EXPECT_EQ(again.assets, state.assets);
  EXPECT_EQ(again.session, "box-again");
  // Other settings are another product.
  server::ProductSource other = source;
  other.photo_options.matte = "none";
  EXPECT_NE(other.key(), source.key());
  // A stored file changed on disk is found out by its hash, not served.
  const auto tween = std::find_if(state.assets.begin(), state.assets.end(), [](const auto& a) { return a.kind == protocol::AssetKind::Tween; });
  const fs::path file = data / "assets" / to_hex(tween->hash);
  std::fstream(file, std::ios::in | std::ios::out | std::ios::binary).seekp(10).put('\x7f');
  EXPECT_NE(test::error_of([&] { server::product_tween_messages(store, state); }).find("does not match its hash"), std::string::npos);
}

TEST(ProductTest, ZoomLevelsDoubleUpToThePhotosOwnSizeAndSkipWhatIsHardlyFiner) {
  EXPECT_EQ(zoom_levels({512, 341}, {2048, 1365}), (std::vector<glm::ivec2>{{1024, 683}, {2048, 1365}}));
  EXPECT_EQ(zoom_levels({512, 384}, {800, 600}), (std::vector<glm::ivec2>{{800, 600}}));
  EXPECT_EQ(zoom_levels({512, 341}, {1200, 800}), (std::vector<glm::ivec2>{{1200, 800}}));  // 1024 is hardly coarser
  EXPECT_TRUE(zoom_levels({512, 288}, {600, 338}).empty());                                 // hardly finer than the first
  EXPECT_TRUE(zoom_levels({300, 300}, {300, 300}).empty());
}

// A shop's large photos (SPEC T18): matched and shown first at 512 pixels a side, kept at their
// own size as a zoom level, keyed and evened as the first level is (the level scaled down is the
// first level again), and found again by key.
TEST(ProductTest, LargePhotosAreKeptAsAZoomLevelMadeAsTheFirstLevelIs) {
  const fs::path data = fresh_dir("zoom-store");
  server::AssetStore store(data);
  server::ProductSource source;
  source.photos = photo_folder("zoomed", 5, 1200, 800);
  std::string said;
  const protocol::Snapshot state = server::find_or_make_product(store, source, "big", [&](int, int, const std::string& line) {
    if (line.starts_with("zoom")) said = line;
  });
  EXPECT_EQ(said, "zoom: photos 512x341 first, then 1200x800");
  EXPECT_EQ(state.product.width, 512);
  ASSERT_EQ(state.product.levels, (std::vector<protocol::ImageSize>{{1200, 800}}));
  std::vector<protocol::AssetAnnounce> first, zoom;
  for (const auto& a : state.assets) {
    if (a.kind == protocol::AssetKind::Samples) first.push_back(a);
    if (a.kind == protocol::AssetKind::Zoom) zoom.push_back(a);
  }
  ASSERT_EQ(zoom.size(), 5u);
  for (size_t i = 0; i < zoom.size(); ++i) {
    const Image fine = load_image_from_memory(store.read_verified(zoom[i].hash), zoom[i].name);
    const Image coarse = load_image_from_memory(store.read_verified(first[i].hash), first[i].name);
    ASSERT_EQ(fine.width, 1200);
    // The same photo, keyed alike (white round it, the object's colours): alike at a quarter of
    // the first level's size, where two JPEGs' ringing on the stripes averages out.
    EXPECT_GT(psnr(resized(fine, 128, 85), resized(coarse, 128, 85)), 40.0) << zoom[i].name;  // the same photo, keyed alike
    EXPECT_GT(zoom[i].size, 2 * first[i].size) << "the level holds more detail than the first";
  }
  EXPECT_EQ(server::product_tween_messages(store, state).size(), 5u);
  // Kept no larger than asked: --max-side 600 is hardly finer than the first level, so none.
  server::ProductSource small = source;
  small.photo_options.layout.max_side = 600;
  EXPECT_TRUE(server::find_or_make_product(store, small, "small", {}).product.levels.empty());
}

// A state stored by protocol version 3 ends before the product's zoom levels: a server upgraded
// in place reads it as having none instead of dropping the session.
TEST(ProductTest, ASessionStoredByTheLastProtocolVersionIsStillRead) {
  const fs::path data = fresh_dir("old-state");
  {
    server::AssetStore store(data);
    protocol::Snapshot state;
    state.session = "review";
    state.revision = 7;
    state.style.renderer = "comic";
    store.save_session({.token = "", .editor_token = "", .state = state});
  }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open((data / "catalogue.sqlite").c_str(), &db), SQLITE_OK);
  {
    sqlite3_stmt* read = nullptr;
    sqlite3_prepare_v2(db, "SELECT state FROM sessions", -1, &read, nullptr);
    ASSERT_EQ(sqlite3_step(read), SQLITE_ROW);
    const auto* bytes = static_cast<const uint8_t*>(sqlite3_column_blob(read, 0));
    protocol::Bytes frame(bytes, bytes + sqlite3_column_bytes(read, 0));
    sqlite3_finalize(read);
    frame.resize(frame.size() - 2);  // no zoom levels' count
    const uint32_t length = uint32_t(frame.size() - protocol::kHeaderBytes);
    for (int k = 0; k < 4; ++k) frame[size_t(k)] = uint8_t(length >> (8 * k));
    sqlite3_stmt* write = nullptr;
    sqlite3_prepare_v2(db, "UPDATE sessions SET state = ?", -1, &write, nullptr);
    sqlite3_bind_blob(write, 1, frame.data(), int(frame.size()), SQLITE_TRANSIENT);
    ASSERT_EQ(sqlite3_step(write), SQLITE_DONE);
    sqlite3_finalize(write);
  }
  sqlite3_close(db);
  server::AssetStore store(data);
  const auto sessions = store.sessions();
  ASSERT_EQ(sessions.size(), 1u);
  EXPECT_EQ(sessions[0].state.style.renderer, "comic");
  EXPECT_EQ(sessions[0].state.revision, 7u);
}

TEST(ProductTest, OutlinePointsFollowTheObjectsEndsRowByRow) {
  // An ellipse that narrows and moves right from one photo to the next, as a turning object does.
  auto ellipse = [](float cx, float rx) {
    Image image(120, 100, {0, 0, 0, 0});
    for (int y = 0; y < 100; ++y)
      for (int x = 0; x < 120; ++x)
        if (std::pow((x + 0.5f - cx) / rx, 2.0f) + std::pow((y + 0.5f - 50.0f) / 40.0f, 2.0f) <= 1.0f) image.at(x, y)[3] = 255;
    return image;
  };
  const Image a = ellipse(50, 30), b = ellipse(58, 24);
  const std::vector<Landmark> points = outline_landmarks(a, b, 8);
  ASSERT_GE(points.size(), 12u);
  for (const Landmark& p : points) {
    EXPECT_EQ(p.source.y, p.target.y);
    const bool left = p.source.x < 50;
    const float half_a = 50 - p.source.x, expected = left ? 58 - half_a * 24.0f / 30.0f : 58 + (p.source.x - 50) * 24.0f / 30.0f;
    EXPECT_NEAR(p.target.x, expected, 1.5f) << p.source.x << "," << p.source.y;
  }
  EXPECT_THROW(outline_landmarks(a, Image(10, 10), 8), Error);
}

// A striped drum turning on a plain backdrop: its outline stands still, its stripes slide faster
// at its middle than at its sides, so a pair needs control points inside as well as round it.
fs::path turning_drum(const std::string& name, int count, int w, int h) {
  const fs::path dir = fresh_dir(name);
  for (int i = 0; i < count; ++i) {
    Image image(w, h);
    const float radius = 0.3f * float(w), turn = 0.12f * float(i);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        uint8_t* p = image.at(x, y);
        const float across = (float(x) - 0.5f * float(w)) / radius;
        if (std::abs(across) < 1.0f && std::abs(y - h / 2) < h / 3) {
          const float u = std::asin(across) + turn;  // where on the drum's surface
          const bool stripe = int(std::floor(u * 6.0f + float(y / 10) * 0.5f)) % 2 != 0;
          p[0] = uint8_t(stripe ? 190 : 30), p[1] = uint8_t(70 + y % 40), p[2] = uint8_t(stripe ? 20 : 150);
        } else {
          p[0] = p[1] = p[2] = 236;
        }
        p[3] = 255;
      }
    char file[32];
    std::snprintf(file, sizeof file, "IMG_%04d.png", i);
    write_photo(image, dir / file);
  }
  return dir;
}

TEST(ProductTest, TheTweenDataKeepsToItsShareOfTheFirstViewByCuttingEachCellsLastPoints) {
  const fs::path folder = turning_drum("budget", 8, 192, 128);
  PhotoProductOptions options;
  options.layout.step_degrees = 45.0f;
  options.max_tween_share = 1.0f;  // no budget: what the matches alone choose
  const Product whole = product_from_photos(folder, options);
  ASSERT_TRUE(whole.matted);
  size_t photo_bytes = 0;
  for (const Image& image : whole.images) photo_bytes += stored_photo(image, true).size() + stored_matte(image).size();
  const size_t whole_bytes = encode_tween(whole.data).size();
  size_t whole_points = 0;
  for (const TweenCell& c : whole.data.cells) whole_points += c.points.size();
  std::printf("no budget: %zu points, %zu bytes of tween data beside %zu of photos and mattes\n", whole_points, whole_bytes, photo_bytes);

  // Every cell of a budgeted product is the unbudgeted cell's first points: the last chosen go.
  auto cut_from_whole = [&](const Product& cut) {
    ASSERT_EQ(cut.data.cells.size(), whole.data.cells.size());
    for (size_t i = 0; i < cut.data.cells.size(); ++i) {
      const auto& kept = cut.data.cells[i].points;
      const auto& all = whole.data.cells[i].points;
      ASSERT_LE(kept.size(), all.size());
      EXPECT_GT(kept.size(), 0u) << "cell " << i << " lost its outline";
      EXPECT_TRUE(std::equal(kept.begin(), kept.end(), all.begin())) << "cell " << i << " is not a cut of its unbudgeted points";
    }
  };
  // Half the tween data's bytes as the share: kept to, and some points cut.
  const double half = double(whole_bytes) / 2.0;
  options.max_tween_share = float(half / (half + double(photo_bytes)));
  const Product budgeted = product_from_photos(folder, options);
  const size_t budgeted_bytes = encode_tween(budgeted.data).size();
  size_t budgeted_points = 0;
  for (const TweenCell& c : budgeted.data.cells) budgeted_points += c.points.size();
  std::printf("share %.4f: %zu points, %zu bytes\n", options.max_tween_share, budgeted_points, budgeted_bytes);
  EXPECT_LE(double(budgeted_bytes), half + 1.0);
  EXPECT_LT(budgeted_points, whole_points);
  cut_from_whole(budgeted);
  // A share the outlines alone exceed: outlines kept, nothing else.
  options.max_tween_share = 1e-5f;
  const Product outlines = product_from_photos(folder, options);
  cut_from_whole(outlines);
  size_t outline_points = 0;
  for (const TweenCell& c : outlines.data.cells) outline_points += c.points.size();
  EXPECT_LT(outline_points, budgeted_points);
}

// Issue "the house and its edges": what a killed add-product leaves (assets stored, no product
// naming them yet, a half-written file) is swept once older than the grace period; a product's
// and a session's assets never are.
TEST(ProductTest, AssetsNothingNamesAreSweptAfterTheGracePeriodAndNamedOnesNever) {
  const fs::path data = fresh_dir("sweep");
  server::AssetStore store(data);
  server::ProductSource source;
  source.photos = photo_folder("swept", 4, 96, 64);
  const protocol::Snapshot product = server::find_or_make_product(store, source, "kept", {});
  protocol::Snapshot scene;
  scene.session = "scene";
  scene.kind = protocol::SessionKind::Scene;
  scene.assets.push_back(store.add_bytes({1, 2, 3, 4}, protocol::AssetKind::Mesh, "scene.glb"));
  store.save_session({.token = "", .editor_token = "", .state = scene});
  const protocol::AssetAnnounce orphan = store.add_bytes({9, 9, 9, 9, 9}, protocol::AssetKind::Samples, "sample-000.jpg");
  std::ofstream(data / "assets" / "abcd.partial") << "half a photo";
  // Younger than the grace period: an add-product may still be running. Nothing goes.
  EXPECT_EQ(store.sweep_unnamed(std::chrono::hours(1)).assets, 0u);
  EXPECT_TRUE(store.find(orphan.hash));
  // Older: the orphan and the partial file go; the product's and the session's assets stay.
  // (Swept as of two seconds on, by a clock the test holds: the catalogue counts whole seconds.)
  const server::AssetStore::Swept swept = store.sweep_unnamed(std::chrono::seconds(0), std::chrono::system_clock::now() + std::chrono::seconds(2));
  EXPECT_TRUE(swept.skipped.empty()) << swept.skipped;
  EXPECT_EQ(swept.assets, 1u);
  EXPECT_EQ(swept.files, 2u);
  EXPECT_FALSE(store.find(orphan.hash));
  EXPECT_FALSE(fs::exists(data / "assets" / to_hex(orphan.hash)));
  EXPECT_FALSE(fs::exists(data / "assets" / "abcd.partial"));
  for (const auto& a : product.assets) EXPECT_TRUE(store.find(a.hash) && fs::exists(data / "assets" / to_hex(a.hash))) << a.name;
  EXPECT_NO_THROW(server::product_tween_messages(store, product));
  EXPECT_TRUE(store.find(scene.assets[0].hash));
}
