// Checks a TIFF file's first directory for what OpenImageIO 2.4 reads wrongly. A TIFF may leave
// out its BitsPerSample tag, which then means 1 bit a sample (TIFF 6.0, section 8: "Default =
// 1"); Pillow writes bilevel images that way. OpenImageIO reads such a file as 8 bits a sample,
// so every byte of packed bits becomes a texel: the image comes out as noise, with no error.
// Relief refuses it, saying how to re-save it, rather than load the noise.
#pragma once

#include "core/base/Result.h"

#include <string>

namespace relief::core::inline image {

// The problem with the first directory, naming the file; ok for files OpenImageIO reads as
// they are (and for files too damaged to parse here: OpenImageIO's reader reports those).
Status preflightTiff(const std::string& path);

}  // namespace relief::core::inline image
