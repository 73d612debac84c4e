// Every shader program, in every variant the renderers compile, is valid GLSL 3.30 core (native)
// and GLSL ES 3.00 (WebGL2) with the header each target puts first (SPEC W5: one source per
// effect). Checked with glslang, the Khronos reference compiler, so no GL context is needed and
// a construct only desktop GL has (storage buffers, noperspective, sampler arrays indexed by a
// variable) fails here before any browser sees it.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "client/gl/resources.hpp"
#include "tests/unit/test_data.hpp"

namespace inkwire {
namespace {

struct ProgramVariant {
  std::vector<std::string> stages;
  std::vector<std::string> defines;
};

// The programs the renderers make (Program::from_files) and their variants.
std::vector<ProgramVariant> every_program() {
  std::vector<ProgramVariant> all = {
      {{"backdrop/fullscreen.vert", "backdrop/paper.frag"}, {}},
      {{"comic/edges.vert", "comic/edges.frag"}, {}},
      {{"comic/outline.vert", "comic/outline.frag"}, {}},
      {{"common/depth_only.vert", "common/depth_only.frag"}, {}},
      {{"common/packed_depth.vert", "common/packed_depth.frag"}, {}},
      {{"default/mesh.vert", "default/mesh.frag"}, {}},
      {{"default/mesh.vert", "default/mesh.frag"}, {"TEXTURED 1"}},
      {{"hidden-line/lines.vert", "hidden-line/lines.frag"}, {}},
      {{"painterly/rect.vert", "painterly/rect.frag"}, {}},
      {{"sketch/segments.vert", "sketch/strokes.frag"}, {"WIDE_LINE"}},
      {{"sketch/strokes.vert", "sketch/strokes.frag"}, {"WIDE_LINE"}},
      {{"sketch/smudge.vert", "sketch/smudge.frag"}, {}},
      {{"sketch/textured.vert", "sketch/textured.frag"}, {}},
      {{"tween/composite.vert", "tween/composite.frag"}, {}},
      {{"tween/warp.vert", "tween/warp.frag"}, {}},
  };
  for (const char* extended : {"", "EXTENDED 1"})
    for (const char* textured : {"", "TEXTURED 1"}) {
      ProgramVariant v{{"comic/comic.vert", "comic/comic.frag"}, {}};
      for (const char* d : {extended, textured})
        if (*d) v.defines.push_back(d);
      all.push_back(v);
    }
  for (const char* kind : {"", "THRESHOLD 1", "VOLUME 1"})
    for (const char* under : {"", "UNDER_PAPER 1", "UNDER_COLOUR 1"}) {
      ProgramVariant v{{"hatching/hatch.vert", "hatching/hatch.frag"}, {}};
      for (const char* d : {kind, under})
        if (*d) v.defines.push_back(d);
      all.push_back(v);
    }
  for (int mask = 0; mask < 16; ++mask) {
    ProgramVariant v{{"painterly/brush.vert", "painterly/brush.frag"}, {}};
    const char* names[] = {"SOFT_EDGES 1", "WET_EDGES 1", "GRANULATION 1", "GLAZE 1"};
    for (int bit = 0; bit < 4; ++bit)
      if (mask & (1 << bit)) v.defines.push_back(names[bit]);
    all.push_back(v);
  }
  for (int n = 1; n <= 3; ++n) {
    all.push_back({{"tween/blend.vert", "tween/blend.frag"}, {"SAMPLES " + std::to_string(n)}});
    all.push_back({{"tween/blend.vert", "tween/blend.frag"}, {"SAMPLES " + std::to_string(n), "MATTE", "MATTE_RANGE 16.0", "BLEED 1.5"}});
  }
  return all;
}

const std::string kCore = "#version 330 core\n";
const std::string kEs =
    "#version 300 es\nprecision highp float;\nprecision highp int;\n"
    "precision highp sampler2D;\nprecision highp sampler2DArray;\nprecision highp sampler3D;\n";

// glslang's output when compiling and linking the stages after `header`, or "" when they pass.
std::string compile_and_link(const ProgramVariant& program, const std::string& header, const std::filesystem::path& dir) {
  std::string command = "glslangValidator -l";
  for (const std::string& stage : program.stages) {
    const std::filesystem::path file = dir / std::filesystem::path(stage).filename();
    std::ofstream out(file);
    out << header;
    for (const std::string& d : program.defines) out << "#define " << d << "\n";
    out << gl::shader_source(stage);
    command += " " + file.string();
  }
  command += " 2>&1";
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return "cannot run glslangValidator";
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe)) output += buffer;
  return pclose(pipe) == 0 ? "" : output;
}

TEST(ShaderTargetsTest, EveryProgramCompilesAsGlsl330CoreAndAsGlslEs300) {
  if (std::system("glslangValidator --version > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "glslangValidator is not installed (Debian package glslang-tools, in scripts/packages.txt)";
  // The native header is the one the library really uses; the ES one is what the WebGL2 build uses.
#ifndef __EMSCRIPTEN__
  ASSERT_EQ(gl::shader_header(), kCore);
#endif
  const std::filesystem::path dir = test::scratch_dir();
  size_t checked = 0;
  for (const ProgramVariant& program : every_program())
    for (const auto& [target, header] : {std::pair{"GLSL 3.30 core", kCore}, std::pair{"GLSL ES 3.00", kEs}}) {
      std::string defines;
      for (const std::string& d : program.defines) defines += " " + d;
      EXPECT_EQ(compile_and_link(program, header, dir), "") << program.stages[0] << " + " << program.stages[1] << " [" << defines << " ] as " << target;
      ++checked;
    }
  EXPECT_GT(checked, 80u);
}

}  // namespace
}  // namespace inkwire
