// A plugin built with assertions on (CMakeLists.txt compiles it without NDEBUG, as a plugin's debug
// build is) that registers one name twice: the host must refuse it with one line, not stop inside the
// plugin's own call of Registry::add.

#include "algorithms/registry/plugin_api.h"

#include <memory>

namespace {

void register_careless(shatter::Registries& r) {
  for (int i = 0; i < 2; ++i)
    r.fracturers.add("test-twice", "registered twice (test)", {},
                     [](const shatter::PluginSettings&) -> shatter::Result<std::unique_ptr<shatter::Fracturer>> {
                       return shatter::Error{"never created"};
                     });
}

}  // namespace

#ifdef NDEBUG
#error "careless_plugin.cpp is a test of a plugin built with assertions on"
#endif

SHATTERBENCH_PLUGIN(register_careless)
