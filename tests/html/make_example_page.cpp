// Writes an example HTML page (reports/html_page.h) for the browser test (tests/html/CMakeLists.txt):
//
//   make_example_page OUT_DIR
//
// OUT_DIR/beside/example.html  with its PNG thumbnails in OUT_DIR/beside/images/
// OUT_DIR/inline/example.html  the same page with the images inlined (nothing beside it)
// OUT_DIR/empty/example.html   a page without rows
// OUT_DIR/large/example.html   1,000 rows sharing three thumbnails in OUT_DIR/large/images/
//
// The example has seven rows — one failed (its new render and ꟻLIP map missing), one over
// threshold with five warnings, one with a warning, four ok, one with a hostile name — whose
// default order, numbers and warnings tests/html/example_page.json states; the large page's
// orders are in tests/html/large_page.json.

#include "assets/image_file.h"
#include "core/cache_files.h"
#include "core/errors.h"
#include "reports/html_page.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace fs = std::filesystem;
using namespace candela;
using namespace candela::reports;

namespace {

constexpr uint32_t kWidth = 96, kHeight = 72;

// A lit sphere on a gradient in the row's hue; `shift` moves the highlight (the "new" render).
std::vector<uint8_t> render(float hue, float shift) {
    std::vector<uint8_t> rgba(size_t(kWidth) * kHeight * 4);
    const float base[3] = {0.5f + 0.5f * std::cos(hue), 0.5f + 0.5f * std::cos(hue - 2.1f), 0.5f + 0.5f * std::cos(hue + 2.1f)};
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            const float u = (x + 0.5f) / kWidth * 2 - 1, v = (y + 0.5f) / kHeight * 1.5f - 0.75f;
            const float r2 = (u * u + v * v) / 0.4f;
            float light = 0.25f + 0.2f * (1 - float(y) / kHeight);
            if (r2 < 1) {
                const float z = std::sqrt(1 - r2);
                light = 0.15f + 0.85f * std::max(0.0f, (-u * (0.4f + shift) - v * 0.5f + z) / 1.3f);
            }
            uint8_t* p = &rgba[(size_t(y) * kWidth + x) * 4];
            for (int c = 0; c < 3; ++c) p[c] = uint8_t(std::clamp(light * base[c] * 255.0f, 0.0f, 255.0f));
            p[3] = 255;
        }
    return rgba;
}

// A heat map of the difference between two renders (black → red → yellow), as a ꟻLIP map looks.
std::vector<uint8_t> heatMap(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    std::vector<uint8_t> rgba(a.size());
    for (size_t i = 0; i < a.size(); i += 4) {
        const float d = std::min(1.0f, (std::abs(a[i] - b[i]) + std::abs(a[i + 1] - b[i + 1]) + std::abs(a[i + 2] - b[i + 2])) / 60.0f);
        rgba[i] = uint8_t(255 * std::min(1.0f, d * 2));
        rgba[i + 1] = uint8_t(255 * std::max(0.0f, d * 2 - 1));
        rgba[i + 2] = uint8_t(40 * (1 - d));
        rgba[i + 3] = 255;
    }
    return rgba;
}

struct Example {
    const char* name;
    const char* file;  // image file stem
    reports::RowStatus status;
    float hue, shift;
    std::map<std::string, double> numbers;
};

reports::PageRow exampleRow(const fs::path& dir, const Example& e) {
    reports::PageRow row{.name = e.name, .status = e.status, .numbers = e.numbers};
    const std::string stem = std::string("images/") + e.file;
    const auto reference = render(e.hue, 0), rendered = render(e.hue, e.shift);
    assets::writePng(dir / (stem + ".reference.png"), kWidth, kHeight, reference);
    row.images.push_back({.label = "reference", .path = stem + ".reference.png"});
    if (e.status == reports::RowStatus::Failed) {
        row.images.push_back({.label = "new", .missingText = "not rendered"});
        row.images.push_back({.label = "ꟻLIP", .missingText = "no ꟻLIP map"});
        return row;
    }
    assets::writePng(dir / (stem + ".new.png"), kWidth, kHeight, rendered);
    assets::writePng(dir / (stem + ".flip.png"), kWidth, kHeight, heatMap(reference, rendered));
    row.images.push_back({.label = "new", .path = stem + ".new.png"});
    row.images.push_back({.label = "ꟻLIP", .path = stem + ".flip.png"});
    row.links = {{.label = "new.png", .path = stem + ".new.png"}, {.label = "flip.png", .path = stem + ".flip.png"}};
    return row;
}

reports::HtmlPage examplePage(const fs::path& dir) {
    reports::HtmlPage page{.title = "Example batch render",
                  .summary = {"7 scenes, 1 failed, 1 over threshold, 1 warning", "device: llvmpipe (LLVM 15.0.6, 256 bits)",
                              "12.3 s"},
                  .columns = {{.name = "ꟻLIP mean", .decimals = 4}, {.name = "p99", .decimals = 1}, {.name = "ms", .decimals = 1}},
                  .errorColumn = "ꟻLIP mean"};
    const Example examples[] = {
        {"DamagedHelmet", "damaged_helmet", reports::RowStatus::Ok, 0.3f, 0.02f, {{"ꟻLIP mean", 0.0123}, {"p99", 2}, {"ms", 41.25}}},
        {"broken.gltf", "broken", reports::RowStatus::Failed, 1.0f, 0, {}},
        {"MetalRoughSpheres", "metal_rough_spheres", reports::RowStatus::OverThreshold, 2.0f, 0.6f,
         {{"ꟻLIP mean", 0.2051}, {"p99", 24}, {"ms", 18.5}}},
        {"Fox (t=1.5)", "fox", reports::RowStatus::Warning, 3.0f, 0.05f, {{"ꟻLIP mean", 0.0311}, {"p99", 5.5}, {"ms", 22}}},
        {"SimpleInstancing", "simple_instancing", reports::RowStatus::Ok, 4.0f, 0.01f, {{"ꟻLIP mean", 0.0042}, {"p99", 1}}},
        {"<b>Sponza</b> & \"friends\"", "sponza", reports::RowStatus::Ok, 5.0f, 0.03f, {{"ꟻLIP mean", 0.0198}, {"p99", 3}, {"ms", 95.75}}},
        {"TextureSettings", "texture_settings", reports::RowStatus::Ok, 5.8f, 0.015f, {{"ꟻLIP mean", 0.0087}, {"p99", 2}, {"ms", 9.5}}},
    };
    for (const Example& e : examples) page.rows.push_back(exampleRow(dir, e));
    page.rows[0].notes = {"3 draws, 1 material"};
    page.rows[1].error = "broken.gltf: accessor 3 reads past the end of buffer 0 (byte 4096 of 2048)";
    page.rows[2].warnings = {"ꟻLIP mean 0.2051 is over the threshold 0.05", "p99 24.0 is over the threshold 10.0",
                             "KHR_materials_volume: thickness texture ignored", "3 NaN pixels in the new render",
                             "render time 18.5 ms is 2.1× the reference's"};
    page.rows[3].warnings = {"animation sampled at t = 1.5 s clamps to the last key"};
    return page;
}

// "scene 0000" … "scene 0999": failed when i % 100 == 7 (their ꟻLIP map missing), over threshold
// when i % 50 == 3, ok otherwise; ꟻLIP mean (i × 37 mod 1000) / 1000, ms i / 10.
reports::HtmlPage largePage(const fs::path& dir) {
    const auto reference = render(0.5f, 0), rendered = render(0.5f, 0.2f);
    assets::writePng(dir / "images/reference.png", kWidth, kHeight, reference);
    assets::writePng(dir / "images/new.png", kWidth, kHeight, rendered);
    assets::writePng(dir / "images/flip.png", kWidth, kHeight, heatMap(reference, rendered));
    reports::HtmlPage page{.title = "1,000 rows", .summary = {"1000 scenes, 10 failed, 20 over threshold"},
                  .columns = {{.name = "ꟻLIP mean"}, {.name = "ms", .decimals = 1}}, .errorColumn = "ꟻLIP mean"};
    for (int i = 0; i < 1000; ++i) {
        char name[16];
        std::snprintf(name, sizeof name, "scene %04d", i);
        const reports::RowStatus status = i % 100 == 7 ? reports::RowStatus::Failed : i % 50 == 3 ? reports::RowStatus::OverThreshold : reports::RowStatus::Ok;
        reports::PageRow row{.name = name, .status = status, .numbers = {{"ꟻLIP mean", (i * 37 % 1000) / 1000.0}, {"ms", i / 10.0}}};
        row.images = {{.label = "reference", .path = "images/reference.png"}, {.label = "new", .path = "images/new.png"},
                      {.label = "ꟻLIP", .path = "images/flip.png"}};
        if (status == reports::RowStatus::Failed) row.images[2] = {.label = "ꟻLIP", .missingText = "no ꟻLIP map"};
        page.rows.push_back(std::move(row));
    }
    return page;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_example_page OUT_DIR\n");
        return 2;
    }
    try {
        const fs::path out = argv[1];
        fs::remove_all(out);
        fs::create_directories(out / "beside" / "images");
        const reports::HtmlPage page = examplePage(out / "beside");
        reports::writeHtmlPage(out / "beside" / "example.html", page);
        const std::string inlined = reports::renderHtmlPage(page, {.inlineImages = true, .imageFolder = out / "beside"});
        writeFileAtomically(out / "inline" / "example.html",
                            [&](std::ostream& o) { o.write(inlined.data(), std::streamsize(inlined.size())); });
        writeHtmlPage(out / "empty" / "example.html",
                      reports::HtmlPage{.title = "No rows", .summary = {"0 scenes"}, .columns = {{.name = "ꟻLIP mean"}}, .errorColumn = "ꟻLIP mean"});
        fs::create_directories(out / "large" / "images");
        writeHtmlPage(out / "large" / "example.html", largePage(out / "large"));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    return 0;
}
