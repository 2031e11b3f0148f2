#include "harness/history/dashboard/dashboard_html.h"

#include "harness/history/dashboard/dashboard_bundle.h"
#include "harness/output/html_page.h"
#include "harness/output/script_json.h"

namespace shatter {

std::string dashboard_html(const nlohmann::json& data) {
  // A branch name is git's bytes: anything not UTF-8 becomes U+FFFD rather than an exception.
  const std::string text =
      json_for_script_element(data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  return html_page({.title = "shatterbench history", .root_id = "dashboard", .data_id = kDashboardDataElementId,
                    .data = text, .script = dashboard_script(), .style = dashboard_style(), .licenses = dashboard_licenses()});
}

}  // namespace shatter
