// SPDX-License-Identifier: MIT
#include <volpost/render/HeadlessContext.hpp>

#include <epoxy/egl.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace volpost {
namespace {

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

[[noreturn]] void fail(const std::string& what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", eglGetError());
  throw std::runtime_error("headless OpenGL: " + what + " (EGL error " + code + ")");
}

}  // namespace

struct HeadlessContext::Impl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  std::string platform;
};

HeadlessContext::HeadlessContext() : impl_(std::make_unique<Impl>()) {
  // eglGetPlatformDisplayEXT, not the EGL 1.5 entry point: libepoxy cannot resolve core
  // 1.5 functions before a display exists.
  const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasExtension(clientExt, "EGL_EXT_platform_base"))
    throw std::runtime_error("headless OpenGL: EGL_EXT_platform_base is not available");
  if (hasExtension(clientExt, "EGL_MESA_platform_surfaceless")) {
    impl_->display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    impl_->platform = "surfaceless";
  }
  if (impl_->display == EGL_NO_DISPLAY && hasExtension(clientExt, "EGL_EXT_platform_device")) {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (eglQueryDevicesEXT(8, devices, &count) && count > 0) {
      impl_->display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
      impl_->platform = "device";
    }
  }
  if (impl_->display == EGL_NO_DISPLAY) fail("no surfaceless or device EGL display");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(impl_->display, &major, &minor)) fail("eglInitialize failed");
  if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API) failed");
  // Surface type 0: no window or pbuffer is needed (the default would ask for windows).
  const EGLint configAttribs[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config;
  EGLint numConfigs = 0;
  if (!eglChooseConfig(impl_->display, configAttribs, &config, 1, &numConfigs) || numConfigs < 1)
    fail("no EGL config for desktop OpenGL");
  const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                   EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  impl_->context = eglCreateContext(impl_->display, config, EGL_NO_CONTEXT, contextAttribs);
  if (impl_->context == EGL_NO_CONTEXT) fail("cannot create an OpenGL 4.5 core context");
  makeCurrent();
}

HeadlessContext::~HeadlessContext() {
  if (impl_->display == EGL_NO_DISPLAY) return;
  eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (impl_->context != EGL_NO_CONTEXT) eglDestroyContext(impl_->display, impl_->context);
  eglTerminate(impl_->display);
}

void HeadlessContext::makeCurrent() {
  if (!eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context))
    fail("eglMakeCurrent without a surface failed");
}

std::string HeadlessContext::platform() const { return impl_->platform; }

}  // namespace volpost
