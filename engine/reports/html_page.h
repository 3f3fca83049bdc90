#pragma once
// The HTML page of a batch render or an image diff: one self-contained file (inline CSS and
// JavaScript, no network, no external fonts or scripts) with a row per scene or image pair —
// status, error message, thumbnails side by side (reference, new render, ꟻLIP map), the numbers
// in sortable columns, warnings, notes and links to output files — and a filter box and a
// "failures only" toggle. Images are referenced by path beside the page, or inlined as base64
// data: URIs. The output is deterministic (no times, no random ids): equal pages, equal bytes.
//
// What tools/check_html_page.py relies on (keep the two in step):
//   tr.row                 one per row, in display order; data-name, data-status ("failed",
//                          "over-threshold", "warning", "ok"), data-index (the default position)
//   td.num[data-column]    a number cell, data-column = the column's name, data-value = the value
//                          in shortest round-trip form ("" when absent)
//   th[data-key]           a sortable header: data-key "status", "name" or "c<column index>";
//                          data-column "name" or the column's name; aria-sort "ascending" or
//                          "descending" once sorted by it
//   .warnings li, .notes li, .error, .links a   a row's warnings, notes, error message, links
//   figure.thumb img       a thumbnail; figure.thumb .placeholder a missing image
//   input#filter, input#failures-only, #shown (the "N of M rows" line), #lightbox
//   html[data-ready]       set once the script has run without an exception

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace candela::reports {

// A row's outcome. The page sorts failures first, then rows over threshold, then the rest.
enum class RowStatus { Failed, OverThreshold, Warning, Ok };

// "failed", "over threshold", "warning", "ok": the text shown in the page.
std::string_view rowStatusName(RowStatus status);

// An image of a row, shown as a thumbnail that opens full size when clicked.
struct PageImage {
    std::string label;           // under the thumbnail: "reference", "new", "ꟻLIP"
    std::filesystem::path path;  // relative to the page's folder; empty: missing (a placeholder)
    std::string missingText;     // the placeholder's text when `path` is empty ("no reference")
};

// A column of numbers.
struct PageColumn {
    std::string name;  // header text, and the key of PageRow::numbers ("mean", "p99", "ms")
    int decimals = 3;  // shown with this many digits after the point (0…17)
};

// A link to an output file.
struct PageLink {
    std::string label;           // the link's text ("render.exr")
    std::filesystem::path path;  // relative to the page's folder
};

struct PageRow {
    std::string name;  // a scene or image name; any text (it is escaped)
    RowStatus status = RowStatus::Ok;
    std::string error;                       // shown under the name when not empty
    std::vector<PageImage> images;           // side by side, in this order
    std::map<std::string, double> numbers;   // column name → value; a column without one shows "—"
    std::vector<std::string> warnings;       // one line each; collapsed when there are more than 3
    std::vector<std::string> notes;          // one line each; collapsed when there are more than 3
    std::vector<PageLink> links;             // output files
};

struct HtmlPage {
    std::string title;
    std::vector<std::string> summary;  // lines under the title ("85 scenes, 2 failed", "device: …")
    std::vector<PageColumn> columns;   // the number columns, in this order
    std::string errorColumn;           // the column the default order sorts by, descending ("" none)
    std::vector<PageRow> rows;         // in any order: the page shows defaultRowOrder's
};

struct HtmlPageOptions {
    // Embed every image as a base64 data: URI read from `imageFolder` / image path (the page then
    // needs nothing beside it). An image that cannot be read becomes a placeholder naming it.
    bool inlineImages = false;
    std::filesystem::path imageFolder;  // where relative image paths resolve: the page's folder
};

// The default display order, as indices into page.rows: failed rows first, then rows over
// threshold, then the others; within each group by page.errorColumn descending (rows without a
// value, or with NaN, after those with one), ties in input order.
// Throws InternalError when errorColumn names no column.
std::vector<size_t> defaultRowOrder(const HtmlPage& page);

// `text` escaped for HTML text and quoted attribute values (& < > " '). Invalid UTF-8 becomes
// U+FFFD and control characters other than tab and newline are dropped, so names taken from file
// names always give a valid document.
std::string escapeHtml(std::string_view text);

// RFC 4648 base64 of `bytes` (with padding).
std::string base64(std::string_view bytes);

// The page as one HTML document (UTF-8). Reads image files only when options.inlineImages.
// Throws InternalError when a row has a number for a column the page does not declare, when
// errorColumn names no column, or when a column's decimals are outside 0…17.
std::string renderHtmlPage(const HtmlPage& page, const HtmlPageOptions& options = {});

// `file` as a page written at `page` refers to it: relative to the page's folder (both made
// absolute first); `file` itself when no relative path exists.
std::filesystem::path pathFromPage(const std::filesystem::path& file, const std::filesystem::path& page);

// Renders the page and writes it to `path` atomically; relative image paths resolve against
// `path`'s folder. Throws UserError naming the file when it cannot be written.
void writeHtmlPage(const std::filesystem::path& path, const HtmlPage& page, bool inlineImages = false);

}  // namespace candela::reports
