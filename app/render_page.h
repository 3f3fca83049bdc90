#pragma once
// The HTML page of a `candela render` run (--html): a row per scene with its images, times, sizes,
// warnings and failure (reports/html_page.h draws it).

#include "render_report.h"
#include "reports/html_page.h"

#include <filesystem>

namespace candela::app {

// The page of `report`, to be written at `page` (image paths are made relative to its folder).
reports::HtmlPage renderPage(const RunReport& report, const std::filesystem::path& page);

}  // namespace candela::app
