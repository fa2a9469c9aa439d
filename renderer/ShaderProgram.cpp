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

core::Status ShaderProgram::build(const ShaderStagePaths& paths,
                                  const std::vector<std::string>& defines,
                                  const ShaderSourceLoader& loader) {
  struct Stage {
    GLenum type;
    const std::string& path;
  };
  std::vector<Stage> stages = {{GL_VERTEX_SHADER, paths.vertex}};
  if (!paths.tessellationControl.empty()) {
    stages.push_back({GL_TESS_CONTROL_SHADER, paths.tessellationControl});
    stages.push_back({GL_TESS_EVALUATION_SHADER, paths.tessellationEvaluation});
  }
  stages.push_back({GL_FRAGMENT_SHADER, paths.fragment});

  const std::string prelude = shaderPrelude(defines);
  std::vector<ResolvedShader> sources;
  for (const Stage& stage : stages) {
    core::Result<ResolvedShader> resolved = resolveShaderIncludes(stage.path, loader, prelude);
    if (!resolved)
      return core::makeError(resolved.error());
    sources.push_back(std::move(resolved).value());
  }

  QOpenGLContext* context = QOpenGLContext::currentContext();
  Q_ASSERT(context);
  QOpenGLExtraFunctions& gl = *context->extraFunctions();
  std::vector<GLuint> shaders;
  const auto deleteShaders = [&] {
    for (GLuint shader : shaders)
      gl.glDeleteShader(shader);
  };
  std::string names;
  for (std::size_t i = 0; i < stages.size(); ++i) {
    std::string log;
    const GLuint shader = compileStage(gl, stages[i].type, sources[i].source, log);
    if (!shader) {
      deleteShaders();
      return core::makeError(stages[i].path + " does not compile:\n" +
                             mapShaderLog(log, sources[i].lineOrigins));
    }
    shaders.push_back(shader);
    names += (names.empty() ? "" : " + ") + stages[i].path;
  }

  auto program = std::make_unique<QOpenGLShaderProgram>();
  program->create();
  for (GLuint shader : shaders)
    gl.glAttachShader(program->programId(), shader);
  const bool linked = program->link();
  // The linked program keeps what it needs; the stage objects can go.
  for (GLuint shader : shaders)
    gl.glDetachShader(program->programId(), shader);
  deleteShaders();
  if (!linked)
    return core::makeError(names + " do not link:\n" + program->log().toStdString());
  m_program = std::move(program);
  return {};
}

}  // namespace relief::renderer
