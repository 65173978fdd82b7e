// OpenGL 3.3 core entry points without a loader library: GLVND's libOpenGL (the
// previewer) and libOSMesa (the display test) both export every core function,
// so the prototypes are enough. Include this before anything else that might
// include GL/gl.h (GLFW: define GLFW_INCLUDE_NONE), and never in a file that
// includes ImGui's own loader header.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
