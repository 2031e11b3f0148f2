// A plugin whose fracturers fail inside a fracture: "test-throws" throws, "test-crashes" dies of a
// segmentation fault. A grid must fail only their cells (a crash: with --timeout, which isolates cells).

#include "algorithms/registry/plugin_api.h"

#include <csignal>
#include <memory>
#include <stdexcept>

namespace {

class FaultyFracturer final : public shatter::Fracturer {
 public:
  explicit FaultyFracturer(bool crash) : crash_(crash) {}
  [[nodiscard]] std::string_view name() const override { return crash_ ? "test-crashes" : "test-throws"; }
  [[nodiscard]] shatter::Result<std::vector<shatter::Fragment>> fracture(
      const shatter::Mesh&, const shatter::FractureParams&) const override {
    if (crash_) std::raise(SIGSEGV);
    throw std::runtime_error("test-throws always throws");
  }

 private:
  bool crash_;
};

void register_faulty(shatter::Registries& r) {
  for (const bool crash : {false, true})
    r.fracturers.add(crash ? "test-crashes" : "test-throws", "fails inside every fracture (test)", {},
                     [crash](const shatter::PluginSettings&) -> shatter::Result<std::unique_ptr<shatter::Fracturer>> {
                       return std::unique_ptr<shatter::Fracturer>(std::make_unique<FaultyFracturer>(crash));
                     });
}

}  // namespace

SHATTERBENCH_PLUGIN(register_faulty)
