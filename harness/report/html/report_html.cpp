#include "harness/report/html/report_html.h"

#include "harness/output/html_page.h"
#include "harness/report/html/report_bundle.h"
#include "harness/report/html/report_data.h"
#include "harness/output/script_json.h"

namespace shatter {

std::string report_html(const ReportInputs& inputs) {
  const std::string data = json_for_script_element(report_data_json(inputs));
  return html_page({.title = "shatterbench report", .root_id = "report", .data_id = kReportDataElementId, .data = data,
                    .script = report_script(), .style = report_style(), .licenses = report_licenses()});
}

}  // namespace shatter
