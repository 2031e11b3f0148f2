#pragma once
/// The version a plugin is checked against when it is loaded (plugin_api.h). The build refuses to
/// configure when SHATTERBENCH_VERSION differs from the project's version in CMakeLists.txt.

/// This shatterbench's version (major.minor.patch).
#define SHATTERBENCH_VERSION "0.1.0"

/// The layout of the plugin descriptor and of what a plugin shares with the host (Registries and
/// the interfaces it holds). A loaded plugin must have been built with the same value, the same
/// SHATTERBENCH_VERSION and the same C++ ABI as the host.
#define SHATTERBENCH_PLUGIN_ABI 4
