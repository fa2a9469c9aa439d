// Uploading compressed textures to the GPU as they are (glCompressedTexImage2D per mip level),
// so the viewport samples exactly the blocks a game would ship. Whether the driver takes a
// format is asked of the current context; when it does not, callers decode with core instead.
//
// Compressed textures keep their rows top first, as the files store them (blocks cannot be
// flipped in general: ETC2 planar and ASTC blocks have no row-swapped equivalent), which is
// the convention every map texture follows; the shaders flip V when they sample.
#pragma once

#include "core/compression/Compressor.h"

#include <QOpenGLTexture>

#include <memory>
#include <string>

namespace relief::renderer {

// Needs a current context.
bool gpuSupportsFormat(core::TextureFormat format, bool srgb);
// The extension or GL version the format needs, for status messages ("GL_KHR_texture_..." ).
std::string formatRequirement(core::TextureFormat format);

// Null when the current context cannot sample the format. Mip levels as the texture has them;
// with one level the texture filters without mipmaps (compressed formats cannot be given a
// generated chain). DXT5nm's X (in alpha) is swizzled into red, so every two-channel normal
// texture samples as (x, y, 0 or ?, 1) and the shader rebuilds z.
std::unique_ptr<QOpenGLTexture> createCompressedTexture(const core::CompressedTexture& texture);

}  // namespace relief::renderer
