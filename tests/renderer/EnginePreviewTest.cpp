// The engine preview modes (shaders/include/engine_parallax.glsl) against CPU replicas of each
// engine's published algorithm, transcribed here a second time, in double precision, from the
// same sources the shader cites:
//   Godot 4   scene/resources/material.cpp, BaseMaterial3D::_update_shader ("Height",
//             "Height Deep Parallax"), Godot 4.0-4.3
//   Unreal    Epic's ParallaxOcclusionMapping material function (its graph and Custom node), UE 5
//   URP       com.unity.render-pipelines.core ShaderLibrary/ParallaxMapping.hlsl,
//             ParallaxOffset1Step
//   HDRP      LitData.hlsl ApplyPerPixelDisplacement and core ShaderLibrary/
//             PerPixelDisplacement.hlsl ParallaxOcclusionMapping (secant method)
// For every pixel the GPU's final UV (the uv view, float) is compared with the replica run on
// the same entry UV and view direction (the eye-ray pass), reading the same bilinear field
// (core::HeightField, texel centres as GL_LINEAR). Pixels where the map is minified are left
// out (the replicas read level 0).
//
// A march decides on comparisons (is the ray below the map?); where float and double land on
// either side of one, the two traces take different steps. Those pixels are few and the bound
// says how few; everywhere else the UVs agree within 0.05 texel.
#include "core/exporters/EnginePreview.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/tracing/HeightField.h"
#include "support/OffscreenFixture.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace relief::test {
namespace {

using core::Engine;
using core::Image;
using core::ParamId;

constexpr int kFieldSize = 64;
constexpr double kScale = 0.08;

Image smoothField() {
  Image field(kFieldSize, kFieldSize, 1);
  const double k = 2.0 * std::numbers::pi / kFieldSize;
  for (int y = 0; y < kFieldSize; ++y) {
    for (int x = 0; x < kFieldSize; ++x)
      field.at(x, y, 0) = float(0.5 + 0.45 * std::sin(2.0 * k * x) * std::sin(3.0 * k * y));
  }
  return field;
}

Image thinWallField() {
  // One-texel walls at 1.0 every 8 texels in a 0.1 floor: where a march with few layers steps
  // over walls, and each engine's step rule shows.
  Image field(kFieldSize, kFieldSize, 1);
  for (int y = 0; y < kFieldSize; ++y) {
    for (int x = 0; x < kFieldSize; ++x)
      field.at(x, y, 0) = (x % 8 == 0 || y % 8 == 0) ? 1.0f : 0.1f;
  }
  return field;
}

core::Material reliefMaterial(core::Technique technique, const Image& field = smoothField()) {
  core::Material material;
  material.setMap(core::MapSlot::Height, std::make_shared<Image>(field));
  material.setTechnique(technique);
  material.setParameter(ParamId::HeightScale, kScale);
  material.setParameter(ParamId::HeightBias, -kScale);
  material.setParameter(ParamId::MinSamples, 8);
  material.setParameter(ParamId::MaxSamples, 32);
  // Relief's self-shadowing stays on: no engine preview may compile it in.
  material.setParameter(ParamId::ShadowMode, double(core::ShadowMode::Hard));
  return material;
}

// h (0..1, 1 the top) at texture coordinates, bilinear and repeating, as the GPU reads it.
struct Field {
  core::HeightField field{smoothField(), 0, 1.0, 0.0, false};
  double operator()(glm::dvec2 uv) const { return field.sample(uv.x, uv.y); }
};

using Replica = std::function<glm::dvec2(const Field&, glm::dvec2 uv, glm::dvec3 V,
                                         const core::EngineTraceParams&)>;

glm::dvec2 godotReplica(const Field& h, glm::dvec2 uv, glm::dvec3 V,
                        const core::EngineTraceParams& p) {
  if (p.trace == core::EngineTrace::GodotOffset)
    return uv - glm::dvec2(V) * (1.0 - h(uv)) * p.depth;
  const double numLayers = p.maxSteps + (p.minSteps - p.maxSteps) * std::abs(V.z);
  const double layerDepth = 1.0 / numLayers;
  const glm::dvec2 delta = glm::dvec2(V) * p.depth / numLayers;
  glm::dvec2 ofs = uv;
  double depth = 1.0 - h(ofs);
  double currentDepth = 0.0;
  while (currentDepth < depth) {
    ofs -= delta;
    depth = 1.0 - h(ofs);
    currentDepth += layerDepth;
  }
  const glm::dvec2 previous = ofs + delta;
  const double after = depth - currentDepth;
  const double before = (1.0 - h(previous)) - currentDepth + layerDepth;
  const double weight = after / (after - before);
  return ofs + (previous - ofs) * weight;
}

glm::dvec2 unrealReplica(const Field& h, glm::dvec2 uv, glm::dvec3 V,
                         const core::EngineTraceParams& p) {
  const glm::dvec2 uvDist = p.depth * (-glm::dvec2(V) / V.z);
  const glm::dvec2 start = uv + uvDist * ((1.0 - p.referencePlane) * -1.0);
  const double steps = p.maxSteps + (p.minSteps - p.maxSteps) * std::clamp(std::abs(V.z), 0., 1.);
  const double stepSize = 1.0 / steps;
  const glm::dvec2 stepUv = uvDist * stepSize;
  double rayHeight = 1.0, oldRay = 1.0, oldTex = 1.0;
  glm::dvec2 offset(0.0);
  for (int i = 0; i < std::floor(steps) + 2; ++i) {
    const double texAtRay = h(start + offset);
    if (rayHeight < texAtRay) {
      double x = (oldRay - oldTex) + (texAtRay - rayHeight);
      x = (texAtRay - rayHeight) / x;
      offset -= x * stepUv;
      break;
    }
    oldRay = rayHeight;
    rayHeight -= stepSize;
    offset += stepUv;
    oldTex = texAtRay;
  }
  return start + offset;
}

glm::dvec2 urpReplica(const Field& h, glm::dvec2 uv, glm::dvec3 V,
                      const core::EngineTraceParams& p) {
  const double amplitude = p.depth;
  const double height = h(uv) * amplitude - amplitude / 2.0;
  glm::dvec3 v = glm::normalize(V);
  v.z += 0.42;
  return uv + height * (glm::dvec2(v) / v.z);
}

glm::dvec2 hdrpReplica(const Field& h, glm::dvec2 uv, glm::dvec3 V,
                       const core::EngineTraceParams& p) {
  // Magnified pixels only: lod 0, no fade.
  const glm::dvec3 viewDirUv = glm::normalize(glm::dvec3(glm::dvec2(V) * p.depth, V.z));
  const double x = std::abs(viewDirUv.z);
  const double fastAcos = ((0.0468878 * x + -0.203471) * x + 1.570796) * std::sqrt(1.0 - x);
  const double unitAngle = std::clamp(fastAcos * (2.0 / std::numbers::pi), 0.0, 1.0);
  const int numSteps = int(p.minSteps + (p.maxSteps - p.minSteps) * unitAngle);
  const double stepSize = 1.0 / numSteps;
  const glm::dvec2 perStep = stepSize * (glm::dvec2(viewDirUv) / -viewDirUv.z);
  glm::dvec2 current(0.0);
  double previousHeight = h(uv + current);
  current += perStep;
  double currentHeight = h(uv + current);
  double rayHeight = 1.0 - stepSize;
  for (int i = 0; i < numSteps; ++i) {
    if (currentHeight > rayHeight)
      break;
    previousHeight = currentHeight;
    rayHeight -= stepSize;
    current += perStep;
    currentHeight = h(uv + current);
  }
  double pt0 = rayHeight + stepSize, pt1 = rayHeight;
  double delta0 = pt0 - previousHeight, delta1 = pt1 - currentHeight;
  glm::dvec2 offset(0.0);
  for (int i = 0; i < 3; ++i) {
    const double intersection = (pt0 * delta1 - pt1 * delta0) / (delta1 - delta0);
    offset = (1.0 - intersection) * perStep * double(numSteps);
    currentHeight = h(uv + offset);
    const double delta = intersection - currentHeight;
    if (std::abs(delta) <= 0.01)
      break;
    if (delta < 0.0) {
      delta1 = delta;
      pt1 = intersection;
    } else {
      delta0 = delta;
      pt0 = intersection;
    }
  }
  return uv + offset;
}

struct Comparison {
  double meanTexels = 0.0;
  double withinShare = 0.0;  // share of pixels within 0.05 texel
  long long pixels = 0;
};

class EnginePreview : public OffscreenTest {
 protected:
  renderer::FrameSettings frameAt(float pitchDeg, std::optional<Engine> engine) {
    renderer::FrameSettings frame;
    frame.view.camera.yawDeg = 20.0f;
    frame.view.camera.pitchDeg = pitchDeg;
    frame.view.camera.distance = 1.2f;
    frame.engine = engine;
    return frame;
  }

  // The GPU's final UVs of `engine` (none: Relief's technique) and the eye rays; the test
  // stops at a failed render.
  renderer::ErrorViewInputs render(const core::Material& material, float pitchDeg,
                                   std::optional<Engine> engine) {
    offscreen().setMaterial(material);
    offscreen().setMesh(core::makePlane());
    auto inputs = offscreen().renderErrorViewInputs(frameAt(pitchDeg, engine), kSize, kSize);
    if (!inputs.ok())
      throw std::runtime_error(inputs.error());
    return std::move(inputs).value();
  }

  Comparison compare(const core::Material& material, Engine engine, float pitchDeg,
                     const Replica& replica) {
    const renderer::ErrorViewInputs inputs = render(material, pitchDeg, engine);
    const core::EngineTraceParams params = core::engineTrace(material, engine);
    const Field field;
    Comparison result;
    long long within = 0;
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const float* finalUv = inputs.finalUv.pixel(x, y);
        const float* ray = inputs.eyeRays.pixel(x, y);
        if (finalUv[3] <= 0.0f || finalUv[2] > 0.0f)  // not covered, or minified
          continue;
        const glm::dvec2 entry(ray[0], ray[1]);
        const glm::dvec2 vxy(ray[2], ray[3]);
        const glm::dvec3 V(vxy, std::sqrt(std::max(1e-9, 1.0 - glm::dot(vxy, vxy))));
        const glm::dvec2 expected = replica(field, entry, V, params);
        const double texels =
            glm::length(glm::dvec2(finalUv[0], finalUv[1]) - expected) * kFieldSize;
        result.meanTexels += texels;
        within += texels <= 0.05 ? 1 : 0;
        ++result.pixels;
      }
    }
    if (result.pixels > 0) {
      result.meanTexels /= double(result.pixels);
      result.withinShare = double(within) / double(result.pixels);
    }
    std::printf("%-10s pitch %2.0f: %.4f%% within 0.05 texel, mean %.5f texels, %lld px\n",
                std::string(core::engineInfo(engine).name).c_str(), double(pitchDeg),
                100.0 * result.withinShare, result.meanTexels, result.pixels);
    return result;
  }

  // Mean distance between two renders' final UVs, in texels, over pixels both cover at level 0.
  double meanDifference(const renderer::ErrorViewInputs& a, const renderer::ErrorViewInputs& b) {
    double sum = 0.0;
    long long pixels = 0;
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const float* p = a.finalUv.pixel(x, y);
        const float* q = b.finalUv.pixel(x, y);
        if (p[3] <= 0.0f || q[3] <= 0.0f || p[2] > 0.0f)
          continue;
        sum += std::hypot(p[0] - q[0], p[1] - q[1]) * kFieldSize;
        ++pixels;
      }
    }
    return pixels > 0 ? sum / double(pixels) : 0.0;
  }

  static constexpr int kSize = 200;
};

void expectTranscribed(const Comparison& c) {
  ASSERT_GT(c.pixels, 15000) << "too few pixels at mip level 0";
  EXPECT_GE(c.withinShare, 0.99);
  EXPECT_LT(c.meanTexels, 0.02);
}

TEST_F(EnginePreview, GodotSimpleParallaxIsGodotsOffsetLimiting) {
  for (float pitch : {60.0f, 25.0f})
    expectTranscribed(compare(reliefMaterial(core::Technique::ParallaxLimited), Engine::Godot,
                              pitch, godotReplica));
}

TEST_F(EnginePreview, GodotDeepParallaxIsGodotsLayerRule) {
  for (float pitch : {60.0f, 25.0f})
    expectTranscribed(
        compare(reliefMaterial(core::Technique::Pom), Engine::Godot, pitch, godotReplica));
}

TEST_F(EnginePreview, UnrealIsEpicsPomFunction) {
  for (float pitch : {60.0f, 25.0f})
    expectTranscribed(
        compare(reliefMaterial(core::Technique::Pom), Engine::Unreal, pitch, unrealReplica));
  // A reference plane below the top starts the march above the mesh.
  core::Material raised = reliefMaterial(core::Technique::Pom);
  raised.setParameter(ParamId::HeightBias, -0.5 * kScale);
  EXPECT_DOUBLE_EQ(core::engineTrace(raised, Engine::Unreal).referencePlane, 0.5);
  expectTranscribed(compare(raised, Engine::Unreal, 40.0f, unrealReplica));
}

TEST_F(EnginePreview, UnityUrpIsParallaxOffset1Step) {
  for (float pitch : {60.0f, 25.0f})
    expectTranscribed(
        compare(reliefMaterial(core::Technique::Pom), Engine::Unity, pitch, urpReplica));
}

TEST_F(EnginePreview, UnityHdrpIsPixelDisplacementWithTheSecantStep) {
  for (float pitch : {60.0f, 25.0f})
    expectTranscribed(
        compare(reliefMaterial(core::Technique::Pom), Engine::UnityHdrp, pitch, hdrpReplica));
}

// The modes differ where their algorithms do: Godot steps along view.xy (no 1/view.z), HDRP
// counts steps by the UV-space angle and refines with the secant method, Unreal interpolates
// once, URP takes one step around the relief's middle; Relief's POM counts layers per texel
// crossed. On a smooth field the marches all land near the surface (0.005-0.016 texel apart
// measured); thin walls and few samples at a grazing view tell them apart.
TEST_F(EnginePreview, ModesDifferFromEachOtherAndFromReliefsPom) {
  core::Material material = reliefMaterial(core::Technique::Pom, thinWallField());
  material.setParameter(ParamId::MinSamples, 4);
  material.setParameter(ParamId::MaxSamples, 16);
  constexpr float kPitch = 20.0f;
  std::vector<renderer::ErrorViewInputs> renders;
  std::vector<std::string> names;
  renders.push_back(render(material, kPitch, std::nullopt));
  names.emplace_back("relief-pom");
  for (const core::EngineInfo& info : core::allEngines()) {
    renders.push_back(render(material, kPitch, info.engine));
    names.emplace_back(info.name);
  }
  for (std::size_t i = 0; i < renders.size(); ++i) {
    for (std::size_t j = i + 1; j < renders.size(); ++j) {
      const double difference = meanDifference(renders[i], renders[j]);
      std::printf("%s vs %s: %.4f texels\n", names[i].c_str(), names[j].c_str(), difference);
      EXPECT_GT(difference, 0.5) << names[i] << " vs " << names[j];
    }
  }
}

// Engine modes compile the engine's trace alone: with the same material, the steps view counts
// what the engine reads, and Relief's self-shadowing adds nothing.
TEST_F(EnginePreview, NoSelfShadowingInEngineModes) {
  core::Material material = reliefMaterial(core::Technique::Pom);
  offscreen().setMesh(core::makePlane());
  renderer::FrameSettings frame = frameAt(40.0f, Engine::Godot);
  frame.debugView = core::DebugView::Shadow;
  frame.output = renderer::FrameOutput::FloatData;
  frame.view.light.elevationDeg = 15.0f;
  offscreen().setMaterial(material);
  auto engineShadow = offscreen().render(frame, 64, 64);
  frame.engine.reset();
  auto reliefShadow = offscreen().render(frame, 64, 64);
  ASSERT_TRUE(engineShadow.ok() && reliefShadow.ok());
  // The shadow view shows 1 - occlusion; summed over covered pixels (alpha > 0).
  const auto occlusion = [](const Image& view) {
    double sum = 0.0;
    for (int y = 0; y < view.height(); ++y) {
      for (int x = 0; x < view.width(); ++x) {
        if (view.at(x, y, 3) > 0.0f)
          sum += 1.0 - view.at(x, y, 0);
      }
    }
    return sum;
  };
  EXPECT_EQ(occlusion(engineShadow.value()), 0.0);
  EXPECT_GT(occlusion(reliefShadow.value()), 10.0)
      << "the low light should shadow Relief's own relief";
}

}  // namespace
}  // namespace relief::test
