#pragma once
// Luz's hand-written OpenGL 3.3 core function table (DESIGN.md "GL"). No packaged loader takes
// OSMesa's resolver, so each entry point of function_list.h is a pointer resolved through
// whichever context is current: OSMesaGetProcAddress (headless) or glfwGetProcAddress (window).
//
// The pointers live in namespace luz, so they are the symbols luz::glClear, ... and never clash
// with the glClear that libGL / libOSMesa export. Code inside namespace luz calls them
// unqualified and reads like any GL tutorial: glClear(GL_COLOR_BUFFER_BIT).
//
// <GL/glcorearb.h> gives only types, enums and PFN typedefs here (GL_GLEXT_PROTOTYPES is not
// defined). Never include <GL/gl.h> or <GL/osmesa.h> elsewhere (offscreen_context.cpp only).
#include <GL/glcorearb.h>

namespace luz {

#define LUZ_GL(type, name) extern type name;
#include "gl/function_list.h"
#undef LUZ_GL

// What both resolvers return: OSMESAproc and GLFWglproc are void (*)().
using GlProc = void (*)();
using GlResolver = GlProc (*)(const char* name);

// Resolves every function of function_list.h through `resolve`, for the context current on
// this thread. Throws luz::Error (kind gl) naming the functions the context does not have.
void load_gl_functions(GlResolver resolve);

// "4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits)": for messages and logs.
const char* gl_version_string();

}  // namespace luz
