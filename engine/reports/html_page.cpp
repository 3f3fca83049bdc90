#include "reports/html_page.h"

#include "core/cache_files.h"
#include "core/errors.h"
#include "reports/html_page_resources.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <ostream>

namespace candela::reports {

namespace fs = std::filesystem;

namespace {

constexpr int kCollapseAfter = 3;  // warnings and notes beyond this many start collapsed

int statusGroup(RowStatus status) {
    return status == RowStatus::Failed ? 0 : status == RowStatus::OverThreshold ? 1 : 2;
}

std::string_view statusClass(RowStatus status) {
    switch (status) {
    case RowStatus::Failed: return "failed";
    case RowStatus::OverThreshold: return "over-threshold";
    case RowStatus::Warning: return "warning";
    case RowStatus::Ok: return "ok";
    }
    return "ok";
}

size_t columnIndex(const HtmlPage& page, const std::string& name) {
    for (size_t i = 0; i < page.columns.size(); ++i)
        if (page.columns[i].name == name) return i;
    throw InternalError("HTML page '" + page.title + "': no column named '" + name + "'");
}

void validate(const HtmlPage& page) {
    if (!page.errorColumn.empty()) columnIndex(page, page.errorColumn);
    for (const PageColumn& column : page.columns)
        if (column.decimals < 0 || column.decimals > 17)
            throw InternalError("HTML page '" + page.title + "': column '" + column.name + "' has " +
                                std::to_string(column.decimals) + " decimals (0…17)");
    for (const PageRow& row : page.rows)
        for (const auto& [name, value] : row.numbers) columnIndex(page, name);
}

// A path as a URL reference: every byte but unreserved characters and '/' percent-encoded (a
// ':' in a file name would otherwise read as a scheme). Absolute paths become file: URLs.
std::string urlOf(const fs::path& path) {
    const std::string text = path.generic_string();
    std::string url = path.is_absolute() ? "file://" : "";
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (std::isalnum(u) && u < 0x80) url += c;
        else if (c == '-' || c == '.' || c == '_' || c == '~' || c == '/') url += c;
        else {
            url += '%';
            url += "0123456789ABCDEF"[u >> 4];
            url += "0123456789ABCDEF"[u & 15];
        }
    }
    return url;
}

std::string_view mimeType(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".png") return "image/png";
    if (ext == ".jpg" || ext == ".jpeg") return "image/jpeg";
    if (ext == ".webp") return "image/webp";
    if (ext == ".gif") return "image/gif";
    if (ext == ".svg") return "image/svg+xml";
    if (ext == ".bmp") return "image/bmp";
    return "application/octet-stream";
}

bool readFile(const fs::path& path, std::string& bytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return !in.bad();
}

// The shortest text that reads back as `value` in JavaScript's Number() ("" never: NaN is "NaN").
std::string jsNumber(double value) {
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "Infinity" : "-Infinity";
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string displayNumber(double value, int decimals) {
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[512];  // fixed notation of 1e308 with 17 decimals fits
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
    return std::string(buffer, result.ptr);
}

void appendImage(std::string& out, const PageImage& image, const HtmlPageOptions& options) {
    const std::string label = escapeHtml(image.label);
    out += "<figure class=\"thumb\">";
    std::string missing = image.missingText.empty() ? "missing" : image.missingText;
    std::string src;
    if (!image.path.empty()) {
        if (!options.inlineImages) {
            src = urlOf(image.path);
        } else {
            const fs::path file = image.path.is_absolute() ? image.path : options.imageFolder / image.path;
            std::string bytes;
            if (readFile(file, bytes)) src = "data:" + std::string(mimeType(file)) + ";base64," + base64(bytes);
            else missing = "cannot read " + image.path.generic_string();
        }
    }
    if (src.empty()) {
        out += "<div class=\"placeholder\" role=\"img\" aria-label=\"" + label + "\">" + escapeHtml(missing) + "</div>";
    } else if (options.inlineImages) {
        out += "<img src=\"" + src + "\" alt=\"" + label + "\" loading=\"lazy\" decoding=\"async\">";
    } else {
        // A link too, for opening the file in a tab; the script shows it in the lightbox instead.
        out += "<a href=\"" + src + "\"><img src=\"" + src + "\" alt=\"" + label +
               "\" loading=\"lazy\" decoding=\"async\"></a>";
    }
    out += "<figcaption>" + label + "</figcaption></figure>";
}

void appendLines(std::string& out, std::string_view cssClass, std::string_view noun, const std::vector<std::string>& lines) {
    if (lines.empty()) return;
    out += "<details class=\"";
    out += cssClass;
    out += lines.size() > size_t(kCollapseAfter) ? "\">" : "\" open>";
    out += "<summary>" + std::to_string(lines.size()) + " ";
    out += noun;
    if (lines.size() != 1) out += 's';
    out += "</summary><ul>";
    for (const std::string& line : lines) out += "<li>" + escapeHtml(line) + "</li>";
    out += "</ul></details>";
}

void appendRow(std::string& out, const HtmlPage& page, const PageRow& row, size_t index, bool imageColumn,
               const HtmlPageOptions& options) {
    const std::string status(statusClass(row.status));
    out += "<tr class=\"row " + status + "\" data-index=\"" + std::to_string(index) + "\" data-name=\"" +
           escapeHtml(row.name) + "\" data-status=\"" + status + "\">\n";
    out += "<td class=\"status\"><span class=\"badge\">" + std::string(rowStatusName(row.status)) + "</span></td>\n";

    out += "<td class=\"about\"><div class=\"name\">" + escapeHtml(row.name) + "</div>";
    if (!row.error.empty()) out += "<p class=\"error\">" + escapeHtml(row.error) + "</p>";
    appendLines(out, "warnings", "warning", row.warnings);
    appendLines(out, "notes", "note", row.notes);
    if (!row.links.empty()) {
        out += "<ul class=\"links\">";
        for (const PageLink& link : row.links)
            out += "<li><a href=\"" + urlOf(link.path) + "\">" + escapeHtml(link.label) + "</a></li>";
        out += "</ul>";
    }
    out += "</td>\n";

    if (imageColumn) {
        out += "<td class=\"images\"><div class=\"thumbs\">";
        for (const PageImage& image : row.images) appendImage(out, image, options);
        out += "</div></td>\n";
    }
    for (const PageColumn& column : page.columns) {
        const std::string name = escapeHtml(column.name);
        const auto it = row.numbers.find(column.name);
        if (it == row.numbers.end())
            out += "<td class=\"num absent\" data-column=\"" + name + "\" data-value=\"\">\u2014</td>\n";
        else
            out += "<td class=\"num\" data-column=\"" + name + "\" data-value=\"" + jsNumber(it->second) + "\">" +
                   displayNumber(it->second, column.decimals) + "</td>\n";
    }
    out += "</tr>\n";
}

}  // namespace

std::string_view rowStatusName(RowStatus status) {
    switch (status) {
    case RowStatus::Failed: return "failed";
    case RowStatus::OverThreshold: return "over threshold";
    case RowStatus::Warning: return "warning";
    case RowStatus::Ok: return "ok";
    }
    return "ok";
}

std::vector<size_t> defaultRowOrder(const HtmlPage& page) {
    std::vector<size_t> order(page.rows.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    const bool byError = !page.errorColumn.empty();
    if (byError) columnIndex(page, page.errorColumn);
    // NaN when a row has no usable value: those go after the rows that have one.
    std::vector<double> error(page.rows.size(), NAN);
    if (byError)
        for (size_t i = 0; i < page.rows.size(); ++i)
            if (const auto it = page.rows[i].numbers.find(page.errorColumn); it != page.rows[i].numbers.end())
                error[i] = it->second;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        const int ga = statusGroup(page.rows[a].status), gb = statusGroup(page.rows[b].status);
        if (ga != gb) return ga < gb;
        const bool ha = !std::isnan(error[a]), hb = !std::isnan(error[b]);
        if (ha != hb) return ha;
        return ha && error[a] > error[b];
    });
    return order;
}

std::string escapeHtml(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    const auto* s = reinterpret_cast<const unsigned char*>(text.data());
    const size_t n = text.size();
    for (size_t i = 0; i < n;) {
        const unsigned char c = s[i];
        if (c < 0x80) {
            switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default:
                if (c >= 0x20 && c != 0x7f) out += char(c);
                else if (c == '\t' || c == '\n') out += char(c);
            }
            ++i;
            continue;
        }
        // A multi-byte sequence: the lead byte's length, continuation bytes, no overlong forms,
        // no surrogates, nothing past U+10FFFF.
        size_t length = 0;
        unsigned char low = 0x80, high = 0xbf;
        if (c >= 0xc2 && c <= 0xdf) length = 2;
        else if (c >= 0xe0 && c <= 0xef) {
            length = 3;
            if (c == 0xe0) low = 0xa0;
            if (c == 0xed) high = 0x9f;
        } else if (c >= 0xf0 && c <= 0xf4) {
            length = 4;
            if (c == 0xf0) low = 0x90;
            if (c == 0xf4) high = 0x8f;
        }
        bool valid = length != 0 && i + length <= n;
        for (size_t k = 1; valid && k < length; ++k) {
            const unsigned char lo = k == 1 ? low : 0x80, hi = k == 1 ? high : 0xbf;
            valid = s[i + k] >= lo && s[i + k] <= hi;
        }
        if (valid) {
            out.append(text.data() + i, length);
            i += length;
        } else {
            out += "\xEF\xBF\xBD";  // U+FFFD
            ++i;
        }
    }
    return out;
}

std::string base64(std::string_view bytes) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    size_t i = 0;
    for (; i + 3 <= bytes.size(); i += 3) {
        const uint32_t v = uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8 | uint8_t(bytes[i + 2]);
        out += kAlphabet[v >> 18];
        out += kAlphabet[(v >> 12) & 63];
        out += kAlphabet[(v >> 6) & 63];
        out += kAlphabet[v & 63];
    }
    if (const size_t rest = bytes.size() - i; rest > 0) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
        if (rest == 2) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        out += kAlphabet[v >> 18];
        out += kAlphabet[(v >> 12) & 63];
        out += rest == 2 ? kAlphabet[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

std::string renderHtmlPage(const HtmlPage& page, const HtmlPageOptions& options) {
    validate(page);
    const bool imageColumn = std::any_of(page.rows.begin(), page.rows.end(), [](const PageRow& r) { return !r.images.empty(); });
    const std::string title = escapeHtml(page.title);

    std::string out;
    out += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    // Nothing but the page itself, images beside it or inlined, and links: no network, by rule.
    out += "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src 'self' file: data:; "
           "style-src 'unsafe-inline'; script-src 'unsafe-inline'\">\n";
    out += "<title>" + title + "</title>\n<style>\n";
    out += htmlPageStyle();
    out += "</style>\n</head>\n<body>\n<header>\n<h1>" + title + "</h1>\n<div class=\"summary\">\n";
    for (const std::string& line : page.summary) out += "<p>" + escapeHtml(line) + "</p>\n";
    out += "</div>\n</header>\n";

    out += "<div class=\"controls\">\n"
           "<label>Filter <input id=\"filter\" type=\"search\" placeholder=\"name, error or warning text\" autocomplete=\"off\"></label>\n"
           "<label><input id=\"failures-only\" type=\"checkbox\"> failures only</label>\n"
           "<span id=\"shown\">" + std::to_string(page.rows.size()) + " of " + std::to_string(page.rows.size()) +
           " rows</span>\n<span class=\"hint\">Click a column header to sort; click a thumbnail for full size.</span>\n</div>\n";

    out += "<main>\n<table>\n<thead><tr><th class=\"status\" data-key=\"status\" tabindex=\"0\">status</th>"
           "<th data-key=\"name\" data-column=\"name\" tabindex=\"0\">name</th>";
    if (imageColumn) out += "<th class=\"images\">images</th>";
    for (size_t c = 0; c < page.columns.size(); ++c) {
        const std::string name = escapeHtml(page.columns[c].name);
        out += "<th class=\"num\" data-key=\"c" + std::to_string(c) + "\" data-column=\"" + name + "\" tabindex=\"0\">" + name + "</th>";
    }
    out += "</tr></thead>\n<tbody id=\"rows\">\n";
    const std::vector<size_t> order = defaultRowOrder(page);
    for (size_t i = 0; i < order.size(); ++i) appendRow(out, page, page.rows[order[i]], i, imageColumn, options);
    out += "</tbody>\n</table>\n";
    if (page.rows.empty()) out += "<p id=\"empty\">No rows.</p>\n";
    out += "</main>\n<div id=\"lightbox\" hidden><img alt=\"\"><p></p></div>\n<script>\n";
    out += htmlPageScript();
    out += "</script>\n</body>\n</html>\n";
    return out;
}

void writeHtmlPage(const fs::path& path, const HtmlPage& page, bool inlineImages) {
    const std::string html = renderHtmlPage(page, {.inlineImages = inlineImages, .imageFolder = path.parent_path()});
    writeFileAtomically(path, [&](std::ostream& out) { out.write(html.data(), std::streamsize(html.size())); });
}

std::filesystem::path pathFromPage(const std::filesystem::path& file, const std::filesystem::path& page) {
    std::error_code ec;
    const std::filesystem::path folder = std::filesystem::absolute(page, ec).parent_path();
    const std::filesystem::path relative = std::filesystem::absolute(file, ec).lexically_relative(folder);
    return relative.empty() ? file : relative;
}

}  // namespace candela::reports
