// Expands `#include "file"` in GLSL sources and maps the driver's error lines back to the file
// and line they came from. Pure string work with no GL, so it is unit-tested on its own.
#pragma once

#include "core/base/Result.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace relief::renderer {

struct SourceLocation {
  std::string file;
  int line = 0;  // 1-based
};

struct ResolvedShader {
  std::string source;                       // prelude + expanded text, ready for the driver
  std::vector<SourceLocation> lineOrigins;  // lineOrigins[n - 1] is where line n came from
};

// Returns the text of a shader file by its path (relative to the shader root), or nullopt.
using ShaderSourceLoader = std::function<std::optional<std::string>(const std::string& path)>;

// Expands includes recursively. An include path is relative to the including file's folder.
// Each file is included at most once per program (like `#pragma once`), so shared parts need no
// guards; an include cycle or a missing file is an error naming the including file and line.
// `prelude` (the #version line and feature #defines) goes first and maps to "<prelude>".
core::Result<ResolvedShader> resolveShaderIncludes(const std::string& path,
                                                   const ShaderSourceLoader& loader,
                                                   const std::string& prelude = {});

// Rewrites the line references of a compiler log ("0:12(5): error ..." from Mesa,
// "0(12) : error ..." from NVIDIA, "ERROR: 0:12: ..." from AMD and Intel) as "file:line: ...".
// Lines it does not recognise pass through unchanged.
std::string mapShaderLog(const std::string& log, const std::vector<SourceLocation>& lineOrigins);

}  // namespace relief::renderer
