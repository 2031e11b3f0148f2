#pragma once
/// Loads plugins (algorithms/registry/plugin_api.h) into a run's registries: the shared libraries
/// named by `--plugin PATH` and by the SHATTERBENCH_PLUGIN_PATH variable (docs/plugins.md).

#include "algorithms/core/result.h"
#include "algorithms/registry/registries.h"

#include <map>
#include <string>
#include <vector>

namespace shatter {

/// Where each registered name came from: "built-in" or the plugin's path (for messages and `list`).
using PluginOrigins = std::map<std::string, std::string>;

/// The plugin files SHATTERBENCH_PLUGIN_PATH names, in order: a ':'-separated list of files and
/// folders (a folder stands for its files ending in ".so", sorted by name); empty entries are
/// skipped. An entry that does not exist is an Error naming it.
Result<std::vector<std::string>> plugin_path_files(const std::string& variable);

/// Loads each plugin of `paths` in order and adds what it registers to `registries`. A plugin is
/// refused (an Error of one line naming its path, nothing of it added) when it cannot be loaded, has
/// no entry point, was built against another plugin ABI, version or C++ ABI, throws while
/// registering, registers a description of more than one line, or registers a name that is taken
/// (the message names who took it: "built-in" or the other plugin's path). `origins` gains each
/// added name. Loaded libraries stay loaded for the life of the process.
Status load_plugins(const std::vector<std::string>& paths, Registries& registries, PluginOrigins& origins);

/// The plugin files loaded so far in this process, each with its size and modification time
/// ("path/size/time;..."): part of what identifies the running code (the pre-fracture cache's key),
/// so a rebuilt plugin never meets the fragments of its earlier build.
std::string loaded_plugins_identity();

}  // namespace shatter
