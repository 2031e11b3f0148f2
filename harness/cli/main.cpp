/// shatterbench: benchmark and regression harness for real-time destruction algorithms.

#include "algorithms/registry/registries.h"
#include "harness/cli/run_cli.h"

int main(int argc, char** argv) {
  shatter::Registries registries;
  shatter::register_all(registries);
  return shatter::run_cli(argc, argv, registries);
}
