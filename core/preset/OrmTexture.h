// An ORM texture (glTF's occlusion/roughness/metallic packing, Unreal's ORM, Poly Haven's "arm"):
// one RGB file whose R is ambient occlusion, G roughness and B metallic. Relief keeps them as
// three slots that remember the file and channel they came from, so a preset saves the file once
// per slot with "channel" and an export packs them again. The editor and the CLI load it here.
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"
#include "core/material/MapSlot.h"

#include <string>
#include <vector>

namespace relief::core::inline preset {

struct ChannelMap {
  MapSlot slot;
  Image image;  // one channel, linear
  int channel;  // the file's channel it came from (0 R, 1 G, 2 B)
};

// The AO, roughness and metallic maps of the file at `path`. Refused, with a message naming the
// file, when it does not load or has fewer than three channels (a grey image is no ORM texture).
Result<std::vector<ChannelMap>> loadOrmTexture(const std::string& path);

}  // namespace relief::core::inline preset
