#include "harness/plugins/plugin_loader.h"

#include "algorithms/registry/plugin_api.h"
#include "harness/plugins/plugin_guard.h"
#include "harness/plugins/shared_object_check.h"

#include <dlfcn.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <string_view>

namespace shatter {
namespace {

namespace fs = std::filesystem;

/// Every plugin file loaded in this process (dlopen's libraries are the process's too).
std::vector<std::string>& loaded_files() {
  static std::vector<std::string> files;
  return files;
}

/// "built-in" for names registered before any plugin.
std::string origin_of(const PluginOrigins& origins, const std::string& name) {
  const auto it = origins.find(name);
  return it == origins.end() ? std::string("built-in") : it->second;
}

/// Error unless every name of `staged` is free in `host`.
template <class Plugin>
Status check_entries(const Registry<Plugin>& staged, const Registry<Plugin>& host, const PluginOrigins& origins,
                     const std::string& path) {
  if (const std::string problem = staged.problem(); !problem.empty()) return Error{"plugin " + path + ": " + problem};
  for (const std::string& name : staged.names())
    if (host.contains(name))
      return Error{"plugin " + path + ": " + std::string(plugin_kind<Plugin>) + " '" + name + "' is already registered by " +
                   origin_of(origins, name)};
  return {};
}

/// Checks the plugin at `handle` and adds what it registers; `path` names it in messages.
Status register_plugin(void* handle, const std::string& path, Registries& registries, PluginOrigins& origins) {
  using Entry = const ShatterbenchPluginV1* (*)();
  void* symbol = dlsym(handle, SHATTERBENCH_PLUGIN_ENTRY);
  if (symbol == nullptr)
    return Error{"plugin " + path + ": no " SHATTERBENCH_PLUGIN_ENTRY " entry point (not a shatterbench plugin)"};
  const ShatterbenchPluginV1* d = reinterpret_cast<Entry>(symbol)();
  if (d == nullptr) return Error{"plugin " + path + ": its " SHATTERBENCH_PLUGIN_ENTRY " gives no descriptor"};
  // The ABI first: only a descriptor of this layout may be read further (its version is a pointer).
  if (d->abi != SHATTERBENCH_PLUGIN_ABI)
    return Error{"plugin " + path + ": built for plugin ABI " + std::to_string(d->abi) + ", this is shatterbench "
                 SHATTERBENCH_VERSION " (plugin ABI " + std::to_string(SHATTERBENCH_PLUGIN_ABI) +
                 "): rebuild it against this version"};
  const std::string version = d->version != nullptr ? std::string(d->version) : std::string("unknown");
  if (version != SHATTERBENCH_VERSION)
    return Error{"plugin " + path + ": built against shatterbench " + one_printable_line(version, 40) +
                 ", this is shatterbench " SHATTERBENCH_VERSION ": rebuild it against this version"};
  if (d->cxx_abi != __GXX_ABI_VERSION)
    return Error{"plugin " + path + ": built with C++ ABI " + std::to_string(d->cxx_abi) + ", this is " +
                 std::to_string(__GXX_ABI_VERSION)};
  if (d->layout != shatterbench_plugin_layout())
    return Error{"plugin " + path + ": built with other shatterbench headers or another standard library ABI "
                 "(layout " + std::to_string(d->layout) + ", this is " + std::to_string(shatterbench_plugin_layout()) +
                 "): rebuild it against this installation"};
  if (d->register_plugins == nullptr)
    return Error{"plugin " + path + ": its " SHATTERBENCH_PLUGIN_ENTRY " gives no registration function"};
  Registries staged;
  try {
    d->register_plugins(staged);
  } catch (const std::exception& e) {
    return Error{"plugin " + path + ": registration threw: " + e.what()};
  } catch (...) {
    return Error{"plugin " + path + ": registration threw a non-standard exception"};
  }
  if (Status s = check_entries(staged.fracturers, registries.fracturers, origins, path); !s) return s;
  if (Status s = check_entries(staged.stress_models, registries.stress_models, origins, path); !s) return s;
  // From here on every object the plugin makes is reached through the host's guard.
  guard_registrations(staged);
  loaded_files().push_back(path);
  for (const std::string& name : staged.fracturers.names()) origins[name] = path;
  for (const std::string& name : staged.stress_models.names()) origins[name] = path;
  registries.fracturers.absorb(std::move(staged.fracturers));
  registries.stress_models.absorb(std::move(staged.stress_models));
  return {};
}

Status load_plugin(const std::string& path, Registries& registries, PluginOrigins& origins) {
  // RTLD_NOW: an unresolved symbol is an error here, not a crash in the middle of a run. Relative
  // paths are made explicit so that dlopen never searches the library path for them.
  const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
  if (Status s = check_shared_object(path); !s) return s;
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    return Error{"plugin " + path + ": cannot load: " + std::string(why != nullptr ? why : "unknown error")};
  }
  Status s = register_plugin(handle, path, registries, origins);
  // A refused plugin is unloaded (its staged entries, whose code it holds, are gone by now); an
  // accepted one stays loaded for the life of the process.
  if (!s) dlclose(handle);
  return s;
}

}  // namespace

Result<std::vector<std::string>> plugin_path_files(const std::string& variable) {
  std::vector<std::string> files;
  std::size_t start = 0;
  while (start <= variable.size()) {
    std::size_t end = variable.find(':', start);
    if (end == std::string::npos) end = variable.size();
    const std::string entry = variable.substr(start, end - start);
    start = end + 1;
    if (entry.empty()) continue;
    std::error_code ec;
    const fs::file_status status = fs::status(entry, ec);
    if (ec || !fs::exists(status)) return Error{"SHATTERBENCH_PLUGIN_PATH: " + entry + " does not exist"};
    if (!fs::is_directory(status)) {
      files.push_back(entry);
      continue;
    }
    std::vector<std::string> in_folder;
    fs::directory_iterator it(entry, ec);
    for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
      std::error_code file_ec;  // a file that cannot be stat'ed (a dangling link) is skipped
      if (it->path().extension() == ".so" && it->is_regular_file(file_ec)) in_folder.push_back(it->path().string());
    }
    if (ec) return Error{"SHATTERBENCH_PLUGIN_PATH: cannot read " + entry + ": " + ec.message()};
    std::sort(in_folder.begin(), in_folder.end());
    files.insert(files.end(), in_folder.begin(), in_folder.end());
  }
  return files;
}

std::string loaded_plugins_identity() {
  std::string id;
  for (const std::string& path : loaded_files()) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    id += (ec ? path : absolute.string());
    const auto size = fs::file_size(path, ec);
    if (!ec) id += "/" + std::to_string(size);
    const auto time = fs::last_write_time(path, ec);
    if (!ec) id += "/" + std::to_string(time.time_since_epoch().count());
    id += ";";
  }
  return id;
}

Status load_plugins(const std::vector<std::string>& paths, Registries& registries, PluginOrigins& origins) {
  for (const std::string& path : paths)
    if (Status s = load_plugin(path, registries, origins); !s) return s;
  return {};
}

}  // namespace shatter
