// GLX protocol numbers the vendor raises errors with (request opcodes, GLX error codes), from
// the X.Org header, which needs Xmd's CARD types first.
#pragma once

#include <X11/Xmd.h>

#include <GL/glxproto.h>
