// The one place GL is included from: libepoxy resolves entry points under both GLX (the window) and
// EGL (headless runs), so every other file includes this instead of a GL header of its own.
#pragma once
#include <epoxy/gl.h>
