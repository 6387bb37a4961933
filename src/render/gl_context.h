// An OpenGL context without a window: EGL on Mesa's surfaceless platform
// (EGL_MESA_platform_surfaceless; llvmpipe when there is no GPU), OpenGL 3.3
// core profile, no default framebuffer (the renderer draws into its own).
// No X server or Wayland compositor is needed. Debian 12's Mesa 22.3 gives
// "4.5 (Core Profile) Mesa 22.3.6" on llvmpipe here.
#pragma once

#include <memory>
#include <string>

namespace sinew::render {

class GlContext {
 public:
  // nullptr with a one-line reason in *error when no context can be created
  // (no EGL library or display, no OpenGL 3.3 core support).
  static std::unique_ptr<GlContext> create(std::string* error);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  bool make_current();
  // "OpenGL <version> on <renderer>".
  const std::string& description() const { return description_; }

 private:
  GlContext() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string description_;
};

}  // namespace sinew::render
