// One OSMesa context for the whole test program, made current before the first test: linked
// into every test executable that draws (luz_test(... GL ...) in tests/CMakeLists.txt).
#include <memory>

#include <gtest/gtest.h>

#include "gl/offscreen_context.h"

namespace luz::test {
namespace {

class GlEnvironment : public ::testing::Environment {
public:
  void SetUp() override { context_ = std::make_unique<gl::OffscreenContext>(); }
  void TearDown() override { context_.reset(); }

private:
  std::unique_ptr<gl::OffscreenContext> context_;
};

[[maybe_unused]] ::testing::Environment* const gl_environment =
    ::testing::AddGlobalTestEnvironment(new GlEnvironment);

}  // namespace
}  // namespace luz::test
