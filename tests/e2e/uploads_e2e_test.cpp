// Scenes from the models people bring (SPEC N8, N10, N11), end to end on 127.0.0.1: uploads sent
// over HTTP as a page's FormData sends them to a real inkwire-server. Every file of assimp's
// invalid corpus is refused with a one-line reason while members are served and nothing stays
// stored; an upload over the size cap is refused from its length before its body comes; an
// address uploading 50 times a second is slowed; a glTF reaching outside its upload is refused;
// good uploads (a glTF of three files, an OBJ with its MTL and five textures, a MilkShape model
// with its texture) become scenes a native client draws as inkwire-render draws the file; the
// editor's key replaces the model of a running scene and its members draw the new one; the
// policy's creator token and "off" are kept to. Reads assimp-testmodels (skips without it).
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "client/net/session_client.hpp"
#include "client/viewer/session_content.hpp"
#include "common/image.hpp"
#include "common/image_metrics.hpp"
#include "making_support.hpp"

using namespace inkwire;
using namespace inkwire::e2e;
using namespace std::chrono_literals;

namespace {

const fs::path kModels = "/usr/share/assimp/models";
const fs::path kBox = kModels / "glTF2/BoxTextured-glTF";
const std::vector<fs::path> kBoxFiles = {kBox / "BoxTextured.gltf", kBox / "BoxTextured0.bin", kBox / "CesiumLogoFlat.png"};
const fs::path kObj = kModels / "OBJ";
const std::vector<fs::path> kSpiderFiles = {kObj / "spider.obj",     kObj / "spider.mtl",        kObj / "SpiderTex.jpg",    kObj / "drkwood2.jpg",
                                            kObj / "engineflare1.jpg", kObj / "wal67ar_small.jpg", kObj / "wal69ar_small.jpg"};
const std::vector<fs::path> kJeepFiles = {kModels / "MS3D/jeep1.ms3d", kModels / "MS3D/jeep1.jpg"};
const fs::path kCow = fs::path(INKWIRE_MESH_DIR) / "cow.off";

nlohmann::json upload_config(nlohmann::json making = nlohmann::json::object(), nlohmann::json extra = nlohmann::json::object()) {
  nlohmann::json c = {{"http", "127.0.0.1:0"},
                      {"sessions", {{{"name", "cows"}, {"kind", "scene"}, {"assets", {{{"path", kCow.string()}}}}}}},
                      {"making", making}};
  c.update(extra);
  return c;
}

// A change made by one member of "cows" reaches another: the server serves its members.
void check_served(SessionClient& from, SessionClient& to, uint32_t sequence) {
  from.send(orbit_pose(float(sequence * 10 % 360), 20, 1.4f, sequence));
  EXPECT_TRUE(eventually([&] { return to.state().camera.sequence == sequence; })) << "members of a session were not served while uploads came";
}

// What a data folder holds that an upload could leave behind.
struct Stored {
  size_t assets = 0, uploads = 0;
  double sessions = 0;
  bool operator==(const Stored&) const = default;
};
Stored stored_in(ServerUnderTest& server, const fs::path& data) {
  return {files_under(data / "assets"), files_under(data / "uploads"), metric_value(metrics_of(server), "inkwire_sessions")};
}
std::ostream& operator<<(std::ostream& o, const Stored& s) { return o << s.assets << " assets, " << s.uploads << " upload files, " << s.sessions << " sessions"; }

// One frame of scene `name` by a headless client, as DIR/NAME-0000.png; its exit status.
int draw_scene(const ServerUnderTest& server, const std::string& name, const fs::path& dir, const std::string& as) {
  auto client = headless_client(server, name, dir, as, 1, 10);
  const int status = client->wait();
  if (status != 0) ADD_FAILURE() << client->output();
  return status;
}

// The model file drawn by inkwire-render at a scene's first view (orbit 30, 20 at 1.4
// diagonals) in an uploaded scene's style.
Image render_file(const fs::path& model, const fs::path& out) {
  Process render("inkwire-render", {"--mesh", model.string(), "--style", "comic-extended", "--view", "30,20,1.4", "--size", "240x180", "--out", out.string()},
                 fs::path(out).replace_extension(".log"));
  EXPECT_EQ(render.wait(), 0) << render.output();
  return load_image(out);
}

}  // namespace

class UploadsE2ETest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kBox) || !fs::exists(kModels / "invalid")) GTEST_SKIP() << kModels << " is missing (Debian package assimp-testmodels)";
    if (!fs::exists(kCow)) GTEST_SKIP() << "libcgal-demo's cow.off is not extracted (run scripts/setup.sh)";
  }
};

TEST_F(UploadsE2ETest, EveryFileOfTheInvalidCorpusIsRefusedWithAReasonWhileMembersAreServedAndNothingStays) {
  const fs::path dir = output_dir("uploads-invalid");
  ServerUnderTest server(dir, upload_config());
  const int port = http_port(server);
  SessionClient a(server.address(), "a"), b(server.address(), "b");
  a.join("cows", "");
  b.join("cows", "");
  const Stored before = stored_in(server, dir / "data");
  std::vector<fs::path> corpus;
  for (const auto& e : fs::directory_iterator(kModels / "invalid")) corpus.push_back(e.path());
  std::sort(corpus.begin(), corpus.end());
  ASSERT_GE(corpus.size(), 10u);
  std::ofstream reasons(dir / "reasons.txt");
  uint32_t sequence = 0;
  for (const fs::path& file : corpus) {
    const HttpAnswer answer = upload_files(port, {file});
    reasons << file.filename().string() << ": " << answer.status << " " << answer.error() << "\n";
    EXPECT_EQ(answer.status, 422) << file << "\n" << answer.raw;
    EXPECT_FALSE(answer.error().empty()) << file << ": no reason\n" << answer.raw;
    EXPECT_EQ(answer.error().find('\n'), std::string::npos) << file << ": not one line: " << answer.error();
    EXPECT_LE(answer.error().size(), 300u) << file << ": " << answer.error();
    if (file.extension() != ".txt") {
      EXPECT_NE(answer.error().find(file.filename().string()), std::string::npos) << "the reason names the file: " << answer.error();
    }
    EXPECT_EQ(answer.error().find((dir / "data").string()), std::string::npos) << "the reason shows the server's folders: " << answer.error();
    check_served(a, b, ++sequence);
  }
  EXPECT_TRUE(a.connected() && b.connected());
  EXPECT_EQ(stored_in(server, dir / "data"), before) << "an upload the server refused left something behind";
  const std::string metrics = metrics_of(server);
  EXPECT_EQ(metric_value(metrics, "inkwire_making_refused_total{reason=\"import\"}"), double(corpus.size())) << metrics;
  EXPECT_EQ(metric_value(metrics, "inkwire_scenes_made_total"), 0) << metrics;
  EXPECT_EQ(metric_value(metrics, "inkwire_scenes_open"), 0) << metrics;
  EXPECT_NE(http_get(port, "GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n").find("200 OK"), std::string::npos);
}

TEST_F(UploadsE2ETest, AnUploadOverTheCapIsRefusedFromItsLengthBeforeItsBodyIsSent) {
  const fs::path dir = output_dir("uploads-too-large");
  ServerUnderTest server(dir, upload_config({{"max_upload_bytes", 1 << 20}}));
  const int port = http_port(server);
  // A head saying 64 MiB, then the first 64 KiB of the body; the rest is never sent.
  asio::io_context io;
  asio::ip::tcp::socket s(io);
  s.connect({asio::ip::make_address("127.0.0.1"), uint16_t(port)});
  const std::string head = "POST /scenes HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: multipart/form-data; boundary=" + kBoundary +
                           "\r\nContent-Length: " + std::to_string(64 << 20) + "\r\n\r\n";
  asio::write(s, asio::buffer(head));
  asio::write(s, asio::buffer(std::string(64 << 10, 'x')));
  std::string raw;
  std::error_code ec;
  asio::read(s, asio::dynamic_buffer(raw), ec);  // up to the server's close
  const HttpAnswer answer = parse_answer(raw);
  EXPECT_EQ(answer.status, 413) << raw;
  EXPECT_EQ(answer.error(), "the upload is 64 MiB; this server takes at most 1 MiB") << raw;
  // One just under the cap is read (and refused for what it is, not for its size).
  const HttpAnswer under = post_upload(port, multipart_body({{"empty.obj", std::string((1 << 20) - 400, ' ')}}));
  EXPECT_EQ(under.status, 422) << under.raw;
  // No length, no upload; nor what is not multipart.
  const HttpAnswer chunked = parse_answer(http_get(port, "POST /scenes HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\n0\r\n\r\n"));
  EXPECT_EQ(chunked.status, 411) << chunked.raw;
  const HttpAnswer plain = parse_answer(http_get(port, "POST /scenes HTTP/1.1\r\nHost: x\r\nContent-Type: text/plain\r\nContent-Length: 2\r\n\r\nhi"));
  EXPECT_EQ(plain.status, 415) << plain.raw;
  const std::string metrics = metrics_of(server);
  EXPECT_EQ(metric_value(metrics, "inkwire_making_refused_total{reason=\"size\"}"), 1) << metrics;
  EXPECT_EQ(files_under(dir / "data" / "uploads"), 0u);
}

TEST_F(UploadsE2ETest, AnAddressUploadingFiftyTimesASecondIsSlowedWhileOthersAreNot) {
  const fs::path dir = output_dir("uploads-rate");
  // The test's uploads come from this machine: the per-address limits are asked to apply to it.
  ServerUnderTest server(dir, upload_config({{"uploads_per_minute_per_address", 20}}, {{"limit_loopback", true}}));
  const int port = http_port(server);
  // A body that is no upload at all: refused as it is read, with no importer to wait for.
  const std::string broken = "--" + kBoundary + "\r\nContent-Disposition: form-data; name=\"note\"\r\n\r\nhello\r\n--" + kBoundary + "--\r\n";
  int taken = 0, slowed = 0;
  std::string retry_after, reason;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 50; ++i) {
    std::this_thread::sleep_until(start + i * 20ms);  // 50 a second
    const HttpAnswer answer = post_upload(port, broken);
    if (answer.status == 429) {
      ++slowed;
      retry_after = answer.headers.count("retry-after") ? answer.headers.at("retry-after") : "";
      reason = answer.error();
    } else {
      EXPECT_EQ(answer.status, 400) << answer.raw;
      ++taken;
    }
  }
  EXPECT_LE(taken, 22) << "a minute's worth (20) at once, then hardly more";
  EXPECT_GE(slowed, 28);
  EXPECT_GE(std::atoi(retry_after.c_str()), 1) << "a slowed upload is told when to come back";
  EXPECT_NE(reason.find("too many uploads from your address"), std::string::npos) << reason;
  EXPECT_GE(metric_value(metrics_of(server), "inkwire_making_refused_total{reason=\"rate\"}"), 28);
  // Another address is not slowed (a socket bound to 127.0.0.2 is another address to the server).
  asio::io_context io;
  asio::ip::tcp::socket other(io);
  other.open(asio::ip::tcp::v4());
  other.bind({asio::ip::make_address("127.0.0.2"), 0});
  other.connect({asio::ip::make_address("127.0.0.1"), uint16_t(port)});
  const std::string body = multipart_of_files(kBoxFiles);
  asio::write(other, asio::buffer("POST /scenes HTTP/1.1\r\nHost: x\r\nContent-Type: multipart/form-data; boundary=" + kBoundary +
                                  "\r\nContent-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body));
  std::string raw;
  std::error_code ec;
  asio::read(other, asio::dynamic_buffer(raw), ec);
  EXPECT_EQ(parse_answer(raw).status, 201) << raw;
}

TEST_F(UploadsE2ETest, AGltfWhoseFilesLieOutsideItsUploadIsRefusedAndNothingIsStored) {
  const fs::path dir = output_dir("uploads-outside");
  ServerUnderTest server(dir, upload_config());
  const int port = http_port(server);
  const Stored before = stored_in(server, dir / "data");
  std::string gltf = read_file_bytes(kBox / "BoxTextured.gltf");
  const auto with_uri = [&](const std::string& from, const std::string& to) {
    std::string changed = gltf;
    changed.replace(changed.find("\"" + from + "\""), from.size() + 2, "\"" + to + "\"");
    return changed;
  };
  // The buffer one folder up (where the server keeps its upload's other files).
  const HttpAnswer up = post_upload(port, multipart_body({{"BoxTextured.gltf", with_uri("BoxTextured0.bin", "../BoxTextured0.bin")},
                                                          {"BoxTextured0.bin", read_file_bytes(kBox / "BoxTextured0.bin")},
                                                          {"CesiumLogoFlat.png", read_file_bytes(kBox / "CesiumLogoFlat.png")}}));
  EXPECT_EQ(up.status, 422) << up.raw;
  EXPECT_NE(up.error().find("outside its upload"), std::string::npos) << up.error();
  // Any file of the machine.
  const HttpAnswer system = post_upload(port, multipart_body({{"BoxTextured.gltf", with_uri("BoxTextured0.bin", "../../../../../../../../etc/passwd")},
                                                              {"CesiumLogoFlat.png", read_file_bytes(kBox / "CesiumLogoFlat.png")}}));
  EXPECT_EQ(system.status, 422) << system.raw;
  EXPECT_NE(system.error().find("outside its upload"), std::string::npos) << system.error();
  // A texture elsewhere on the machine (one that exists).
  const HttpAnswer texture = post_upload(port, multipart_body({{"BoxTextured.gltf", with_uri("CesiumLogoFlat.png", (kBox / "CesiumLogoFlat.png").string())},
                                                               {"BoxTextured0.bin", read_file_bytes(kBox / "BoxTextured0.bin")}}));
  EXPECT_EQ(texture.status, 422) << texture.raw;
  EXPECT_EQ(stored_in(server, dir / "data"), before);
}

TEST_F(UploadsE2ETest, GoodUploadsBecomeScenesThatANativeClientDrawsAsTheFileIsDrawn) {
  const fs::path dir = output_dir("uploads-good");
  ServerUnderTest server(dir, upload_config());
  const int port = http_port(server);
  const std::vector<std::pair<std::string, std::vector<fs::path>>> models = {{"box", kBoxFiles}, {"spider", kSpiderFiles}, {"jeep", kJeepFiles}};
  std::set<std::string> names;
  for (const auto& [label, files] : models) {
    const HttpAnswer answer = upload_files(port, files);
    ASSERT_EQ(answer.status, 201) << label << "\n" << answer.raw;
    const nlohmann::json made = answer.json();
    const std::string name = made.value("name", "");
    EXPECT_GE(name.size(), 16u) << "an unguessable name (96 bits) is 16 characters";
    EXPECT_TRUE(names.insert(name).second);
    EXPECT_EQ(made.value("page", ""), "/scene/" + name);
    EXPECT_EQ(made.value("editor_key", "").size(), 32u);
    EXPECT_GT(made.value("triangles", 0), 0);
    EXPECT_NE(http_get(port, "GET /scene/" + name + " HTTP/1.1\r\nHost: x\r\n\r\n").find("200 OK"), std::string::npos);
    ASSERT_EQ(draw_scene(server, name, dir, label), 0);
    // The client holds one GLB, however many files came.
    std::vector<fs::path> cached;
    for (const auto& e : fs::directory_iterator(dir / ("cache-" + label))) cached.push_back(e.path());
    ASSERT_EQ(cached.size(), 1u) << label;
    EXPECT_EQ(cached[0].extension(), ".glb") << label;
    const Image drawn = load_image(client_frame(dir, label, 0)), from_file = render_file(files[0], dir / (label + "-render.png"));
    EXPECT_GE(psnr(drawn, from_file), 35.0) << label << ": the scene drawn differs from the file drawn by inkwire-render";
  }
  const std::string metrics = metrics_of(server);
  EXPECT_EQ(metric_value(metrics, "inkwire_scenes_made_total"), 3) << metrics;
  EXPECT_EQ(metric_value(metrics, "inkwire_scenes_open"), 3) << metrics;
  EXPECT_EQ(files_under(dir / "data" / "uploads"), 0u) << "an upload's files stayed after it became a scene";
  // Scenes made so are not listed on the front page.
  const std::string front = http_get(port, "GET / HTTP/1.1\r\nHost: x\r\n\r\n");
  for (const std::string& name : names) EXPECT_EQ(front.find(name), std::string::npos) << "an uploaded scene is listed on /";
}

TEST_F(UploadsE2ETest, TheEditorsKeyReplacesTheModelOfARunningSceneAndEveryMemberDrawsTheNewOne) {
  const fs::path dir = output_dir("uploads-replace");
  ServerUnderTest server(dir, upload_config());
  const int port = http_port(server);
  const nlohmann::json made = upload_files(port, kBoxFiles).json();
  const std::string name = made.value("name", ""), key = made.value("editor_key", "");
  ASSERT_FALSE(name.empty()) << made.dump();
  SessionClient member(server.address(), "member");
  const protocol::Snapshot first = member.join(name, "");
  ASSERT_EQ(first.assets.size(), 1u);
  // The editor's camera, which the new model keeps.
  SessionClient editor(server.address(), "editor");
  editor.join(name, key);
  editor.send(orbit_pose(30, 20, 1.4f, 7));
  ASSERT_TRUE(eventually([&] { return member.state().camera.sequence == 7; }));
  auto viewer = std::make_unique<Process>(
      "inkwire-client", std::vector<std::string>{"--connect", server.address(), "--session", name, "--headless", "--frames", "3000", "--fps", "5",
                                                 "--size", "240x180", "--cache", (dir / "cache-viewer").string(), "--out",
                                                 (dir / "viewer-%04d.png").string(), "--frame-log", (dir / "viewer.jsonl").string()},
      dir / "viewer.log");
  ASSERT_TRUE(eventually([&] { return frame_log(dir / "viewer.jsonl").size() >= 2; })) << viewer->output();

  // Without the key, with a wrong one, or for a scene that is not there: refused.
  const std::string spider = multipart_of_files(kSpiderFiles);
  EXPECT_EQ(post_upload(port, spider, "/scenes/" + name + "/model").status, 403);
  const HttpAnswer wrong = post_upload(port, spider, "/scenes/" + name + "/model", "X-Inkwire-Editor-Key: 0123456789abcdef0123456789abcdef\r\n");
  EXPECT_EQ(wrong.status, 403) << wrong.raw;
  EXPECT_EQ(wrong.error(), "only the scene's editor may replace its model");
  EXPECT_EQ(post_upload(port, spider, "/scenes/nowhere/model", "X-Inkwire-Editor-Key: " + key + "\r\n").status, 404);
  EXPECT_EQ(post_upload(port, spider, "/scenes/cows/model", "X-Inkwire-Editor-Key: " + key + "\r\n").status, 403)
      << "one scene's key replaced another's model";
  EXPECT_EQ(member.state().assets, first.assets);

  // With it, every member gets the new snapshot: the new model, the camera kept.
  const uint32_t revision = member.state().revision;
  const HttpAnswer replaced = post_upload(port, spider, "/scenes/" + name + "/model", "X-Inkwire-Editor-Key: " + key + "\r\n");
  ASSERT_EQ(replaced.status, 200) << replaced.raw;
  EXPECT_EQ(replaced.json().value("name", ""), name);
  ASSERT_TRUE(eventually([&] { return member.state().assets != first.assets; }));
  const protocol::Snapshot now = member.state();
  ASSERT_EQ(now.assets.size(), 1u);
  EXPECT_EQ(now.assets[0].name, "spider.glb");
  EXPECT_GT(now.revision, revision);
  EXPECT_EQ(now.camera.sequence, 7u) << "the scene's camera was not kept";
  EXPECT_EQ(now.style, first.style);
  // The native member draws the spider a few frames later, as inkwire-render draws the file.
  ASSERT_TRUE(eventually([&] {
    int newer = 0;
    for (const auto& line : frame_log(dir / "viewer.jsonl")) newer += line["revision"].get<uint32_t>() >= now.revision;
    return newer >= 3;
  })) << viewer->output();
  viewer->kill(SIGTERM);
  ASSERT_EQ(viewer->wait(), 0) << viewer->output();
  const auto log = frame_log(dir / "viewer.jsonl");
  const Image before = load_image(client_frame(dir, "viewer", 0)), after = load_image(client_frame(dir, "viewer", int(log.size()) - 1));
  EXPECT_GE(psnr(before, render_file(kBoxFiles[0], dir / "box-render.png")), 35.0) << "the first frames are not the box";
  EXPECT_GE(psnr(after, render_file(kSpiderFiles[0], dir / "spider-render.png")), 35.0) << "the last frame is not the spider";
  EXPECT_EQ(metric_value(metrics_of(server), "inkwire_models_replaced_total"), 1);
  // A later member joins the scene as it is now.
  SessionClient late(server.address(), "late");
  EXPECT_EQ(late.join(name, "").assets, now.assets);
}

TEST_F(UploadsE2ETest, ThePolicysCreatorTokenAndOffAreKeptTo) {
  const fs::path dir = output_dir("uploads-policy");
  const std::string box = multipart_of_files(kBoxFiles);
  {
    fs::create_directories(dir / "token");
    ServerUnderTest server(dir / "token", upload_config({{"who", "token"}, {"creator_token", "c0ffee"}}));
    const int port = http_port(server);
    const HttpAnswer none = post_upload(port, box);
    EXPECT_EQ(none.status, 403) << none.raw;
    EXPECT_EQ(none.error(), "only holders of this server's creator token may make scenes");
    const HttpAnswer wrong = post_upload(port, box, "/scenes", "X-Inkwire-Creator-Token: tea\r\n");
    EXPECT_EQ(wrong.status, 403) << wrong.raw;
    EXPECT_NE(wrong.error().find("wrong token"), std::string::npos) << wrong.error();
    const HttpAnswer right = post_upload(port, box, "/scenes", "X-Inkwire-Creator-Token: c0ffee\r\n");
    EXPECT_EQ(right.status, 201) << right.raw;
    EXPECT_EQ(metric_value(metrics_of(server), "inkwire_making_refused_total{reason=\"token\"}"), 2);
  }
  {
    fs::create_directories(dir / "off");
    ServerUnderTest server(dir / "off", upload_config({{"who", "off"}}));
    const int port = http_port(server);
    const HttpAnswer off = post_upload(port, box);
    EXPECT_EQ(off.status, 403) << off.raw;
    EXPECT_EQ(off.error(), "this server does not let visitors make scenes");
    EXPECT_EQ(files_under(dir / "off" / "data" / "uploads"), 0u);
  }
}

TEST_F(UploadsE2ETest, ModelsOverTheTriangleOrTexturePixelCapsAreRefusedSayingWhich) {
  const fs::path dir = output_dir("uploads-caps");
  ServerUnderTest server(dir, upload_config({{"max_triangles", 1000}, {"max_texture_pixels", 40000}}));
  const int port = http_port(server);
  const HttpAnswer triangles = upload_files(port, kSpiderFiles);  // 1312 triangles
  EXPECT_EQ(triangles.status, 422) << triangles.raw;
  EXPECT_EQ(triangles.error(), "spider.obj has 1312 triangles; this server takes at most 1000");
  const HttpAnswer pixels = upload_files(port, kBoxFiles);  // a 211 x 211 texture
  EXPECT_EQ(pixels.status, 422) << pixels.raw;
  EXPECT_EQ(pixels.error(), "BoxTextured.gltf's textures hold 44521 pixels; this server takes at most 40000");
  EXPECT_EQ(files_under(dir / "data" / "uploads"), 0u);
}


// Uploads that stall (a head and a little of the body, then nothing) cost their senders only:
// someone else's upload meanwhile becomes a scene, and the stalled ones are cut off with the
// reason, leaving nothing behind. (Each upload held one of the server's two import places from
// its head on, so two stalled senders refused every other upload for as long as they stalled.)
TEST_F(UploadsE2ETest, StalledUploadsCostOnlyTheirSenders) {
  const fs::path dir = output_dir("uploads-stalled");
  ServerUnderTest server(dir, upload_config(nlohmann::json::object(), {{"limit_loopback", true}}));
  const int port = http_port(server);
  asio::io_context io;
  std::vector<std::unique_ptr<asio::ip::tcp::socket>> stalled;
  for (int i = 0; i < 3; ++i) {
    auto s = std::make_unique<asio::ip::tcp::socket>(io);
    s->open(asio::ip::tcp::v4());
    s->bind({asio::ip::make_address("127.0.0.3"), 0});  // the stalling sender's own address
    s->connect({asio::ip::make_address("127.0.0.1"), uint16_t(port)});
    const std::string start = "--" + kBoundary + "\r\nContent-Disposition: form-data; name=\"files\"; filename=\"big.obj\"\r\n\r\nv 0 0 0\n";
    asio::write(*s, asio::buffer("POST /scenes HTTP/1.1\r\nHost: x\r\nContent-Type: multipart/form-data; boundary=" + kBoundary +
                                 "\r\nContent-Length: 1000000\r\n\r\n" + start));
    stalled.push_back(std::move(s));
  }
  ASSERT_TRUE(eventually([&] { return files_under(dir / "data" / "uploads") >= 2; })) << "the stalled uploads were not begun";
  const auto since = std::chrono::steady_clock::now();
  const HttpAnswer other = upload_files(port, kBoxFiles);
  EXPECT_EQ(other.status, 201) << "another sender's upload was refused while uploads stalled:\n" << other.raw;
  EXPECT_LT(std::chrono::steady_clock::now() - since, 10s);
  // The stalled ones are answered with why, and their files go.
  for (auto& s : stalled) {
    std::string raw;
    std::error_code ec;
    asio::read(*s, asio::dynamic_buffer(raw), ec);  // until the server closes, 15 s without a byte
    const HttpAnswer answer = parse_answer(raw);
    if (answer.status == 429) continue;  // the third, if its sender's address may upload two at once
    EXPECT_EQ(answer.status, 400) << raw;
    EXPECT_NE(answer.error().find("stalled"), std::string::npos) << raw;
  }
  EXPECT_TRUE(eventually([&] { return files_under(dir / "data" / "uploads") == 0; })) << "a stalled upload left its files";
}
