// The one place that includes OpenGL. Mesa's libOpenGL exports every GL 4.5 entry point, so the
// prototypes are enough and no loader is needed (the renderer targets 3.3 core).
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
