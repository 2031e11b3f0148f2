#pragma once
/// Fracturers by name. Registration is explicit (algorithms/register_all.cpp), never by static
/// initialisers, so a linker cannot silently drop a plugin.

#include "algorithms/fracture/fracturer.h"
#include "algorithms/core/result.h"

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace shatter {

/// Creates a fracturer with its default settings.
using FracturerFactory = std::function<std::unique_ptr<Fracturer>()>;

/// Name -> factory table.
class FracturerRegistry {
 public:
  /// Adds a fracturer; asserts that the name is new.
  void add(std::string name, std::string description, FracturerFactory factory);
  /// Creates the named fracturer, or an error that lists the known names.
  [[nodiscard]] Result<std::unique_ptr<Fracturer>> create(std::string_view name) const;
  /// Registered names, in registration order.
  [[nodiscard]] std::vector<std::string> names() const;
  /// One-line description of a registered name ("" when unknown).
  [[nodiscard]] std::string description(std::string_view name) const;

 private:
  struct Entry {
    std::string name;
    std::string description;
    FracturerFactory factory;
  };
  std::vector<Entry> entries_;
};

}  // namespace shatter
