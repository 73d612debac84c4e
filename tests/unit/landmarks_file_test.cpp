// The landmarks file that travels with a neutral photo: round trip, and every malformed form
// refused with a reason.
#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/face/landmarks_file.hpp"
#include "test_data.hpp"

using namespace inkwire;
namespace fs = std::filesystem;

namespace {

FaceLandmarks some_landmarks() {
  FaceLandmarks l;
  for (size_t i = 0; i < l.size(); ++i) l[i] = {100.25f + float(i), 200.5f + std::sin(float(i)) * 30.0f};
  return l;
}

std::string refusal(const std::string& json) {
  return test::error_of([&] { parse_landmarks(json); });
}

}  // namespace

TEST(LandmarksFileTest, RoundTripsThroughAFile) {
  const fs::path file = test::scratch_dir() / "landmarks-file-test.json";
  save_landmarks(file, some_landmarks());
  const FaceLandmarks back = load_landmarks(file);
  for (size_t i = 0; i < back.size(); ++i) {
    EXPECT_FLOAT_EQ(back[i].x, some_landmarks()[i].x);
    EXPECT_FLOAT_EQ(back[i].y, some_landmarks()[i].y);
  }
  EXPECT_FALSE(fs::exists(file.string() + ".partial"));
}

TEST(LandmarksFileTest, MalformedFilesAreRefusedWithAReason) {
  const std::string good = landmarks_to_json(some_landmarks());
  EXPECT_EQ(refusal(good), "");
  EXPECT_NE(refusal("").find("not a JSON object"), std::string::npos);
  EXPECT_NE(refusal(good.substr(0, good.size() / 2)).find("not a JSON object"), std::string::npos);  // truncated
  EXPECT_NE(refusal(R"({"format": "other", "points": []})").find("format"), std::string::npos);
  EXPECT_NE(refusal(R"({"format": "inkwire-face-landmarks", "points": [[1, 2]]})").find("68"), std::string::npos);
  // Found by fuzz_landmarks: a "format" that is not a string threw a JSON type error, not an
  // inkwire::Error, and ended the program.
  EXPECT_NE(refusal(R"({"format": [[1, 2]], "points": []})").find("format"), std::string::npos);
  std::string bad_point = good;
  bad_point.replace(bad_point.find('['), 2, "[\"a\",");  // first point's x is a string
  EXPECT_NE(refusal(bad_point), "");
  std::string huge = good;
  huge.replace(huge.find("[[") + 2, 6, "1e30");
  EXPECT_NE(refusal(huge).find("out of range"), std::string::npos) << refusal(huge);

  const fs::path big = test::scratch_dir() / "landmarks-file-too-big.json";
  std::ofstream(big) << std::string(100000, ' ') << good;
  EXPECT_THROW(load_landmarks(big), Error);
  EXPECT_THROW(load_landmarks(test::scratch_dir() / "no-such-landmarks.json"), Error);
}
