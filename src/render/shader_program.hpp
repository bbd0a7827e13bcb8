// GLSL programs built from a vertex and a fragment shader file, with errors that name the file
// and quote the GL info log.
#pragma once

#include <filesystem>
#include <string_view>

#include "core/result.hpp"
#include "render/gl_object.hpp"

namespace globe::render {

class ShaderProgram {
 public:
  ShaderProgram() = default;
  explicit ShaderProgram(GlObject program) : program_(std::move(program)) {}

  GLuint id() const { return program_.get(); }
  // -1 when the program has no active uniform of that name (GL ignores -1 in glUniform*).
  GLint uniformLocation(const char* name) const { return glGetUniformLocation(id(), name); }

 private:
  GlObject program_;
};

// Reads, compiles and links the two files. Errors: "<file>: cannot read shader file",
// "<file>: GLSL compile error:\n<log>", "<vertex file> + <fragment file>: GLSL link error:\n<log>".
// `defines` (e.g. "#define X 1"), when given, is inserted into both sources right after their
// "#version" line.
Result<ShaderProgram> loadShaderProgram(const std::filesystem::path& vertexPath,
                                        const std::filesystem::path& fragmentPath,
                                        std::string_view defines = {});

// The same from sources in memory; the names stand in for file names in error messages.
Result<ShaderProgram> buildShaderProgram(std::string_view vertexSource, std::string_view vertexName,
                                         std::string_view fragmentSource,
                                         std::string_view fragmentName,
                                         std::string_view defines = {});

}  // namespace globe::render
