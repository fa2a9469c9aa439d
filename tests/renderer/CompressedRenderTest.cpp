// The lit, parallax-mapped material with compressed maps: the blocks uploaded natively must
// render the same picture as core's decoding of the same blocks uploaded level by level. This
// checks the upload path end to end: row order (blocks keep rows top first and the shaders flip
// V), mip levels, sRGB, DXT5nm's swizzle and the shader's Z rebuild for two-channel normals
// (reference 003, eq. 2.1). And compression must visibly change the picture for a coarse format,
// so the comparison is not between two copies of the original.
#include "core/compression/Compressor.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/preset/MaterialPreset.h"
#include "support/ImageCompare.h"
#include "support/OffscreenFixture.h"
#include "support/TestPaths.h"

namespace relief::test {
namespace {

using core::MapSlot;
using core::TextureFormat;

class CompressedRender : public OffscreenTest {
 protected:
  void SetUp() override {
    core::Result<core::LoadedPreset> preset = core::loadPreset(samplePreset("bricks"));
    ASSERT_TRUE(preset.ok()) << preset.error();
    m_material = preset->preset.material;
    offscreen().setMesh(core::makePlane());
    m_view.camera.yawDeg = 20.0f;
    m_view.camera.pitchDeg = 35.0f;
    m_view.camera.distance = 1.6f;
  }
  void TearDown() override { offscreen().setNativeCompressedUploads(true); }

  core::Material withCompressed(MapSlot slot, TextureFormat format) {
    auto texture = std::make_shared<core::CompressedTexture>(
        core::compressMap(*m_material.image(slot), slot,
                          {format, core::CompressionQuality::Fast, true})
            .value());
    auto decoded = std::make_shared<core::Image>(core::decodeAsMap(*texture).value());
    core::Material material = m_material;
    material.setCompressedMap(slot, std::move(texture), std::move(decoded));
    return material;
  }

  core::Image render(const core::Material& material, bool native) {
    offscreen().setNativeCompressedUploads(native);
    offscreen().setMaterial(material);
    core::Result<core::Image> image = offscreen().render(m_view, 240, 160);
    EXPECT_TRUE(image.ok()) << image.error();
    return image.ok() ? std::move(image).value() : core::Image();
  }

  core::Material m_material;
  renderer::RenderView m_view;
};

TEST_F(CompressedRender, NativeUploadsRenderAsCoreDecodingDoes) {
  const std::pair<MapSlot, TextureFormat> cases[] = {
      {MapSlot::Normal, TextureFormat::Bc5},     {MapSlot::Normal, TextureFormat::Dxt5nm},
      {MapSlot::Normal, TextureFormat::EacRg11}, {MapSlot::Normal, TextureFormat::Bc1},
      {MapSlot::Color, TextureFormat::Bc1},      {MapSlot::Color, TextureFormat::Etc2A},
      {MapSlot::Color, TextureFormat::Astc6x6},  {MapSlot::Height, TextureFormat::Bc4},
      {MapSlot::Height, TextureFormat::EacR11},  {MapSlot::Normal, TextureFormat::Astc4x4Normal},
      {MapSlot::Color, TextureFormat::Bc7}};
  for (const auto& [slot, format] : cases) {
    const core::Material material = withCompressed(slot, format);
    const core::Image native = render(material, true);
    const core::Image decoded = render(material, false);
    const ImageDifference difference = compareImages(native, decoded);
    // The same texels either way; what differs is where filtering happens: the driver filters
    // 8-bit (or 11-bit) block texels, the decoded path 16-bit (normals) or float (heights)
    // copies, and a two-channel normal's Z is rebuilt after filtering instead of before. That
    // moves a few pixels by a level or two and the mean by far less than one. Heights are
    // the exception for the maximum: the drivers' BC4 decoding differs from ours by a step
    // (CompressedSamplingTest), and a step moves a parallax ray's hit across a brick edge.
    // Normals come next: under pbr the studio's reflection has the soft boxes' hard edges,
    // and the small turn of a normal rebuilt after filtering moves a pixel across one.
    EXPECT_LT(difference.meanError, 0.6 / 255.0)
        << core::textureFormatInfo(format).name << " in " << core::mapSlotName(slot);
    const double maxError = slot == MapSlot::Height   ? 0.4
                            : slot == MapSlot::Normal ? 48.0 / 255.0
                                                      : 24.0 / 255.0;
    EXPECT_LT(difference.maxError, maxError)
        << core::textureFormatInfo(format).name << " in " << core::mapSlotName(slot);
  }
}

TEST_F(CompressedRender, CoarseCompressionChangesThePicture) {
  const core::Image original = render(m_material, true);
  const core::Image astc8x8 = render(withCompressed(MapSlot::Color, TextureFormat::Astc8x8), true);
  const core::Image bc5 = render(withCompressed(MapSlot::Normal, TextureFormat::Bc5), true);
  // ASTC 8x8 (2 bits per texel) visibly changes the colour; BC5 keeps normals close.
  const double coarse = compareImages(original, astc8x8).meanError;
  const double fine = compareImages(original, bc5).meanError;
  EXPECT_GT(coarse, 0.3 / 255.0);
  EXPECT_LT(fine, coarse);
}

}  // namespace
}  // namespace relief::test
