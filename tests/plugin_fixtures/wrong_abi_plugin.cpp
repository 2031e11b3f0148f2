// A plugin built against another shatterbench (its descriptor says version 9.9.0, plugin ABI 999):
// the loader must refuse it before calling anything of it.

#include "algorithms/registry/plugin_api.h"

#include <cstdlib>

namespace {

void register_nothing(shatter::Registries&) { std::abort(); }  // never called

}  // namespace

extern "C" __attribute__((visibility("default"))) const ShatterbenchPluginV1* shatterbench_plugin_v1() {
  static const ShatterbenchPluginV1 descriptor{999, "9.9.0", __GXX_ABI_VERSION, &register_nothing, 0};
  return &descriptor;
}
