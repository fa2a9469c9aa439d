// ShaderProgram: a GLSL program built from files under shaders/ (embedded as Qt resources),
// with #include resolved and feature #defines prepended. A failed rebuild keeps the last good
// program and returns the driver's log mapped back to file:line.
#pragma once

#include "core/base/Result.h"
#include "renderer/ShaderIncludeResolver.h"

#include <QOpenGLShaderProgram>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace relief::renderer {

// The GLSL version every Relief shader is compiled with (OpenGL 4.1 core, macOS's ceiling).
constexpr const char* kGlslVersionLine = "#version 410 core";

// Reads a file below the shader root (":/shaders/" in the resources).
std::optional<std::string> loadShaderSource(const std::string& path);

// "#version 410 core" followed by one "#define NAME" or "#define NAME VALUE" line per entry.
std::string shaderPrelude(const std::vector<std::string>& defines);

// The files of a program's stages; the tessellation stages are optional (both or neither).
struct ShaderStagePaths {
  std::string vertex;
  std::string fragment;
  std::string tessellationControl;
  std::string tessellationEvaluation;
};

class ShaderProgram {
 public:
  // Needs a current OpenGL context. `loader` reads the sources (the embedded shaders/ folder
  // unless a test passes its own).
  core::Status build(const ShaderStagePaths& paths, const std::vector<std::string>& defines = {},
                     const ShaderSourceLoader& loader = loadShaderSource);
  core::Status build(const std::string& vertexPath, const std::string& fragmentPath,
                     const std::vector<std::string>& defines = {},
                     const ShaderSourceLoader& loader = loadShaderSource) {
    return build(ShaderStagePaths{vertexPath, fragmentPath, {}, {}}, defines, loader);
  }

  bool isValid() const { return m_program != nullptr; }
  QOpenGLShaderProgram& program() { return *m_program; }
  void release() { m_program.reset(); }

 private:
  std::unique_ptr<QOpenGLShaderProgram> m_program;
};

}  // namespace relief::renderer
