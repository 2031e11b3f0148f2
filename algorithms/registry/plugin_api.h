#pragma once
/// What a plugin implements: a shared library, built outside this repository against the installed
/// package (target shatterbench::plugin), that adds its fracturers and stress models to a run of the
/// shatterbench command (`--plugin PATH`, SHATTERBENCH_PLUGIN_PATH; docs/plugins.md).
///
///   #include "algorithms/registry/plugin_api.h"
///   void register_mine(shatter::Registries& r) {
///     r.fracturers.add("mine", "my fracturer (one line)", {}, make_mine);
///   }
///   SHATTERBENCH_PLUGIN(register_mine)
///
/// Design note: the loader first reads a plain C descriptor (the plugin ABI, version and C++ ABI the
/// plugin was built with) and calls the plugin's C++ only when all three match the host's: the C++
/// types a plugin shares with the host (Registries, Mesh, Fracturer, std::function) have no stable
/// layout across versions or compilers. The plugin registers into an empty Registries of its own;
/// the host then adds those entries beside the built-ins, refusing a name that is taken. A plugin
/// links no library of this project: its calls into the algorithms resolve against the shatterbench
/// executable, which exports them.

#include "algorithms/core/fragment.h"
#include "algorithms/core/mesh.h"
#include "algorithms/core/plugin_settings.h"
#include "algorithms/fracture/fracturer.h"
#include "algorithms/registry/plugin_abi.h"
#include "algorithms/registry/registries.h"

#include <functional>
#include <string>
#include <vector>

extern "C" {

/// Version 1 of the descriptor a plugin's entry point returns. Fields are only ever added at the end
/// under a new entry point name (shatterbench_plugin_v2, ...).
struct ShatterbenchPluginV1 {
  int abi;                                          ///< SHATTERBENCH_PLUGIN_ABI the plugin was built with
  const char* version;                              ///< SHATTERBENCH_VERSION it was built with
  int cxx_abi;                                      ///< the compiler's C++ ABI (__GXX_ABI_VERSION)
  void (*register_plugins)(shatter::Registries&);  ///< adds the plugin's fracturers and stress models
  /// The layout of what the plugin shares with the host, as its compiler saw it: a build with another
  /// standard library ABI (_GLIBCXX_USE_CXX11_ABI, _GLIBCXX_DEBUG) or other headers differs here.
  unsigned layout;                                  ///< shatterbench_plugin_layout()
};

}  // extern "C"

/// A fingerprint of the layout of the types a plugin shares with the host (their sizes and the
/// standard library's ABI switches), the same in the host and the plugin only when both see the
/// same headers the same way.
inline unsigned shatterbench_plugin_layout() {
  unsigned h = 2166136261u;
  const auto mix = [&h](unsigned long v) {
    for (int i = 0; i < 8; ++i) {
      h = (h ^ static_cast<unsigned>(v & 0xffu)) * 16777619u;
      v >>= 8;
    }
  };
  mix(sizeof(std::string));
  mix(sizeof(std::vector<int>));
  mix(sizeof(std::function<void()>));
  mix(sizeof(shatter::Registries));
  mix(sizeof(shatter::Mesh));
  mix(sizeof(shatter::Fragment));
  mix(sizeof(shatter::FractureParams));
  mix(sizeof(shatter::PluginSettings));
#ifdef _GLIBCXX_USE_CXX11_ABI
  mix(100 + _GLIBCXX_USE_CXX11_ABI);
#endif
#ifdef _GLIBCXX_DEBUG
  mix(200);
#endif
  return h;
}

/// The name of the entry point the loader looks up.
#define SHATTERBENCH_PLUGIN_ENTRY "shatterbench_plugin_v1"

/// Defines the entry point of a plugin whose registration function is `register_function`
/// (void(shatter::Registries&)). Once per plugin, at namespace scope.
#define SHATTERBENCH_PLUGIN(register_function)                                                    \
  extern "C" __attribute__((visibility("default"))) const ShatterbenchPluginV1* shatterbench_plugin_v1() { \
    static const ShatterbenchPluginV1 descriptor{SHATTERBENCH_PLUGIN_ABI, SHATTERBENCH_VERSION,  \
                                                 __GXX_ABI_VERSION, &(register_function),       \
                                                 shatterbench_plugin_layout()};                 \
    return &descriptor;                                                                           \
  }
