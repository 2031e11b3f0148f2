#pragma once
/// Plugins by name: one table per interface (fracturers, stress models). Registration is explicit
/// (algorithms/registry/register_all.cpp for the built-ins, one `add` per plugin for a program's own),
/// never by static initialisers, so a linker cannot silently drop a plugin. A registry is a value: the
/// caller makes one, fills it and passes it to the runs.

#include "algorithms/core/plugin_settings.h"
#include "algorithms/core/result.h"

#include <cassert>
#include <functional>
#include <memory>
#include <span>
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
  /// Creates a plugin from its settings (empty: every default); an error names the bad key.
  using Factory = std::function<Result<std::unique_ptr<Plugin>>(const PluginSettings&)>;

  /// Adds a plugin with its documented settings. `add` never stops the program (it runs inside
  /// plugins, whatever their build): a name taken twice, a name with white space or a description of
  /// more than one line is reported by `problem`, which the plugin loader and run_cli check.
  void add(std::string name, std::string description, std::vector<SettingDoc> settings, Factory factory) {
    entries_.push_back({std::move(name), std::move(description), std::move(settings), std::move(factory)});
  }

  /// The first entry that breaks the registry's rules, as "<kind> '<name>' <what>" (empty when none):
  /// names unique, not empty and without white space; descriptions one line.
  [[nodiscard]] std::string problem() const {
    const std::string kind(plugin_kind<Plugin>);
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      const Entry& e = entries_[i];
      if (e.name.empty() || e.name.find_first_of(" \t\r\n") != std::string::npos)
        return kind + " name '" + e.name + "' is empty or holds white space";
      if (e.description.find_first_of("\r\n") != std::string::npos)
        return kind + " '" + e.name + "' has a description of more than one line";
      for (std::size_t j = 0; j < i; ++j)
        if (entries_[j].name == e.name) return kind + " '" + e.name + "' is registered twice";
    }
    return {};
  }

  /// Creates the named plugin from `settings`, or an error that lists the known names (unknown name)
  /// or names the key (bad settings).
  [[nodiscard]] Result<std::unique_ptr<Plugin>> create(std::string_view name,
                                                       const PluginSettings& settings = {}) const {
    if (const Entry* e = find(name)) return e->factory(settings);
    std::string known;
    for (const Entry& e : entries_) known += (known.empty() ? "" : ", ") + e.name;
    return Error{"unknown " + std::string(plugin_kind<Plugin>) + " '" + std::string(name) + "' (known: " + known +
                 ")"};
  }

  /// True when `name` is registered.
  [[nodiscard]] bool contains(std::string_view name) const { return find(name) != nullptr; }

  /// Moves every entry of `other` (none of whose names may be registered here) after this one's.
  void absorb(Registry&& other) {
    for (Entry& e : other.entries_) {
      assert(!contains(e.name) && "plugin registered twice");
      entries_.push_back(std::move(e));
    }
    other.entries_.clear();
  }

  /// Replaces each entry's factory by `wrap(name, factory)`: how the plugin loader puts its guard
  /// (harness/plugins/plugin_guard.h) between a plugin's code and the host.
  void wrap_factories(const std::function<Factory(const std::string& name, Factory factory)>& wrap) {
    for (Entry& e : entries_) e.factory = wrap(e.name, std::move(e.factory));
  }

  /// Registered names, in registration order.
  [[nodiscard]] std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const Entry& e : entries_) out.push_back(e.name);
    return out;
  }

  /// One-line description of a registered name ("" when unknown).
  [[nodiscard]] std::string description(std::string_view name) const {
    const Entry* e = find(name);
    return e ? e->description : std::string();
  }

  /// The documented settings of a registered name (empty when unknown or without settings).
  [[nodiscard]] std::span<const SettingDoc> settings(std::string_view name) const {
    const Entry* e = find(name);
    return e ? std::span<const SettingDoc>(e->settings) : std::span<const SettingDoc>();
  }

 private:
  struct Entry {
    std::string name;
    std::string description;
    std::vector<SettingDoc> settings;
    Factory factory;
  };
  [[nodiscard]] const Entry* find(std::string_view name) const {
    for (const Entry& e : entries_)
      if (e.name == name) return &e;
    return nullptr;
  }
  std::vector<Entry> entries_;
};

}  // namespace shatter
