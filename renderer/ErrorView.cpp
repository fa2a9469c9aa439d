// ErrorView; see ErrorView.h.
#include "renderer/ErrorView.h"

#include "renderer/MaterialRenderer.h"

namespace relief::renderer {

core::Result<ErrorViewInputs> renderErrorViewInputs(MaterialRenderer& renderer,
                                                    const FrameSettings& frame, int width,
                                                    int height) {
  FrameSettings pass = frame;
  pass.split.reset();  // the error of the current material (A)
  pass.debugView = core::DebugView::Uv;
  pass.output = FrameOutput::FloatData;
  core::Result<core::Image> finalUv = renderer.renderToImage(pass, width, height);
  if (!finalUv)
    return core::makeError(finalUv.error());
  pass.output = FrameOutput::EyeRays;
  core::Result<core::Image> eyeRays = renderer.renderToImage(pass, width, height);
  if (!eyeRays)
    return core::makeError(eyeRays.error());
  return ErrorViewInputs{std::move(finalUv).value(), std::move(eyeRays).value(),
                         core::HeightField::fromMaterial(renderer.material())};
}

}  // namespace relief::renderer
