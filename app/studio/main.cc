// procex-studio: the node editor, plan and profile editors and a live 3D preview.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "app/studio/editor/options.h"
#include "app/studio/ui/studio_app.h"

int main(int argc, char** argv) {
  procex::studio::Options options;
  try {
    options = procex::studio::parse_options(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "procex-studio: %s\n%s", e.what(), procex::studio::usage().c_str());
    return 2;
  }
  if (options.help) {
    std::fputs(procex::studio::usage().c_str(), stdout);
    return 0;
  }
  // What the studio cannot go on without (a context for the 3D preview) ends it with the reason.
  try {
    return procex::studio::run_studio(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "procex-studio: %s\n", e.what());
    return 1;
  }
}
