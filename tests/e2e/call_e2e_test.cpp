// A call end to end on 127.0.0.1 (SPEC F7-F13): two members publish their own face and voice
// to a real inkwire-server, a third listens. The publishers are SessionClients sending what a
// member's client sends (a neutral photo, face crops as JPEG, Opus voice); the server analyses
// the crops and relays the voice. Reads the Yale faces' development subjects from
// ../shared/data/yalefaces when they are there, else libdlib's example photo with no change of
// expression (then the expression check is skipped with a message).
#include <array>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "client/call/face_crop.hpp"
#include "client/net/session_client.hpp"
#include "common/image.hpp"
#include "e2e_support.hpp"
#include "protocol/face_versions.hpp"

using namespace inkwire;
using namespace inkwire::e2e;

TEST(CallE2ETest, MembersAreSeenAndHeardAsThemselvesAndBadInputIsDroppedAndCounted) {
  if (!fs::exists(kFaceModel) || !fs::exists(kDlibPhoto)) GTEST_SKIP() << "libdlib-data's model or libdlib-dev's example photo is missing";
  const bool yale = fs::exists(kYale / "subject02_normal.png");
  if (!yale) std::printf("../shared/data/yalefaces is absent: the photo of libdlib's examples stands in, and the smile is not checked\n");
  const fs::path dir = output_dir("call");
  ServerUnderTest server(dir, {{"http", "127.0.0.1:0"}, {"sessions", {{{"name", "call"}, {"kind", "conference"}}}}});
  const Image neutral = yale ? load_image(kYale / "subject02_normal.png") : load_image(kDlibPhoto);
  const Image happy = yale ? load_image(kYale / "subject02_happy.png") : neutral;

  SessionClient ada(server.address(), "Ada"), grace(server.address(), "Grace"), listener(server.address(), "Listener");
  for (SessionClient* c : {&ada, &grace, &listener}) c->join("call", "");
  ada.send(protocol::Publish{.camera = true, .microphone = true});
  grace.send(protocol::Publish{.camera = false, .microphone = true});
  ada.send(protocol::NeutralPhoto{.jpeg = encode_image(neutral, "jpg", 90)});

  // The roster lists all three, Ada's photo and landmarks among her assets, fetched by hash.
  ASSERT_TRUE(eventually([&] {
    const auto r = listener.roster();
    return r.members.size() == 3 && named(r, "Ada") && named(r, "Ada")->assets.size() == 2;
  })) << "roster of " << listener.roster().members.size();
  const protocol::Roster roster = listener.roster();
  const uint16_t ada_number = named(roster, "Ada")->member, grace_number = named(roster, "Grace")->member;
  EXPECT_EQ(roster.you, named(roster, "Listener")->member);
  EXPECT_TRUE(named(roster, "Ada")->camera);
  EXPECT_FALSE(named(roster, "Grace")->camera);
  AssetCache cache(dir / "cache");
  const fs::path photo = listener.fetch_asset(named(roster, "Ada")->assets[0], cache);
  EXPECT_EQ(load_image(photo).width, neutral.width);

  // Ada's camera: neutral for a second, then smiling, 10 crops a second (whole frames: the
  // server has not found her face yet, then around where it did). Both speak meanwhile.
  const auto voice = voice_packets(100);
  int sent_voice = 0;
  for (int frame = 0; frame < 40; ++frame) {
    const Image& shown = frame < 10 ? neutral : happy;
    protocol::FaceCrop crop{.time_ms = uint32_t(frame * 100), .frame_width = uint16_t(shown.width), .frame_height = uint16_t(shown.height),
                            .x = 0, .y = 0, .width = uint16_t(shown.width), .height = uint16_t(shown.height), .jpeg = {}};
    if (const auto region = ada.face_region(); region && region->found) {
      crop.x = region->x, crop.y = region->y, crop.width = region->width, crop.height = region->height;
      crop.jpeg = encode_image(resized(cropped(shown, crop.x, crop.y, crop.width, crop.height), 160, 160), "jpg", 90);
    } else {
      const PictureSize whole = search_picture_size(shown.width, shown.height);  // at most 320 a side (SPEC)
      crop.jpeg = encode_image(resized(shown, whole.width, whole.height), "jpg", 90);
    }
    ada.send(crop);
    for (int k = 0; k < 5 && sent_voice < int(voice.size()); ++k, ++sent_voice) {
      ada.send(protocol::VoiceFrame{.member = 0, .time_ms = uint32_t(sent_voice * 20), .opus = voice[size_t(sent_voice)]});
      grace.send(protocol::VoiceFrame{.member = 999, .time_ms = uint32_t(sent_voice * 20), .opus = voice[size_t(sent_voice)]});
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  ASSERT_TRUE(ada.face_region() && ada.face_region()->found) << "the server never found Ada's face";
  ASSERT_TRUE(eventually([&] { return listener.member_faces().count(ada_number); }));
  // The one code its layers say most (what a peer of protocol version 7 is sent).
  const protocol::MemberFace ada_face = protocol::member_face_of(listener.member_faces().at(ada_number));
  EXPECT_EQ(ada_face.source, protocol::FaceSource::Camera);
  if (yale) {
    EXPECT_EQ(expression_from_code(ada_face.expression.code), Expression::Smile) << "neutral then smile arrives as " << int(ada_face.expression.code);
  }
  // Grace has no camera: her voice moves her mouth.
  ASSERT_TRUE(listener.member_faces().count(grace_number));
  EXPECT_EQ(listener.member_faces().at(grace_number).source, protocol::FaceSource::Voice);
  const int mouth = int(listener.member_faces().at(grace_number).mouth.expression);
  EXPECT_TRUE(mouth >= int(Expression::VisemeClosed) && mouth <= int(Expression::VisemeRound)) << mouth;

  // Every voice packet came through, stamped with its sender's own number (Grace said 999): what
  // is in flight lands (or the wait ends and the counts say what did).
  int from_ada = 0, from_grace = 0;
  size_t heard = 0;
  eventually([&] {
    for (const auto& [v, arrived] : listener.take_voice()) from_ada += v.member == ada_number, from_grace += v.member == grace_number, ++heard;
    return from_ada >= sent_voice && from_grace >= sent_voice;
  });
  EXPECT_GE(from_ada, sent_voice - 2);  // the first packets come before the server heard anyone speak
  EXPECT_GE(from_grace, sent_voice - 2);
  EXPECT_EQ(size_t(from_ada + from_grace), heard) << "a packet under another member's number";
  bool speaking = false;
  for (const auto& m : listener.roster().members) speaking |= m.speaking;
  EXPECT_TRUE(speaking);

  // Bad input is dropped and counted; a member may not send session-wide expression codes; the
  // listener is not disturbed.
  // (Each is sent again, a quarter of a second apart, until the server counts it: on a loaded
  // machine the server may read the crops above in a burst, and a bad one that comes while their
  // allowance is spent is counted as too frequent instead.)
  const auto counted = [&](const std::string& reason) {
    return metrics_of(server).find("inkwire_call_dropped_total{reason=\"" + reason + "\"}") != std::string::npos;
  };
  const auto dropped_as = [&](const std::string& reason, const protocol::Message& bad) {
    auto sent = std::chrono::steady_clock::now() - std::chrono::seconds(1);
    return eventually([&] {
      if (std::chrono::steady_clock::now() - sent > std::chrono::milliseconds(250)) ada.send(bad), sent = std::chrono::steady_clock::now();
      return counted(reason);
    }, std::chrono::seconds(30));
  };
  EXPECT_TRUE(dropped_as("crop-not-jpeg", protocol::FaceCrop{.time_ms = 5000, .frame_width = 64, .frame_height = 64, .x = 0, .y = 0, .width = 64,
                                                              .height = 64, .jpeg = protocol::Bytes{0x89, 'P', 'N', 'G', 0, 0}}))
      << metrics_of(server);
  EXPECT_TRUE(dropped_as("voice-too-large", protocol::VoiceFrame{.member = 0, .time_ms = 5000, .opus = protocol::Bytes(600, 0x11)})) << metrics_of(server);
  EXPECT_TRUE(dropped_as("voice-not-opus", protocol::VoiceFrame{.member = 0, .time_ms = 5020, .opus = protocol::Bytes{0x03, 0x00}})) << metrics_of(server);
  ada.send(protocol::ExpressionCode{.code = 4, .intensity = 255});
  ASSERT_TRUE(eventually([&] { return ada.refusals() == 1; }));
  EXPECT_NE(ada.refusal().find("only as themselves"), std::string::npos) << ada.refusal();
  EXPECT_TRUE(listener.connected() && ada.connected());

  // Leaving takes the member out of everyone's roster.
  grace.send(protocol::Leave{});
  ASSERT_TRUE(eventually([&] { return listener.roster().members.size() == 2 && !named(listener.roster(), "Grace"); }));
}

// Each refusal of SPEC F13 as a member meets it: crops too frequent or too large are dropped and
// counted, a camera that never shows a face is reported as such (the member keeps its neutral
// photo), and a member who floods is closed with the reason; the others carry on.
TEST(CallE2ETest, FloodsOversizedCropsAndAFacelessCameraAreRefusedOrReportedWhileOthersCarryOn) {
  if (!fs::exists(kFaceModel) || !fs::exists(kDlibPhoto)) GTEST_SKIP() << "libdlib-data's model or libdlib-dev's example photo is missing";
  const fs::path dir = output_dir("call-refusals");
  ServerUnderTest server(dir, {{"http", "127.0.0.1:0"}, {"sessions", {{{"name", "call"}, {"kind", "conference"}}}}});
  SessionClient blank(server.address(), "Blank"), mallory(server.address(), "Mallory"), listener(server.address(), "Listener");
  for (SessionClient* c : {&blank, &mallory, &listener}) c->join("call", "");
  blank.send(protocol::Publish{.camera = true, .microphone = false});

  // A camera pointed at a wall: crops without a face, 10 a second, as a camera keeps sending
  // (the server reports it after 3 s of them; a busy analyst may take a little longer).
  Image wall(160, 120);
  for (size_t i = 0; i < wall.pixels.size(); ++i) wall.pixels[i] = i % 4 == 3 ? 255 : 180;
  const protocol::Bytes wall_jpeg = encode_image(wall, "jpg", 80);
  const auto reported = [&] {
    const protocol::CallMember* m = named(listener.roster(), "Blank");
    return m && !m->face_found;
  };
  for (int k = 0; k < 150 && !reported(); ++k) {
    blank.send(protocol::FaceCrop{.time_ms = uint32_t(k * 100), .frame_width = 160, .frame_height = 120, .x = 0, .y = 0, .width = 160,
                                  .height = 120, .jpeg = wall_jpeg});
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(reported()) << "the faceless camera is not reported after 15 s of crops";
  EXPECT_FALSE(blank.face_region() && blank.face_region()->found);

  // Thirty crops at once (a second's allowance is 15): some are dropped as too frequent.
  const auto dropped_for = [&](const std::string& reason) {
    return metrics_of(server).find("inkwire_call_dropped_total{reason=\"" + reason + "\"}") != std::string::npos;
  };
  for (int k = 0; k < 30; ++k)
    blank.send(protocol::FaceCrop{.time_ms = 5000, .frame_width = 160, .frame_height = 120, .x = 0, .y = 0, .width = 160, .height = 120, .jpeg = wall_jpeg});
  ASSERT_TRUE(eventually([&] { return dropped_for("crop-too-frequent"); })) << metrics_of(server);
  // One of 40 KB: dropped as too large once the allowance has come back (sent again until the
  // server counts it; before that it may still count as too frequent).
  protocol::Bytes big(40 * 1024, 0x42);
  big[0] = 0xff, big[1] = 0xd8, big[2] = 0xff;
  auto sent_big = std::chrono::steady_clock::now() - std::chrono::seconds(1);
  ASSERT_TRUE(eventually([&] {
    if (std::chrono::steady_clock::now() - sent_big > std::chrono::milliseconds(250)) {  // well within the allowance
      blank.send(protocol::FaceCrop{.time_ms = 6000, .frame_width = 160, .frame_height = 120, .x = 0, .y = 0, .width = 160, .height = 120, .jpeg = big});
      sent_big = std::chrono::steady_clock::now();
    }
    return dropped_for("crop-too-large");
  }, std::chrono::seconds(30))) << metrics_of(server);

  // Mallory floods: two thousand voice packets as fast as the socket takes them.
  const auto voice = voice_packets(1);
  for (int k = 0; k < 2000; ++k) mallory.send(protocol::VoiceFrame{.member = 0, .time_ms = uint32_t(k), .opus = voice[0]});
  ASSERT_TRUE(eventually([&] { return !mallory.connected(); })) << "the flood was not cut off";
  EXPECT_NE(mallory.last_error().find("flooding"), std::string::npos) << mallory.last_error();

  const std::string metrics = metrics_of(server);
  for (const char* reason : {"crop-too-frequent", "crop-too-large", "voice-too-frequent"})
    EXPECT_NE(metrics.find(std::string("inkwire_call_dropped_total{reason=\"") + reason + "\"}"), std::string::npos) << reason << "\n" << metrics;
  EXPECT_TRUE(listener.connected() && blank.connected());
  EXPECT_TRUE(eventually([&] { return !named(listener.roster(), "Mallory"); })) << "the flooder stays in the roster";
}

// Clients of protocol versions 7 (before rooms) and 8 (before faces came in layers) still join a
// call and read every frame they are sent (SPEC "Versioning"): a member's face comes to them as
// member-face, one code, never as member-layers, which their decoders would refuse; version 7's
// join has no open_room and its rosters no host or lock. Read here as raw frames, by the bytes
// each version's codec writes and reads.
class CallOldClientE2ETest : public ::testing::TestWithParam<uint16_t> {};

TEST_P(CallOldClientE2ETest, IsSentMemberFacesNotLayers) {
  if (!fs::exists(kFaceModel) || !fs::exists(kDlibPhoto)) GTEST_SKIP() << "libdlib-data's model or libdlib-dev's example photo is missing";
  const uint16_t version = GetParam();
  const fs::path dir = output_dir("call-version-" + std::to_string(version));
  ServerUnderTest server(dir, {{"http", "127.0.0.1:0"}, {"sessions", {{{"name", "call"}, {"kind", "conference"}}}}});
  asio::io_context io;
  asio::ip::tcp::socket old(io);
  old.connect(server.endpoint());
  const protocol::Bytes hello = protocol::encode(protocol::Hello{.magic = protocol::kMagic, .version = version, .client_name = "old"});
  protocol::Bytes join = protocol::encode(protocol::Join{.session = "call", .token = ""});
  if (version < 8) {  // session and token only
    join.pop_back();
    const auto payload = uint32_t(join.size() - protocol::kHeaderBytes);
    for (int i = 0; i < 4; ++i) join[size_t(i)] = uint8_t(payload >> (8 * i));
  }
  asio::write(old, asio::buffer(hello));
  asio::write(old, asio::buffer(join));
  std::mutex mutex;  // guards what the reader saw
  std::map<protocol::MessageType, int> seen;
  std::optional<uint16_t> welcomed;
  std::vector<std::string> unreadable;  // frames this version's reader would refuse
  std::atomic<bool> reading{true};
  std::thread reader([&] {
    protocol::Bytes pending;
    std::array<uint8_t, 4096> buffer{};
    std::error_code ec;
    while (reading) {
      const size_t n = old.read_some(asio::buffer(buffer), ec);
      if (ec) return;
      pending.insert(pending.end(), buffer.begin(), buffer.begin() + long(n));
      while (pending.size() >= protocol::kHeaderBytes) {
        const protocol::FrameHeader h = protocol::parse_header(pending.data());
        if (pending.size() < protocol::kHeaderBytes + h.length) break;
        protocol::Bytes payload(pending.begin() + protocol::kHeaderBytes, pending.begin() + long(protocol::kHeaderBytes + h.length));
        pending.erase(pending.begin(), pending.begin() + long(protocol::kHeaderBytes + h.length));
        std::lock_guard lock(mutex);
        ++seen[h.type];
        // Version 7's roster ends before the host and lock this version's reader wants after it.
        if (version < 8 && h.type == protocol::MessageType::Roster) payload.insert(payload.end(), {0, 0, 0});
        try {
          const protocol::Message m = protocol::decode(h.type, payload.data(), payload.size());
          if (const auto* w = std::get_if<protocol::Welcome>(&m)) welcomed = w->version;
        } catch (const protocol::ProtocolError& e) {
          unreadable.push_back(std::string(protocol::name_of(h.type)) + ": " + e.what());
        }
      }
    }
  });
  SessionClient ada(server.address(), "Ada");
  ada.join("call", "");
  ada.send(protocol::Publish{.camera = true, .microphone = false});
  const Image photo = load_image(kDlibPhoto);
  ada.send(protocol::NeutralPhoto{.jpeg = encode_image(photo, "jpg", 90)});
  for (int frame = 0; frame < 30; ++frame) {
    protocol::FaceCrop crop{.time_ms = uint32_t(frame * 100), .frame_width = uint16_t(photo.width), .frame_height = uint16_t(photo.height),
                            .x = 0, .y = 0, .width = uint16_t(photo.width), .height = uint16_t(photo.height), .jpeg = {}};
    const PictureSize whole = search_picture_size(photo.width, photo.height);
    crop.jpeg = encode_image(resized(photo, whole.width, whole.height), "jpg", 90);
    ada.send(crop);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  const bool faced = eventually([&] {
    std::lock_guard lock(mutex);
    return seen[protocol::MessageType::MemberFace] > 0;
  });
  reading = false;
  old.shutdown(asio::ip::tcp::socket::shutdown_both);
  reader.join();
  std::lock_guard lock(mutex);
  EXPECT_EQ(welcomed, std::optional<uint16_t>(version)) << "the welcome says the version it is spoken to in";
  EXPECT_TRUE(faced) << "no member-face reached the client of version " << version;
  EXPECT_EQ(seen[protocol::MessageType::MemberLayers], 0) << "a member-layers, which version " << version << " cannot read";
  EXPECT_EQ(seen[protocol::MessageType::Error], 0) << "its join was refused";
  EXPECT_GT(seen[protocol::MessageType::Roster], 0);
  EXPECT_TRUE(unreadable.empty()) << unreadable.front();
}

INSTANTIATE_TEST_SUITE_P(Versions, CallOldClientE2ETest, ::testing::Values(uint16_t(7), uint16_t(8)),
                         [](const auto& info) { return "Version" + std::to_string(info.param); });

// A smile while speaking (SPEC F21): the camera shows a still smile while the member talks in
// syllables; the listener's faces keep the smile as their expression while their mouth opens and
// closes with the voice (a camera's mouth that holds still while the voice speaks is not the
// camera's to say). Needs the Yale faces (a smile to read).
TEST(CallE2ETest, ASmileWhileSpeakingKeepsTheSmileWhileTheVoiceMovesTheMouth) {
  if (!fs::exists(kFaceModel) || !fs::exists(kYale / "subject02_happy.png")) GTEST_SKIP() << "needs libdlib-data's model and ../shared/data/yalefaces";
  const fs::path dir = output_dir("call-smile-speaking");
  ServerUnderTest server(dir, {{"http", "127.0.0.1:0"}, {"sessions", {{{"name", "call"}, {"kind", "conference"}}}}});
  const Image neutral = load_image(kYale / "subject02_normal.png"), happy = load_image(kYale / "subject02_happy.png");
  SessionClient ada(server.address(), "Ada"), listener(server.address(), "Listener");
  for (SessionClient* c : {&ada, &listener}) c->join("call", "");
  ada.send(protocol::Publish{.camera = true, .microphone = true});
  ada.send(protocol::NeutralPhoto{.jpeg = encode_image(neutral, "jpg", 90)});
  ASSERT_TRUE(eventually([&] { return named(listener.roster(), "Ada") && named(listener.roster(), "Ada")->assets.size() == 2; }));
  const uint16_t number = named(listener.roster(), "Ada")->member;
  // Syllables: 200 ms of voice, 160 ms of silence.
  const auto loud = voice_packets(10), quiet = voice_packets(8, 0.0f);
  std::vector<protocol::Bytes> voice;
  while (voice.size() < 300) voice.insert(voice.end(), loud.begin(), loud.end()), voice.insert(voice.end(), quiet.begin(), quiet.end());
  std::vector<protocol::MemberLayers> faces;
  int sent_voice = 0;
  for (int frame = 0; frame < 60; ++frame) {
    const Image& shown = frame < 10 ? neutral : happy;
    protocol::FaceCrop crop{.time_ms = uint32_t(frame * 100), .frame_width = uint16_t(shown.width), .frame_height = uint16_t(shown.height), .x = 0,
                            .y = 0, .width = uint16_t(shown.width), .height = uint16_t(shown.height), .jpeg = {}};
    if (const auto region = ada.face_region(); region && region->found) {
      crop.x = region->x, crop.y = region->y, crop.width = region->width, crop.height = region->height;
      crop.jpeg = encode_image(resized(cropped(shown, crop.x, crop.y, crop.width, crop.height), kFaceVideoSide, kFaceVideoSide), "jpg", 90);
    } else {
      crop.jpeg = encode_image(shown, "jpg", 90);
    }
    ada.send(crop);
    for (int k = 0; k < 5; ++k, ++sent_voice) {
      ada.send(protocol::VoiceFrame{.member = 0, .time_ms = uint32_t(sent_voice * 20), .opus = voice[size_t(sent_voice)]});
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    for (const auto& f : listener.take_member_faces())
      if (f.member == number) faces.push_back(f);
  }
  // From the moment the smile is read on.
  const auto smiling = std::find_if(faces.begin(), faces.end(), [](const auto& f) { return f.expression.expression == Expression::Smile; });
  ASSERT_NE(smiling, faces.end()) << "Ada's smile never came (" << faces.size() << " faces)";
  int smile = 0, open = 0, closed = 0, n = 0;
  std::string mouths;
  for (auto it = smiling; it != faces.end(); ++it, ++n) {
    smile += it->expression.expression == Expression::Smile;
    open += is_viseme(it->mouth.expression) && it->mouth.expression != Expression::VisemeClosed;
    closed += it->mouth.expression == Expression::VisemeClosed;
    mouths += std::string(" ") + name_of(it->mouth.expression);
  }
  EXPECT_GE(n, 8) << "too few faces:" << mouths;
  EXPECT_GE(smile, n * 8 / 10) << smile << " of " << n << " keep the smile";
  EXPECT_GE(open, 2) << "the mouth never opened with the voice:" << mouths;
  EXPECT_GE(closed, 2) << "the mouth never closed between syllables:" << mouths;
}
