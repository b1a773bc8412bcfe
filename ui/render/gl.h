#pragma once
// OpenGL 3.3 core entry points. Linux's libGL (glvnd) exports every core function, so the
// prototypes are enough and no loader library is needed; GLFW must not pull in its own GL header.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
