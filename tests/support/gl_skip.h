// Render tests skip on a machine without an off-screen OpenGL context, and only then: a
// renderer that fails for another reason (a shader that does not compile, an incomplete
// framebuffer) is a bug of the renderer, reported as a failure.
#pragma once

#include <string>

namespace sinew::test {

// True when OffscreenRenderer::create's `error` says the machine has no usable context.
inline bool no_gl_context(const std::string& error) {
  return error.rfind("no off-screen OpenGL context", 0) == 0 ||
         error.rfind("the off-screen OpenGL context cannot be made current", 0) == 0;
}

}  // namespace sinew::test
