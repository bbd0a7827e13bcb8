// Shader loading: the real terrain shaders build; missing files and GLSL errors are reported with
// the file name and the GL info log.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <string>

#include "render/embedded_shaders.hpp"
#include "render/osmesa_context.hpp"
#include "render/shader_directory.hpp"
#include "render/shader_program.hpp"
#include "render/terrain_renderer.hpp"
#include "tests/support/build_paths.hpp"

namespace globe::render {
namespace {

class ShaderProgramTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto context = OsMesaContext::create(16, 16);
    ASSERT_TRUE(context.ok()) << context.error();
    context_ = std::move(*context);
    dir_ = std::filesystem::temp_directory_path() /
           ("globe-shader-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    context_.reset();
    std::filesystem::remove_all(dir_);
  }
  std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto path = dir_ / name;
    std::ofstream(path) << text;
    return path;
  }

  std::unique_ptr<OsMesaContext> context_;
  std::filesystem::path dir_;
};

constexpr const char* kGoodVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
out vec3 v_color;
void main() { v_color = a_position; gl_Position = vec4(a_position, 1.0); })";
constexpr const char* kGoodFragment = R"(#version 330 core
in vec3 v_color;
out vec4 o_color;
void main() { o_color = vec4(v_color, 1.0); })";

TEST_F(ShaderProgramTest, RealTerrainShadersBuild) {
  auto program = loadNamedShaderProgram(defaultShaderDirectory(), "terrain.vert", "terrain.frag");
  ASSERT_TRUE(program.ok()) << program.error();
  EXPECT_NE(program->id(), 0u);
  EXPECT_GE(program->uniformLocation("u_modelView"), 0);
  EXPECT_GE(program->uniformLocation("u_logDepthScale"), 0);
  EXPECT_EQ(program->uniformLocation("no_such_uniform"), -1);
}

TEST_F(ShaderProgramTest, MissingFileIsNamed) {
  const auto vertex = write("ok.vert", kGoodVertex);
  auto program = loadShaderProgram(vertex, dir_ / "missing.frag");
  ASSERT_FALSE(program.ok());
  EXPECT_NE(program.error().find("missing.frag: no such file (a shader file)"), std::string::npos)
      << program.error();
}

TEST_F(ShaderProgramTest, CompileErrorNamesTheFileAndQuotesTheLog) {
  const auto vertex = write("ok.vert", kGoodVertex);
  const auto fragment = write("broken.frag", R"(#version 330 core
out vec4 o_color;
void main() { o_color = vec4(undeclared_thing, 1.0); })");
  auto program = loadShaderProgram(vertex, fragment);
  ASSERT_FALSE(program.ok());
  EXPECT_NE(program.error().find("broken.frag: GLSL compile error:"), std::string::npos)
      << program.error();
  EXPECT_NE(program.error().find("undeclared_thing"), std::string::npos) << program.error();
}

TEST_F(ShaderProgramTest, LinkErrorNamesBothFiles) {
  const auto vertex = write("ok.vert", kGoodVertex);
  // Reads a varying of another type than the vertex shader writes: compiles, fails to link.
  const auto fragment = write("mismatch.frag", R"(#version 330 core
in vec2 v_color;
out vec4 o_color;
void main() { o_color = vec4(v_color, 0.0, 1.0); })");
  auto program = loadShaderProgram(vertex, fragment);
  ASSERT_FALSE(program.ok());
  EXPECT_NE(program.error().find("ok.vert + "), std::string::npos) << program.error();
  EXPECT_NE(program.error().find("mismatch.frag: GLSL link error:"), std::string::npos)
      << program.error();
}

TEST_F(ShaderProgramTest, RendererReportsAMissingShaderDirectory) {
  TerrainRendererOptions options;
  options.shaderDirectory = dir_ / "nowhere";
  auto renderer = TerrainRenderer::create(options);
  ASSERT_FALSE(renderer.ok());
  EXPECT_NE(renderer.error().find("nowhere/terrain.vert"), std::string::npos) << renderer.error();
}

TEST_F(ShaderProgramTest, EnvironmentOverridesTheShaderDirectory) {
  ::setenv("GLOBE_SHADER_DIR", dir_.c_str(), 1);
  EXPECT_EQ(defaultShaderDirectory(), dir_);
  ::unsetenv("GLOBE_SHADER_DIR");
  EXPECT_TRUE(defaultShaderDirectory().empty());  // the embedded shaders
}

// The program carries every file of shaders/ as it is in the source tree: nothing is read from
// the checkout at run time, and nothing embedded is stale.
TEST_F(ShaderProgramTest, EmbeddedShadersAreTheSourceTreesFiles) {
  const std::filesystem::path source = std::filesystem::path(GLOBE_SOURCE_DIR) / "shaders";
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".vert" && entry.path().extension() != ".frag") continue;
    ++files;
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto embedded = embeddedShader(name);
    ASSERT_TRUE(embedded) << name << " is not embedded";
    EXPECT_EQ(*embedded, text) << name;
  }
  EXPECT_GE(files, 6u);
  EXPECT_EQ(embeddedShaderNames().size(), files);
  EXPECT_FALSE(embeddedShader("nothing.frag"));
  auto missing = loadNamedShaderProgram({}, "terrain.vert", "nothing.frag");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("embedded:nothing.frag"), std::string::npos) << missing.error();
}

}  // namespace
}  // namespace globe::render
