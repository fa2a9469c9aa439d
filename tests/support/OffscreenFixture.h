// A shared offscreen renderer for render tests (one GL context per test process).
#pragma once

#include "renderer/OffscreenRenderer.h"

#include <gtest/gtest.h>

namespace relief::test {

class OffscreenTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    auto created = renderer::OffscreenRenderer::create();
    ASSERT_TRUE(created.ok()) << created.error();
    s_renderer = std::move(created).value().release();
  }
  static void TearDownTestSuite() {
    delete s_renderer;
    s_renderer = nullptr;
  }
  renderer::OffscreenRenderer& offscreen() { return *s_renderer; }

 private:
  static inline renderer::OffscreenRenderer* s_renderer = nullptr;
};

}  // namespace relief::test
