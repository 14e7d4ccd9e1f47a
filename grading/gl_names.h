// The names of the OpenGL values a GL exercise's check prints (labs 0 and 3: formats, filters, wraps,
// attachment types, framebuffer statuses, errors), as the OpenGL reference spells them.
#pragma once

#include <string>

namespace shadowlab {

// "GL_LINEAR", "GL_FRAMEBUFFER_COMPLETE", ...; a value not listed as hex ("0x8c3a").
std::string gl_enum_name(int value);

}  // namespace shadowlab
