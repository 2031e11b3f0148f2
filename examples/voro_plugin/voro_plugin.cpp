// The plugin's entry point: what `shatterbench --plugin voro_plugin.so` calls.

#include "voro_fracturer.h"

#include "algorithms/registry/plugin_api.h"

SHATTERBENCH_PLUGIN(voro_plugin::register_voro)
