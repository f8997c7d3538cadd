// The one place ui/ includes OpenGL: core-profile 3.3+ prototypes from glcorearb.h, resolved by
// linking GLVND's libGL/libOpenGL, which dispatches to whichever context is current — a GLFW
// window (GLX) or an EGL headless context — so no per-context loader is needed.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
