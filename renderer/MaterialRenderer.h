// MaterialRenderer: draws a mesh with a material for a view. The viewport, the offscreen
// renderer (CLI, thumbnails, tests) all call render() with their own framebuffer, so every
// picture Relief makes comes from this one code path. All calls need the same current context.
#pragma once

#include "core/Material.h"
#include "core/Mesh.h"
#include "core/Result.h"
#include "renderer/GpuMesh.h"
#include "renderer/MaterialTextures.h"
#include "renderer/RenderView.h"
#include "renderer/ShaderProgram.h"

#include <QOpenGLExtraFunctions>

#include <string>

namespace relief::renderer {

class MaterialRenderer : protected QOpenGLExtraFunctions {
 public:
  MaterialRenderer();
  ~MaterialRenderer();
  MaterialRenderer(const MaterialRenderer&) = delete;
  MaterialRenderer& operator=(const MaterialRenderer&) = delete;

  // Compiles the shaders and creates GL objects; fails with the mapped shader log.
  core::Status initialize();
  // Frees every GL object; call with the context current (before it is destroyed).
  void releaseResources();
  bool isInitialized() const { return m_initialized; }

  void setMesh(const core::Mesh& mesh);
  // Uploads the maps that changed since the last call and takes the parameters.
  void setMaterial(const core::Material& material);

  // Draws into `framebuffer` (0 for the window's, or an FBO id) at width x height pixels.
  void render(const RenderView& view, int width, int height, unsigned framebuffer);

  // GL_RENDERER and GL_VERSION of the context, for the status bar and reports.
  std::string rendererDescription();

 private:
  void drawBackground(const RenderView& view);
  void setMaterialUniforms(QOpenGLShaderProgram& program, const RenderView& view, float aspect);

  bool m_initialized = false;
  ShaderProgram m_materialProgram;
  ShaderProgram m_backgroundProgram;
  GpuMesh m_mesh;
  MaterialTextures m_textures;
  core::Material m_material;
  unsigned m_emptyVao = 0;  // core profile needs a bound VAO even for attribute-less draws
};

}  // namespace relief::renderer
