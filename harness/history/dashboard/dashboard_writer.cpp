#include "harness/history/dashboard/dashboard_writer.h"

#include "harness/output/atomic_file.h"
#include "harness/output/output_folder.h"

namespace shatter {

Status write_dashboard(std::string_view page, const std::filesystem::path& dir) {
  return write_folder_atomically(dir, [&](const std::filesystem::path& staging) {
    return write_file_atomically(staging / kDashboardFileName, page);
  });
}

}  // namespace shatter
