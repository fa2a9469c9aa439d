// GpuMesh: a core::Mesh uploaded to vertex and index buffers with its vertex layout recorded
// in a VAO. Needs a current context for upload, draw and destruction.
#pragma once

#include "core/mesh/Mesh.h"

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLVertexArrayObject>

namespace relief::renderer {

// Attribute locations shared with shaders/material.vert.
enum VertexAttribute : unsigned {
  kAttribPosition = 0,
  kAttribNormal = 1,
  kAttribUv = 2,
  kAttribTangent = 3,
  kAttribUvScale = 4
};

class GpuMesh {
 public:
  GpuMesh();
  void upload(QOpenGLExtraFunctions& gl, const core::Mesh& mesh);
  // `mode`: GL_TRIANGLES, or GL_PATCHES of three vertices for the tessellation stages;
  // `primitivesPerDraw` triangles or patches per draw call (one call for all by default).
  void draw(QOpenGLExtraFunctions& gl, GLenum mode, int primitivesPerDraw = 1 << 29);
  void release();
  bool isEmpty() const { return m_indexCount == 0; }

 private:
  QOpenGLVertexArrayObject m_vao;
  QOpenGLBuffer m_vertices{QOpenGLBuffer::VertexBuffer};
  QOpenGLBuffer m_indices{QOpenGLBuffer::IndexBuffer};
  int m_indexCount = 0;
};

}  // namespace relief::renderer
