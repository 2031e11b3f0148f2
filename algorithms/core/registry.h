#pragma once
/// Plugins by name: one table per interface (fracturers, stress models). Registration is explicit
/// (algorithms/register_all.cpp), never by static initialisers, so a linker cannot silently drop a
/// plugin.

#include "algorithms/core/result.h"

#include <cassert>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace shatter {

/// What a registry of `Plugin` calls its entries in messages ("fracturer", "stress model").
template <class Plugin>
inline constexpr std::string_view plugin_kind = "plugin";

/// Name -> factory table of `Plugin` implementations, in registration order.
template <class Plugin>
class Registry {
 public:
  /// Creates a plugin with its default settings.
  using Factory = std::function<std::unique_ptr<Plugin>()>;

  /// Adds a plugin; asserts that the name is new and the description one line.
  void add(std::string name, std::string description, Factory factory) {
    assert(description.find('\n') == std::string::npos);
    for ([[maybe_unused]] const Entry& e : entries_) assert(e.name != name && "plugin registered twice");
    entries_.push_back({std::move(name), std::move(description), std::move(factory)});
  }

  /// Creates the named plugin, or an error that lists the known names.
  [[nodiscard]] Result<std::unique_ptr<Plugin>> create(std::string_view name) const {
    for (const Entry& e : entries_)
      if (e.name == name) return e.factory();
    std::string known;
    for (const Entry& e : entries_) known += (known.empty() ? "" : ", ") + e.name;
    return Error{"unknown " + std::string(plugin_kind<Plugin>) + " '" + std::string(name) + "' (known: " + known +
                 ")"};
  }

  /// Registered names, in registration order.
  [[nodiscard]] std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const Entry& e : entries_) out.push_back(e.name);
    return out;
  }

  /// One-line description of a registered name ("" when unknown).
  [[nodiscard]] std::string description(std::string_view name) const {
    for (const Entry& e : entries_)
      if (e.name == name) return e.description;
    return {};
  }

 private:
  struct Entry {
    std::string name;
    std::string description;
    Factory factory;
  };
  std::vector<Entry> entries_;
};

}  // namespace shatter
