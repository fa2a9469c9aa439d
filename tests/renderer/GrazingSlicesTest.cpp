// Defaults that do not slice: at a grazing view (10 degrees) the bundled samples, and an 8-bit
// JPEG height map as artists ship them, render with default sampling as they do with 256 samples
// along every view ray, within a stated PSNR; reference 001's angle rule at its old 8/32 does
// not on the 8-bit map.
#include "core/image/ImageIO.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/preset/MaterialPreset.h"
#include "support/OffscreenFixture.h"
#include "support/TestPaths.h"

#include <cmath>

namespace relief::test {
namespace {

using core::ParamId;

constexpr int kWidth = 480, kHeight = 360;

double psnrRgb(const core::Image& a, const core::Image& b) {
  double sum = 0.0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      for (int c = 0; c < 3; ++c) {
        const double d = double(a.at(x, y, c)) - double(b.at(x, y, c));
        sum += d * d;
      }
    }
  }
  const double mse = sum / (double(a.width()) * a.height() * 3.0);
  return mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : 99.0;
}

class GrazingSlices : public OffscreenTest {
 protected:
  // The plane 10 degrees above its surface, as the CLI's --pitch 10 --distance 1.2 shows it.
  core::Image render(const core::Material& material) {
    const core::Mesh mesh = core::makePlane();
    offscreen().setMesh(mesh);
    offscreen().setMaterial(material);
    renderer::RenderView view;
    view.camera.pitchDeg = 10.0f;
    view.camera.frame(mesh.bounds(), float(kWidth) / float(kHeight));
    view.camera.distance = 1.2f;
    core::Result<core::Image> image = offscreen().render(view, kWidth, kHeight);
    EXPECT_TRUE(image.ok()) << image.error();
    return image.ok() ? std::move(image).value() : core::Image();
  }

  // PSNR of `material` as it is against the same with 256 samples on every view ray.
  double againstDenseMarch(core::Material material) {
    const core::Image candidate = render(material);
    material.setParameter(ParamId::MinSamples, 256);
    material.setParameter(ParamId::MaxSamples, 256);
    return psnrRgb(render(material), candidate);
  }
};

core::Material samplePresetMaterial(const std::string& name) {
  core::Result<core::LoadedPreset> preset = core::loadPreset(samplePreset(name));
  EXPECT_TRUE(preset.ok()) << preset.error();
  return preset.ok() ? preset->preset.material : core::Material();
}

TEST_F(GrazingSlices, TheBundledSamplesMatchADenseMarchAtTenDegrees) {
  for (const char* name : {"bricks", "cobblestones", "tiles"}) {
    const double psnr = againstDenseMarch(samplePresetMaterial(name));
    std::printf("%s at 10 degrees, default sampling against 256 samples: %.2f dB\n", name, psnr);
    EXPECT_GT(psnr, 42.0) << name;
  }
}

// The bricks' height map saved as an 8-bit JPEG (quality 85), as game packages ship height maps:
// plateaus with steps and block noise, which the angle rule's 32 samples slice at this view.
TEST_F(GrazingSlices, AnEightBitJpegHeightMapMatchesADenseMarchAtTenDegrees) {
  core::Material material = samplePresetMaterial("bricks");
  const std::string jpeg = scratchFolder() + "/bricks_height.jpg";
  ASSERT_TRUE(core::saveImage(*material.image(core::MapSlot::Height), jpeg).ok());
  core::Result<core::Image> eightBit = core::loadImage(jpeg);
  ASSERT_TRUE(eightBit.ok()) << eightBit.error();
  ASSERT_EQ(eightBit->sourceBitsPerChannel(), 8);
  material.setMap(core::MapSlot::Height,
                  std::make_shared<core::Image>(std::move(eightBit).value()));
  material.setParameter(ParamId::HeightScale, 0.04);
  material.setParameter(ParamId::HeightBias, -0.04);

  const double byTexels = againstDenseMarch(material);
  core::Material byAngle = material;
  byAngle.setParameter(ParamId::SamplesPerTexel, 0.0);
  byAngle.setParameter(ParamId::MaxSamples, 32);
  const double angleRule = againstDenseMarch(byAngle);
  std::printf("8-bit JPEG bricks at 10 degrees: %.2f dB by texels crossed, %.2f dB by angle\n",
              byTexels, angleRule);
  EXPECT_GT(byTexels, 40.0);
  EXPECT_GT(byTexels, angleRule + 3.0);
}

}  // namespace
}  // namespace relief::test
