// AdaptiveResolution: the resolution of the viewport's frames while the user drags, chosen from
// the measured frame time so that a drag stays fluid on a slow GL (llvmpipe, VMs, remote
// desktops). A frame's cost is modelled as proportional to its pixels: the shaders' per-pixel
// work (parallax marching, shadow rays) dominates every technique on such a GL. The fixed part of
// a frame makes small frames look dearer per pixel, so the model errs towards smaller frames.
#pragma once

namespace relief::ui::inline viewport {

class AdaptiveResolution {
 public:
  // What an interactive frame may cost: the 66 ms of a 15 Hz update less what each frame costs
  // outside the viewport's drawing: Qt composing the window and repainting the slider and status
  // bar, measured at 25 to 30 ms a frame on llvmpipe in a 1600x1000 window (tools/bench-interaction
  // --budget 1: 10 ms frames 34 ms apart).
  static constexpr double kDefaultBudgetMs = 35.0;
  // Scales are multiples of 1/kScaleSteps (so the reduced framebuffer is not reallocated on every
  // frame) from kMinimumScale to 1.
  static constexpr int kScaleSteps = 16;
  static constexpr float kMinimumScale = 2.0f / float(kScaleSteps);

  double budgetMilliseconds() const { return m_budgetMs; }
  void setBudgetMilliseconds(double milliseconds) { m_budgetMs = milliseconds; }

  // A frame of `pixels` pixels took `milliseconds` (drawn and finished).
  void recordFrame(double milliseconds, double pixels);
  // The scale of the next interactive frame of `fullPixels` pixels at full resolution: 1 when
  // nothing was measured yet or a full frame fits the budget. A scale goes up only when the
  // measurements leave room for two steps, so it does not flip between neighbours.
  float nextInteractiveScale(double fullPixels);
  // A full-resolution frame was shown (the input rested): the next drag starts afresh.
  void resetScale() { m_scale = 1.0f; }
  // How many full-resolution rows of `width` pixels one frame may draw within the budget, for
  // refining a reduced frame in bands: at least height / maxBands (so a refinement ends within
  // maxBands frames however slow the GL), at most `height` (nothing measured yet: all at once).
  int rowsWithinBudget(int width, int height, int maxBands) const;

 private:
  double m_budgetMs = kDefaultBudgetMs;
  double m_msPerPixel = 0.0;  // 0: nothing measured yet
  float m_scale = 1.0f;       // the last interactive scale
};

}  // namespace relief::ui::inline viewport
