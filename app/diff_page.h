#pragma once
// The HTML page of `candela diff` (--html): a row per image pair with reference, test and ꟻLIP map
// side by side, the numbers, warnings and why a pair failed (reports/html_page.h draws it).

#include "reports/diff_results.h"
#include "reports/html_page.h"

#include <filesystem>

namespace candela::app {

// The page of `report`, to be written at `page` (image paths are made relative to its folder).
reports::HtmlPage diffPage(const reports::DiffReport& report, const std::filesystem::path& page);

}  // namespace candela::app
