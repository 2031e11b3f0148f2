// A command line of one's own: every shatterbench command, with "voro++" beside the built-ins.

#include "voro_fracturer.h"

#include "harness/cli/run_cli.h"

int main(int argc, char** argv) {
  shatter::Registries registries;
  shatter::register_all(registries);
  voro_plugin::register_voro(registries);
  return shatter::run_cli(argc, argv, registries);
}
