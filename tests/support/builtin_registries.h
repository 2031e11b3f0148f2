#pragma once
/// The built-in plugins in a registry of their own, for tests that run them by name.

#include "algorithms/registry/registries.h"

namespace shatter::test {

/// A Registries filled by register_all (a new value each call: nothing is shared between tests).
inline Registries builtin_registries() {
  Registries r;
  register_all(r);
  return r;
}

}  // namespace shatter::test
