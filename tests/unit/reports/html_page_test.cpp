// The HTML page of a batch render or an image diff (reports/html_page.h): escaping, the default
// order, empty and large pages, inlined images, no network references, errors. What a browser
// shows is tools/check_html_page.py's job (tests/html).

#include "reports/html_page.h"

#include "assets/image_file.h"
#include "core/errors.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>

namespace candela::reports {
namespace {

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
    return n;
}

// The data-name of every row in the order the page lists them.
std::vector<std::string> rowNames(const std::string& html) {
    static const std::regex row(R"re(<tr class="row [a-z-]+" data-index="\d+" data-name="([^"]*)")re");
    std::vector<std::string> names;
    for (auto it = std::sregex_iterator(html.begin(), html.end(), row); it != std::sregex_iterator(); ++it)
        names.push_back((*it)[1]);
    return names;
}

PageRow row(std::string name, RowStatus status, std::map<std::string, double> numbers = {}) {
    return PageRow{.name = std::move(name), .status = status, .numbers = std::move(numbers)};
}

TEST(HtmlPage, EscapesHostileTextEverywhere) {
    const std::string hostile = "<script>alert(\"x\")</script> & 'q'";
    const std::string escaped = "&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt; &amp; &#39;q&#39;";
    HtmlPage page{.title = hostile, .summary = {hostile}, .columns = {{.name = hostile}}, .errorColumn = hostile};
    PageRow r = row(hostile, RowStatus::Failed, {{hostile, 1.0}});
    r.error = hostile;
    r.images = {{.label = hostile, .path = "a\"b<c>.png"}, {.label = hostile, .missingText = hostile}};
    r.warnings = {hostile};
    r.notes = {hostile};
    r.links = {{.label = hostile, .path = "x\" onclick=\"y.exr"}};
    page.rows = {r};
    const std::string html = renderHtmlPage(page);
    EXPECT_EQ(count(html, "<script"), 1u) << "only the page's own script element";
    EXPECT_EQ(count(html, hostile), 0u);
    EXPECT_EQ(count(html, "alert(\""), 0u);
    EXPECT_EQ(count(html, "onclick=\""), 0u);
    // title ×2, summary, column header and its data-column, the cell's data-column, row name ×2,
    // error, two image labels ×2 (alt/aria-label and caption), placeholder text, warning, note, link
    EXPECT_EQ(count(html, escaped), 17u);
    EXPECT_NE(html.find("src=\"a%22b%3Cc%3E.png\""), std::string::npos);
    EXPECT_NE(html.find("href=\"x%22%20onclick%3D%22y.exr\""), std::string::npos);
}

TEST(HtmlPage, EscapeKeepsValidUtf8AndReplacesInvalidBytes) {
    EXPECT_EQ(escapeHtml("caf\xC3\xA9 \xEA\x9F\xBBLIP \xF0\x9F\x99\x82"), "caf\xC3\xA9 \xEA\x9F\xBBLIP \xF0\x9F\x99\x82");
    const std::string fffd = "\xEF\xBF\xBD";
    EXPECT_EQ(escapeHtml("a\xFF" "b"), "a" + fffd + "b");
    EXPECT_EQ(escapeHtml("\xC0\xAF"), fffd + fffd);          // overlong '/'
    EXPECT_EQ(escapeHtml("\xED\xA0\x80"), fffd + fffd + fffd);  // a UTF-16 surrogate
    EXPECT_EQ(escapeHtml("\xE2\x82"), fffd + fffd);          // truncated
    EXPECT_EQ(escapeHtml("a\x01\x7F\tb\nc\rd"), "a\tb\ncd");
}

TEST(HtmlPage, Base64MatchesRfc4648) {
    EXPECT_EQ(base64(""), "");
    EXPECT_EQ(base64("f"), "Zg==");
    EXPECT_EQ(base64("fo"), "Zm8=");
    EXPECT_EQ(base64("foo"), "Zm9v");
    EXPECT_EQ(base64("foob"), "Zm9vYg==");
    EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
    EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
    EXPECT_EQ(base64(std::string("\xFF\xFE\x00", 3)), "//4A");
}

TEST(HtmlPage, DefaultOrderIsFailedThenOverThresholdThenByErrorDescending) {
    HtmlPage page{.columns = {{.name = "mean"}, {.name = "ms"}}, .errorColumn = "mean"};
    page.rows = {
        row("ok small", RowStatus::Ok, {{"mean", 1.0}}),
        row("failed, no numbers", RowStatus::Failed),
        row("over small", RowStatus::OverThreshold, {{"mean", 0.5}}),
        row("warning large", RowStatus::Warning, {{"mean", 3.0}, {"ms", 100}}),
        row("over large", RowStatus::OverThreshold, {{"mean", 2.0}}),
        row("ok absent", RowStatus::Ok, {{"ms", 5}}),
        row("failed large", RowStatus::Failed, {{"mean", 5.0}}),
        row("ok nan", RowStatus::Ok, {{"mean", NAN}}),
        row("ok tie second", RowStatus::Ok, {{"mean", 1.0}}),
    };
    EXPECT_EQ(defaultRowOrder(page), (std::vector<size_t>{6, 1, 4, 2, 3, 0, 8, 5, 7}));
    EXPECT_EQ(rowNames(renderHtmlPage(page)),
              (std::vector<std::string>{"failed large", "failed, no numbers", "over large", "over small", "warning large",
                                        "ok small", "ok tie second", "ok absent", "ok nan"}));
    page.errorColumn.clear();  // no error column: status groups only, input order within them
    EXPECT_EQ(defaultRowOrder(page), (std::vector<size_t>{1, 6, 2, 4, 0, 3, 5, 7, 8}));
}

TEST(HtmlPage, NumbersUseTheColumnFormatAndShowAbsentValues) {
    HtmlPage page{.columns = {{.name = "mean", .decimals = 2}, {.name = "count", .decimals = 0}, {.name = "p99"}}};
    page.rows = {row("a", RowStatus::Ok, {{"mean", 0.125}, {"count", 1234.0}}), row("b", RowStatus::Ok, {{"mean", NAN}})};
    const std::string html = renderHtmlPage(page);
    EXPECT_NE(html.find("data-column=\"mean\" data-value=\"0.125\">0.12<"), std::string::npos);  // round half to even
    EXPECT_NE(html.find("data-column=\"count\" data-value=\"1234\">1234<"), std::string::npos);
    EXPECT_NE(html.find("data-column=\"p99\" data-value=\"\">\u2014<"), std::string::npos);
    EXPECT_NE(html.find("data-column=\"mean\" data-value=\"NaN\">NaN<"), std::string::npos);
}

TEST(HtmlPage, EmptyPageRendersWithNoRows) {
    const std::string html = renderHtmlPage(HtmlPage{.title = "nothing", .columns = {{.name = "mean"}}});
    EXPECT_TRUE(rowNames(html).empty());
    EXPECT_NE(html.find("<p id=\"empty\">No rows.</p>"), std::string::npos);
    EXPECT_NE(html.find("0 of 0 rows"), std::string::npos);
    EXPECT_EQ(html.find(">images</th>"), std::string::npos);
}

TEST(HtmlPage, ThousandRowsRenderInOrderAndDeterministically) {
    HtmlPage page{.title = "many", .columns = {{.name = "mean"}}, .errorColumn = "mean"};
    for (int i = 0; i < 1000; ++i) {
        PageRow r = row("scene " + std::to_string(i), i % 97 == 0 ? RowStatus::Failed : RowStatus::Ok, {{"mean", double(i % 10)}});
        r.images = {{.label = "new", .path = "scene_" + std::to_string(i) + ".png"}};
        page.rows.push_back(std::move(r));
    }
    const std::string html = renderHtmlPage(page);
    const auto names = rowNames(html);
    ASSERT_EQ(names.size(), 1000u);
    EXPECT_EQ(names[0], "scene 679");  // failed (i % 97 == 0) with the largest mean (679 % 10 = 9)
    EXPECT_EQ(html, renderHtmlPage(page));
}

TEST(HtmlPage, InlinedImagesAreDataUrisOfTheFilesBytes) {
    const candela::test::TempDir dir("candela_html_page");
    const std::vector<uint8_t> rgba{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    assets::writePng(dir / "new render.png", 2, 2, rgba);
    std::ifstream in(dir / "new render.png", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 8u);

    HtmlPage page;
    PageRow r = row("a", RowStatus::Ok);
    r.images = {{.label = "new", .path = "new render.png"}, {.label = "reference", .path = "gone.png"}, {.label = "ꟻLIP"}};
    page.rows = {r};
    const std::string inlined = renderHtmlPage(page, {.inlineImages = true, .imageFolder = dir.path()});
    EXPECT_NE(inlined.find("<img src=\"data:image/png;base64," + base64(bytes) + "\" alt=\"new\""), std::string::npos);
    EXPECT_EQ(count(inlined, "src=\"data:"), 1u);
    EXPECT_NE(inlined.find(">cannot read gone.png</div>"), std::string::npos);
    EXPECT_NE(inlined.find(">missing</div>"), std::string::npos);
    // Valid base64 from "data:" to the closing quote: the alphabet, padding only at the end.
    static const std::regex dataUri(R"re(src="data:image/png;base64,([A-Za-z0-9+/]*={0,2})")re");
    EXPECT_TRUE(std::regex_search(inlined, dataUri));

    const std::string beside = renderHtmlPage(page);
    EXPECT_NE(beside.find("<a href=\"new%20render.png\"><img src=\"new%20render.png\" alt=\"new\""), std::string::npos);
    EXPECT_NE(beside.find("src=\"gone.png\""), std::string::npos);  // not checked without inlining
    EXPECT_EQ(count(beside, "src=\"data:"), 0u);
}

TEST(HtmlPage, ReferencesNothingOnTheNetwork) {
    HtmlPage page{.title = "t", .summary = {"s"}, .columns = {{.name = "mean"}}, .errorColumn = "mean"};
    PageRow r = row("a", RowStatus::Warning, {{"mean", 1}});
    r.images = {{.label = "new", .path = "a.png"}, {.label = "abs", .path = "/tmp/b.png"}};
    r.links = {{.label = "c:d", .path = "c:d.exr"}};
    r.warnings = {"w"};
    page.rows = {r};
    const std::string html = renderHtmlPage(page);
    for (const char* banned : {"http:", "https:", "ftp:", "src=\"//", "href=\"//", "<link", "@import", "url(", "fetch(",
                               "XMLHttpRequest", "<iframe"})
        EXPECT_EQ(html.find(banned), std::string::npos) << banned;
    EXPECT_NE(html.find("href=\"c%3Ad.exr\""), std::string::npos);  // not read as a "c:" scheme
    EXPECT_NE(html.find("src=\"file:///tmp/b.png\""), std::string::npos);
}

TEST(HtmlPage, ManyWarningsStartCollapsed) {
    PageRow few = row("few", RowStatus::Warning), many = row("many", RowStatus::Warning);
    few.warnings = {"one", "two", "three"};
    many.warnings = {"1", "2", "3", "4"};
    many.notes = {"n"};
    const std::string html = renderHtmlPage(HtmlPage{.rows = {few, many}});
    EXPECT_NE(html.find("<details class=\"warnings\" open><summary>3 warnings</summary>"), std::string::npos);
    EXPECT_NE(html.find("<details class=\"warnings\"><summary>4 warnings</summary>"), std::string::npos);
    EXPECT_NE(html.find("<details class=\"notes\" open><summary>1 note</summary>"), std::string::npos);
}

TEST(HtmlPage, ContractErrorsAreInternalErrors) {
    HtmlPage page{.columns = {{.name = "mean"}}, .errorColumn = "p99"};
    EXPECT_THROW(renderHtmlPage(page), InternalError);
    EXPECT_THROW(defaultRowOrder(page), InternalError);
    page.errorColumn = "mean";
    page.rows = {row("a", RowStatus::Ok, {{"ms", 1}})};
    EXPECT_THROW(renderHtmlPage(page), InternalError);
    page.rows.clear();
    page.columns[0].decimals = 18;
    EXPECT_THROW(renderHtmlPage(page), InternalError);
}

TEST(HtmlPage, WritesTheFileOrNamesItInTheError) {
    const candela::test::TempDir dir("candela_html_page");
    const HtmlPage page{.title = "written", .rows = {row("a", RowStatus::Ok)}};
    writeHtmlPage(dir / "out" / "page.html", page);
    std::ifstream in(dir / "out" / "page.html", std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text, renderHtmlPage(page));

    std::ofstream(dir / "a file") << "x";
    const std::filesystem::path bad = dir / "a file" / "page.html";
    try {
        writeHtmlPage(bad, page);
        FAIL() << "no error";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace candela::reports
