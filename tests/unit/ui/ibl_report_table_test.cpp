// The ibl-report figures the viewer's environment panel shows (ui/ibl_report_table.h).
#include "core/errors.h"
#include "ui/ibl_report_table.h"

#include <gtest/gtest.h>

namespace candela::ui {
namespace {

TEST(IblReportTable, CompiledInReportsParseAndHaveTheDefault) {
    const std::vector<IblReportTable> reports = builtinIblReports();
    ASSERT_EQ(reports.size(), 3u);
    EXPECT_EQ(reports[0].name, "sky");
    for (const IblReportTable& report : reports) {
        EXPECT_GE(report.rows.size(), 42u) << report.name;
        const IblReportRow* row = report.find(ibl::IblQuality{});
        ASSERT_NE(row, nullptr) << report.name << ": the default settings were measured";
        EXPECT_EQ(row->group, "prefilter, filtered IS");
        EXPECT_GT(row->ratioToCalibration, 1.0);
        EXPECT_GT(row->specularMeanRelative, 0.0);
    }
    // docs/ibl.md: the sky's default precompute is 9.17× the calibration pass, specular error 7.2e-4.
    const IblReportRow* sky = reports[0].find(ibl::IblQuality{});
    EXPECT_NEAR(sky->ratioToCalibration, 9.165, 1e-3);
    EXPECT_NEAR(sky->specularMeanRelative, 0.000721, 1e-6);
    // The previous defaults' row, measured with every texel sampled, is found by its settings.
    ibl::IblQuality previous;
    previous.prefilterSamples = 32;
    previous.specularLevels = 6;
    previous.brightTexels = 0;
    previous.irradiance = ibl::IrradianceMode::Sh9;
    ASSERT_NE(reports[0].find(previous), nullptr);
    EXPECT_EQ(reports[0].find(previous)->group, "previous default");
}

TEST(IblReportTable, RowsMapToTheSettingsTheyMeasured) {
    const IblReportTable sky = builtinIblReports()[0];
    ibl::IblQuality q;
    q.prefilterSamples = 1024;
    q.filteredSampling = false;
    const IblReportRow* plain = sky.find(q);
    ASSERT_NE(plain, nullptr);
    EXPECT_EQ(plain->group, "prefilter, plain IS");
    q = {};
    q.irradiance = ibl::IrradianceMode::Cube;
    q.irradianceSamples = 64;
    ASSERT_NE(sky.find(q), nullptr);
    EXPECT_EQ(sky.find(q)->setting, "cube:64");
    q = {};
    q.lodBias = 2.0f;  // not swept: matched by the rest
    EXPECT_EQ(sky.find(q), sky.find(ibl::IblQuality{}));
    q.cubeSize = 32;  // not measured
    EXPECT_EQ(sky.find(q), nullptr);
}

TEST(IblReportTable, MalformedReportsAreOneLineErrors) {
    EXPECT_THROW(parseIblReport("", "empty.csv"), UserError);
    try {
        parseIblReport("group,setting\nx,y\n", "short.csv");
        FAIL();
    } catch (const UserError& e) {
        EXPECT_STREQ(e.what(), "short.csv: not an ibl-report CSV (no column 'cube')");
    }
    std::string csv(builtinIblReportCsv()[0].second);
    const size_t line = csv.find('\n');
    std::string broken = csv.substr(0, line + 1) + "\"g\",s,abc,6,32,1,sh9,32,256,128,256\n";
    try {
        parseIblReport(broken, "broken.csv");
        FAIL();
    } catch (const UserError& e) {
        EXPECT_STREQ(e.what(), "broken.csv: line 2: cube 'abc' is not a number");
    }
    EXPECT_THROW(loadIblReport("/nonexistent/report.csv"), UserError);
}

// The environment panel shows the table measured on the environment loaded, and says so when it
// shows another.
TEST(IblReportTable, TheTableForAnEnvironmentIsFoundByItsSource) {
    std::vector<IblReportTable> reports = builtinIblReports();
    EXPECT_EQ(reports[0].environment, "procedural sky");
    const std::string venice = "../shared/assets/environments/venice_sunset_1k.hdr";
    ASSERT_EQ(findIblReportFor(reports, venice), std::optional<size_t>(1));
    EXPECT_EQ(reports[1].environment, "venice_sunset_1k");
    EXPECT_EQ(findIblReportFor(reports, "procedural sky"), std::optional<size_t>(0));
    EXPECT_EQ(findIblReportFor(reports, "/x/forest_slope_1k.hdr"), std::nullopt);
    EXPECT_EQ(findIblReportFor(reports, ""), std::nullopt);

    EXPECT_EQ(iblReportNote(reports, 1, venice), "");
    EXPECT_EQ(iblReportNote(reports, 0, "procedural sky"), "");
    EXPECT_EQ(iblReportNote(reports, 0, venice),
              "measured on procedural sky, not on venice_sunset_1k.hdr (its table: venice_sunset_1k)");
    EXPECT_EQ(iblReportNote(reports, 0, "/x/forest_slope_1k.hdr"),
              "measured on procedural sky; no table was measured on forest_slope_1k.hdr");
    EXPECT_EQ(iblReportNote(reports, 2, ""), "measured on studio_small_03_1k; no environment is loaded");
    // A CSV of the user's does not say what it was measured on: never taken for the loaded one.
    reports.insert(reports.begin(), parseIblReport(builtinIblReportCsv()[1].second, "mine/report.csv"));
    EXPECT_EQ(findIblReportFor(reports, venice), std::optional<size_t>(2));
    EXPECT_EQ(iblReportNote(reports, 0, venice),
              "mine/report.csv does not say which environment it was measured on; the table measured on "
              "venice_sunset_1k.hdr: venice_sunset_1k");
    EXPECT_EQ(iblReportNote(reports, 0, ""), "mine/report.csv does not say which environment it was measured on");
}

}  // namespace
}  // namespace candela::ui
