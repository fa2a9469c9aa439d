// ShaderProgram; see ShaderProgram.h.
#include "renderer/ShaderProgram.h"

#include "renderer/ShaderIncludeResolver.h"

#include <QFile>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>

#include <algorithm>
#include <cstring>

namespace relief::renderer {
std::optional<std::string> loadShaderSource(const std::string& path) {
  QFile file(QStringLiteral(":/shaders/") + QString::fromStdString(path));
  if (!file.open(QIODevice::ReadOnly))
    return std::nullopt;
  return file.readAll().toStdString();
}

std::string shaderPrelude(const std::vector<std::string>& defines) {
  std::string prelude = std::string(kGlslVersionLine) + "\n";
  for (const std::string& define : defines)
    prelude += "#define " + define + "\n";
  return prelude;
}

namespace {

// Compiles one stage from exactly the text given. QOpenGLShader inserts its own lines (precision
// defines and a #line directive) after #version on desktop GL, which shifts the line numbers some
// drivers report; compiling the text ourselves keeps the driver's numbers equal to ours.
// Returns the shader object, or 0 with `log` set.
GLuint compileStage(QOpenGLExtraFunctions& gl, GLenum type, const std::string& source,
                    std::string& log) {
  const GLuint shader = gl.glCreateShader(type);
  const char* text = source.c_str();
  const auto length = GLint(source.size());
  gl.glShaderSource(shader, 1, &text, &length);
  gl.glCompileShader(shader);
  GLint compiled = GL_FALSE;
  gl.glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
  if (compiled == GL_TRUE)
    return shader;
  GLint logLength = 0;
  gl.glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &logLength);
  log.assign(std::size_t(std::max(logLength, 1)), '\0');
  gl.glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
  log.resize(std::strlen(log.c_str()));
  gl.glDeleteShader(shader);
  return 0;
}

}  // namespace

core::Status ShaderProgram::build(const std::string& vertexPath, const std::string& fragmentPath,
                                  const std::vector<std::string>& defines,
                                  const ShaderSourceLoader& loader) {
  const std::string prelude = shaderPrelude(defines);
  core::Result<ResolvedShader> vertex = resolveShaderIncludes(vertexPath, loader, prelude);
  if (!vertex)
    return core::makeError(vertex.error());
  core::Result<ResolvedShader> fragment = resolveShaderIncludes(fragmentPath, loader, prelude);
  if (!fragment)
    return core::makeError(fragment.error());

  QOpenGLContext* context = QOpenGLContext::currentContext();
  Q_ASSERT(context);
  QOpenGLExtraFunctions& gl = *context->extraFunctions();
  std::string log;
  const GLuint vertexShader = compileStage(gl, GL_VERTEX_SHADER, vertex->source, log);
  if (!vertexShader) {
    return core::makeError(vertexPath + " does not compile:\n" +
                           mapShaderLog(log, vertex->lineOrigins));
  }
  const GLuint fragmentShader = compileStage(gl, GL_FRAGMENT_SHADER, fragment->source, log);
  if (!fragmentShader) {
    gl.glDeleteShader(vertexShader);
    return core::makeError(fragmentPath + " does not compile:\n" +
                           mapShaderLog(log, fragment->lineOrigins));
  }

  auto program = std::make_unique<QOpenGLShaderProgram>();
  program->create();
  gl.glAttachShader(program->programId(), vertexShader);
  gl.glAttachShader(program->programId(), fragmentShader);
  const bool linked = program->link();
  // The linked program keeps what it needs; the stage objects can go.
  gl.glDetachShader(program->programId(), vertexShader);
  gl.glDetachShader(program->programId(), fragmentShader);
  gl.glDeleteShader(vertexShader);
  gl.glDeleteShader(fragmentShader);
  if (!linked) {
    return core::makeError(vertexPath + " + " + fragmentPath + " do not link:\n" +
                           program->log().toStdString());
  }
  m_program = std::move(program);
  return {};
}

}  // namespace relief::renderer
