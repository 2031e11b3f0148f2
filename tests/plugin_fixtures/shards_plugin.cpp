// A plugin as an outside project writes it (plugin_api.h), for the plugin tests: the fracturer
// "test-shards" (plane-slice's fracture, called through the host's exported symbols) and the stress
// model "test-count" (connection-count's). Built twice, as two libraries, to test a name taken twice.

#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "algorithms/registry/plugin_api.h"
#include "algorithms/stress/connection_count/connection_count_model.h"

#include <memory>

namespace {

class ShardsFracturer final : public shatter::Fracturer {
 public:
  [[nodiscard]] std::string_view name() const override { return "test-shards"; }
  [[nodiscard]] shatter::Result<std::vector<shatter::Fragment>> fracture(
      const shatter::Mesh& solid, const shatter::FractureParams& params) const override {
    return slicer_.fracture(solid, params);
  }
  [[nodiscard]] shatter::Result<std::optional<shatter::CutPlan>> cut_plan(
      const shatter::Mesh& solid, const shatter::FractureParams& params) const override {
    return slicer_.cut_plan(solid, params);
  }

 private:
  shatter::PlaneSliceFracturer slicer_;
};

void register_shards(shatter::Registries& r) {
  r.fracturers.add("test-shards", "plane-slice, loaded from a plugin (test)", {},
                   [](const shatter::PluginSettings&) -> shatter::Result<std::unique_ptr<shatter::Fracturer>> {
                     return std::unique_ptr<shatter::Fracturer>(std::make_unique<ShardsFracturer>());
                   });
  r.stress_models.add("test-count", "connection-count, loaded from a plugin (test)", {},
                      [](const shatter::PluginSettings& settings) {
                        shatter::StressModelRegistry builtin;
                        shatter::register_connection_count(builtin);
                        return builtin.create("connection-count", settings);
                      });
}

}  // namespace

SHATTERBENCH_PLUGIN(register_shards)
