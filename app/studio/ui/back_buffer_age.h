// back_buffer_age.h -- how many frames old the back buffer of the current
// OpenGL context's window is (GLX_EXT_buffer_age): 1 when it still holds the
// last frame drawn, 0 when unknown (its content undefined). The studio
// redraws only what changed when it knows what the back buffer holds.
#pragma once

namespace procex::studio {

int back_buffer_age();

}  // namespace procex::studio
