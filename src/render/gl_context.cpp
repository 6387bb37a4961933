#include "render/gl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <cstring>

namespace sinew::render {

namespace {

std::string egl_error_text(const char* what) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s failed (EGL error 0x%04x)", what, static_cast<unsigned>(eglGetError()));
  return buf;
}

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

// Mesa's surfaceless platform first (never touches a window system), else the default display.
EGLDisplay open_display() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (get_platform_display) {
      EGLDisplay d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      if (d != EGL_NO_DISPLAY) {
        EGLint major = 0, minor = 0;
        if (eglInitialize(d, &major, &minor)) return d;
      }
    }
  }
  EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  EGLint major = 0, minor = 0;
  if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) return d;
  return EGL_NO_DISPLAY;
}

}  // namespace

std::unique_ptr<GlContext> GlContext::create(std::string* error) {
  auto fail = [&](const std::string& why) -> std::unique_ptr<GlContext> {
    if (error) *error = "no off-screen OpenGL context: " + why;
    return nullptr;
  };
  EGLDisplay display = open_display();
  if (display == EGL_NO_DISPLAY) return fail(egl_error_text("opening an EGL display"));
  if (!has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
    return fail("the EGL display has no EGL_KHR_surfaceless_context");
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    return fail(egl_error_text("eglBindAPI(OpenGL)"));
  }
  const EGLint config_attrs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  eglChooseConfig(display, config_attrs, &config, 1, &count);
  const EGLint context_attrs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, count > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT,
                                        context_attrs);
  if (context == EGL_NO_CONTEXT) {
    return fail(egl_error_text("creating an OpenGL 3.3 core context"));
  }
  std::unique_ptr<GlContext> c(new GlContext);
  c->display_ = display;
  c->context_ = context;
  if (!c->make_current()) return fail(egl_error_text("eglMakeCurrent"));
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  c->description_ = std::string("OpenGL ") + (version ? version : "?") + " on " + (renderer ? renderer : "?");
  return c;
}

bool GlContext::make_current() {
  return eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, static_cast<EGLContext>(context_)) == EGL_TRUE;
}

GlContext::~GlContext() {
  if (!display_) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_) eglDestroyContext(display_, static_cast<EGLContext>(context_));
  // The display stays initialised: EGL displays are per process, and terminating it would
  // destroy the contexts of other renderers alive at the same time.
}

}  // namespace sinew::render
