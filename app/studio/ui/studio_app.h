// studio_app.h -- procex-studio's window: GLFW + OpenGL 3.3 + Dear ImGui.
#pragma once

#include "app/studio/editor/options.h"

namespace procex::studio {

// Opens the window and runs until the user quits (or, with --screenshot, until
// the image is saved). Returns the process exit code.
int run_studio(const Options& options);

}  // namespace procex::studio
