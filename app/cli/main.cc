#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"procex: procedural extrusions from the command line"};
  app.require_subcommand(1);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
