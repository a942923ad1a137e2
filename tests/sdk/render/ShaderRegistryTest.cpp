// SPDX-License-Identifier: MIT
// The SDK's shader registry (what an out-of-tree renderer registers its GLSL through) and
// the headless context every renderer test runs in.
#include <volpost/render/HeadlessContext.hpp>
#include <volpost/render/ShaderLibrary.hpp>

#include <gtest/gtest.h>

#include <map>
#include <memory>

using namespace volpost;

TEST(ShaderRegistry, IncludesResolveUnderTheIncludersPrefixFirst) {
  static const std::map<std::string, std::string_view> shared = {{"common/piece.glsl", "// shared piece\n"}};
  static const std::map<std::string, std::string_view> mine = {
      {"main.comp", "#version 450 core\n#include \"common/piece.glsl\"\n#include \"common/own.glsl\"\n"},
      {"common/own.glsl", "// own piece\n#include \"common/piece.glsl\"\n"},
      {"common/piece.glsl", "// my piece\n"}};
  gl::registerShaders("registrytest_shared", shared);
  gl::registerShaders("registrytest", mine);
  const std::string source = gl::shaderSource("registrytest/main.comp");
  EXPECT_NE(source.find("// my piece"), std::string::npos) << source;
  EXPECT_EQ(source.find("// shared piece"), std::string::npos) << "the includer's own file wins";
  EXPECT_NE(source.find("// own piece"), std::string::npos);
  EXPECT_EQ(source.find("// my piece"), source.rfind("// my piece")) << "each file is included once";
}

TEST(ShaderRegistry, TwoOwnersOfOneNameAreRefusedAndUnknownNamesNamed) {
  static const std::map<std::string, std::string_view> a = {{"x.frag", "// a\n"}};
  static const std::map<std::string, std::string_view> b = {{"x.frag", "// b\n"}};
  gl::registerShaders("registrytest_owner", a);
  EXPECT_NO_THROW(gl::registerShaders("registrytest_owner", a)) << "the same text again is fine";
  EXPECT_THROW(gl::registerShaders("registrytest_owner", b), std::logic_error);
  try {
    (void)gl::shaderSource("registrytest_owner/missing.frag");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("registrytest_owner/missing.frag"), std::string::npos);
  }
}

TEST(HeadlessContext, IsOpenGL45Core) {
  std::unique_ptr<HeadlessContext> context;
  try {
    context = std::make_unique<HeadlessContext>();
  } catch (const std::exception& e) {
    GTEST_SKIP() << "not run: no headless OpenGL 4.5 context: " << e.what();
  }
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45);
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
}
