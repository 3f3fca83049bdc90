#pragma once
// The style sheet and the script that html_page.cpp writes inline into every page. They rely on
// the markup described in reports/html_page.h (row classes, data attributes, element ids).

#include <string_view>

namespace candela::reports {

// CSS for the page: the table, the status colours, thumbnails side by side at a fixed box size
// (smaller below 1100 px of width), the lightbox.
std::string_view htmlPageStyle();

// JavaScript for the page: sorting by a header click (ascending, then descending; absent values
// last either way; ties in the default order), the filter box and the "failures only" toggle
// (both O(rows)), the lightbox that shows a clicked thumbnail at full size. No network access.
std::string_view htmlPageScript();

}  // namespace candela::reports
