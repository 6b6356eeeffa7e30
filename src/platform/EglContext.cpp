#include "platform/EglContext.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace penumbra::platform {

static bool hasClientExtension(const char* name) {
    return epoxy_has_egl_extension(EGL_NO_DISPLAY, name);
}

static EGLDisplay openSurfaceless() {
    if (!hasClientExtension("EGL_MESA_platform_surfaceless")) return EGL_NO_DISPLAY;
    return eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
}

// First device whose display initialises (NVIDIA exposes its GPUs this way), or device `index`
// when one is asked for ("device:N"); an index past the devices is an error that lists them.
static EGLDisplay openDevice(int index = -1) {
    if (!hasClientExtension("EGL_EXT_platform_device")) return EGL_NO_DISPLAY;
    EGLint count = 0;
    if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) return EGL_NO_DISPLAY;
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    eglQueryDevicesEXT(count, devices.data(), &count);
    if (index >= 0) {
        if (index >= count)
            throw std::runtime_error("EGL: there is no device " + std::to_string(index) + "; this machine has " +
                                     std::to_string(count) + " EGL device(s), 0.." + std::to_string(count - 1));
        EGLDisplay dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<std::size_t>(index)], nullptr);
        EGLint major = 0, minor = 0;
        if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor))
            throw std::runtime_error("EGL: device " + std::to_string(index) + " cannot be initialised (eglInitialize failed)");
        return dpy;
    }
    for (EGLDeviceEXT dev : devices) {
        EGLDisplay dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, dev, nullptr);
        EGLint major = 0, minor = 0;
        if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, &major, &minor)) return dpy;
    }
    return EGL_NO_DISPLAY;
}

std::unique_ptr<EglContext> EglContext::create(const std::string& platform, bool debug) {
    std::string chosen = platform;
    if (const char* env = std::getenv("PENUMBRA_EGL_PLATFORM"); env && platform == "auto") chosen = env;

    EGLDisplay dpy = EGL_NO_DISPLAY;
    std::string used;
    if (chosen == "auto" || chosen == "surfaceless") {
        dpy = openSurfaceless();
        used = "surfaceless";
    }
    if (dpy == EGL_NO_DISPLAY && (chosen == "auto" || chosen == "device")) {
        dpy = openDevice();
        used = "device";
    }
    if (chosen.rfind("device:", 0) == 0) {
        dpy = openDevice(std::atoi(chosen.c_str() + 7));
        used = chosen;
    }
    if (dpy == EGL_NO_DISPLAY)
        throw std::runtime_error("EGL: no usable display (platform '" + chosen +
                                 "'); is libegl-mesa0 or the NVIDIA EGL driver installed?");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(dpy, &major, &minor))
        throw std::runtime_error("EGL: eglInitialize failed on the " + used + " platform");

    const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                    EGL_NONE};
    EGLConfig config = nullptr;
    EGLint numConfigs = 0;
    if (!eglChooseConfig(dpy, configAttribs, &config, 1, &numConfigs) || numConfigs < 1)
        config = EGL_NO_CONFIG_KHR;
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("EGL: eglBindAPI(EGL_OPENGL_API) failed");

    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                     EGL_CONTEXT_MINOR_VERSION, 5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE,
                                     EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, contextAttribs);
    if (ctx == EGL_NO_CONTEXT) {
        eglTerminate(dpy);
        throw std::runtime_error("EGL: cannot create an OpenGL 4.5 core context (error 0x" +
                                 std::to_string(eglGetError()) + ")");
    }
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        eglDestroyContext(dpy, ctx);
        eglTerminate(dpy);
        throw std::runtime_error("EGL: eglMakeCurrent without a surface failed");
    }
    std::unique_ptr<EglContext> result(new EglContext());
    result->display_ = dpy;
    result->context_ = ctx;
    result->platform_ = used;
    return result;
}

EglContext::~EglContext() {
    if (!display_) return;
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
}

std::string glDeviceDescription() {
    auto str = [](GLenum e) {
        const auto* s = reinterpret_cast<const char*>(glGetString(e));
        return std::string(s ? s : "?");
    };
    return str(GL_RENDERER) + " | " + str(GL_VERSION);
}

}  // namespace penumbra::platform
