// Face detection and 68-point landmarks on real photos packaged by Debian (libdlib19.1's example
// faces, with hand-placed landmarks in testing_with_face_landmarks.xml) through dlib's model
// from libdlib-data. Skips with a message when either package is absent.
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/image.hpp"
#include "server/face/face_analyzer.hpp"

namespace inkwire {
namespace {

namespace fs = std::filesystem;
const fs::path kExamples = "/usr/share/doc/libdlib19.1/examples/faces";

struct LabelledFace {
  fs::path image;
  FaceBox box;
  FaceLandmarks landmarks;
};

// The <image><box><part .../></box></image> entries of a dlib imglab file.
std::vector<LabelledFace> read_labelled_faces(const fs::path& xml) {
  std::ifstream in(xml);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  std::vector<LabelledFace> faces;
  const std::regex image_re(R"(<image file='([^']+)')"), box_re(R"(<box top='(-?\d+)' left='(-?\d+)' width='(\d+)' height='(\d+)')"),
      part_re(R"(<part name='(\d+)' x='(-?\d+)' y='(-?\d+)'/>)");
  fs::path current;
  std::istringstream lines(s);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (std::regex_search(line, m, image_re)) current = xml.parent_path() / m[1].str();
    else if (std::regex_search(line, m, box_re)) {
      const int top = std::stoi(m[1]), left = std::stoi(m[2]), w = std::stoi(m[3]), h = std::stoi(m[4]);
      faces.push_back({current, {left, top, left + w - 1, top + h - 1}, {}});
    } else if (std::regex_search(line, m, part_re) && !faces.empty()) {
      faces.back().landmarks.at(size_t(std::stoi(m[1]))) = {std::stof(m[2]), std::stof(m[3])};
    }
  }
  return faces;
}

float overlap(const FaceBox& a, const FaceBox& b) {  // intersection over union
  const int w = std::min(a.right, b.right) - std::max(a.left, b.left) + 1, h = std::min(a.bottom, b.bottom) - std::max(a.top, b.top) + 1;
  if (w <= 0 || h <= 0) return 0;
  const float inter = float(w) * float(h);
  return inter / (float(a.width()) * float(a.height()) + float(b.width()) * float(b.height()) - inter);
}

class FaceLandmarksTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!fs::exists(kDefaultFaceModel) || !fs::exists(kExamples / "testing_with_face_landmarks.xml")) return;
    // The example faces are small (37-109 px): one upsampling step lets the detector see them.
    analyzer_ = std::make_unique<FaceAnalyzer>(FaceAnalyzerOptions{.detect_every = 1, .detect_width = 0, .upsample = 1});
  }
  static void TearDownTestSuite() { analyzer_.reset(); }
  void SetUp() override {
    if (!analyzer_) GTEST_SKIP() << "needs Debian's libdlib-data (" << kDefaultFaceModel << ") and libdlib19.1's example faces";
  }
  static std::unique_ptr<FaceAnalyzer> analyzer_;
};
std::unique_ptr<FaceAnalyzer> FaceLandmarksTest::analyzer_;

TEST_F(FaceLandmarksTest, LandmarksMatchTheHandPlacedOnesOnRealPhotos) {
  const auto faces = read_labelled_faces(kExamples / "testing_with_face_landmarks.xml");
  ASSERT_GE(faces.size(), 20u);
  float sum = 0, worst = 0;
  for (const LabelledFace& face : faces) {
    const float error = mean_landmark_error(analyzer_->landmarks_in(load_image(face.image), face.box), face.landmarks);
    sum += error;
    worst = std::max(worst, error);
  }
  // Bound: mean error 0.05 inter-ocular distances (eye centre to eye centre), worst face 0.12.
  const float mean = sum / float(faces.size());
  std::cout << "landmarks on " << faces.size() << " faces: mean error " << mean << ", worst " << worst << " inter-ocular\n";
  EXPECT_LT(mean, 0.05f);
  EXPECT_LT(worst, 0.12f);
}

TEST_F(FaceLandmarksTest, DetectorFindsTheLabelledFaces) {
  const auto faces = read_labelled_faces(kExamples / "testing_with_face_landmarks.xml");
  std::map<fs::path, std::vector<FaceBox>> found;
  int matched = 0;
  for (const LabelledFace& face : faces) {
    if (!found.count(face.image)) found[face.image] = analyzer_->detect(load_image(face.image));
    for (const FaceBox& box : found[face.image]) matched += overlap(box, face.box) > 0.4f ? 1 : 0;
  }
  std::cout << "detector: " << matched << " of " << faces.size() << " labelled faces found\n";
  EXPECT_GE(float(matched), 0.8f * float(faces.size()));
}

TEST_F(FaceLandmarksTest, TracksBetweenDetections) {
  FaceAnalyzer tracker({.detect_every = 5, .detect_width = 320, .upsample = 0});
  const Image photo = load_image(kExamples / "Tom_Cruise_avp_2014_4.jpg");
  const auto first = tracker.analyse(photo);
  ASSERT_TRUE(first.has_value());
  EXPECT_TRUE(first->detected);
  const auto second = tracker.analyse(photo);
  ASSERT_TRUE(second.has_value());
  EXPECT_FALSE(second->detected);
  EXPECT_EQ(tracker.last_detect_ms(), 0.0);
  EXPECT_LT(mean_landmark_error(second->landmarks, first->landmarks), 0.03f);
}

TEST_F(FaceLandmarksTest, BadInputGetsAClearError) {
  EXPECT_THROW(analyzer_->analyse(Image{}), Error);
  Image blank(64, 48);
  EXPECT_FALSE(analyzer_->analyse(blank).has_value());
  EXPECT_THROW(FaceAnalyzer({.detect_every = 1, .detect_width = 0, .upsample = 0, .model = "/nonexistent/model.dat"}), Error);
  const fs::path junk = fs::temp_directory_path() / "inkwire-junk-model.dat";
  std::ofstream(junk) << "not a model";
  EXPECT_THROW(FaceAnalyzer({.detect_every = 1, .detect_width = 0, .upsample = 0, .model = junk.string()}), Error);
  fs::remove(junk);
}

}  // namespace
}  // namespace inkwire
