#pragma once
/// Stress models by name. Registration is explicit (algorithms/register_all.cpp), never by static
/// initialisers, so a linker cannot silently drop a model.

#include "algorithms/core/result.h"
#include "algorithms/stress/stress_model.h"

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace shatter {

/// Creates a stress model with its default settings.
using StressModelFactory = std::function<std::unique_ptr<StressModel>()>;

/// Name -> factory table.
class StressModelRegistry {
 public:
  /// Adds a model; asserts that the name is new.
  void add(std::string name, std::string description, StressModelFactory factory);
  /// Creates the named model, or an error that lists the known names.
  [[nodiscard]] Result<std::unique_ptr<StressModel>> create(std::string_view name) const;
  /// Registered names, in registration order.
  [[nodiscard]] std::vector<std::string> names() const;
  /// One-line description of a registered name ("" when unknown).
  [[nodiscard]] std::string description(std::string_view name) const;

 private:
  struct Entry {
    std::string name;
    std::string description;
    StressModelFactory factory;
  };
  std::vector<Entry> entries_;
};

}  // namespace shatter
