#include "ui/ibl_report_table.h"

#include "core/errors.h"

#include <charconv>
#include <fstream>
#include <map>
#include <sstream>

namespace candela::ui {

namespace {

// One CSV line; fields may be "quoted, with commas".
std::vector<std::string> splitCsv(std::string_view line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (char c : line) {
        if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) fields.emplace_back();
        else if (c != '\r') fields.back() += c;
    }
    return fields;
}

std::string canonicalWithoutBias(ibl::IblQuality quality) {
    quality.lodBias = ibl::IblQuality{}.lodBias;
    return quality.canonical();
}

}  // namespace

const IblReportRow* IblReportTable::find(const ibl::IblQuality& quality) const {
    const std::string wanted = canonicalWithoutBias(quality);
    for (const IblReportRow& row : rows)
        if (canonicalWithoutBias(row.quality) == wanted) return &row;
    return nullptr;
}

IblReportTable parseIblReport(std::string_view csv, std::string name) {
    IblReportTable table{.name = std::move(name)};
    std::istringstream lines{std::string(csv)};
    std::string line;
    std::map<std::string, size_t> column;
    size_t lineNumber = 0;
    while (std::getline(lines, line)) {
        ++lineNumber;
        if (line.empty() || line == "\r") continue;
        const std::vector<std::string> fields = splitCsv(line);
        if (column.empty()) {
            for (size_t i = 0; i < fields.size(); ++i) column[fields[i]] = i;
            for (const char* required : {"group", "setting", "cube", "levels", "prefilter_samples", "filtered",
                                         "irradiance", "sh_size", "irradiance_samples", "lut_size", "lut_samples",
                                         "precompute_ms", "ratio_to_calibration", "specular_mean_relative",
                                         "irradiance_mean_relative", "lut_max_a", "lut_max_b", "image_mean_relative"})
                if (!column.count(required))
                    throw UserError(table.name + ": not an ibl-report CSV (no column '" + required + "')");
            continue;
        }
        const auto text = [&](const char* key) -> const std::string& {
            const size_t i = column.at(key);
            if (i >= fields.size())
                throw UserError(table.name + ": line " + std::to_string(lineNumber) + " has too few fields");
            return fields[i];
        };
        const auto number = [&](const char* key) {
            const std::string& value = text(key);
            double out = 0.0;
            const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), out);
            if (error != std::errc() || end != value.data() + value.size())
                throw UserError(table.name + ": line " + std::to_string(lineNumber) + ": " + key + " '" + value +
                                "' is not a number");
            return out;
        };
        IblReportRow row{.group = text("group"), .setting = text("setting")};
        ibl::IblQuality& q = row.quality;
        q.cubeSize = uint32_t(number("cube"));
        q.specularLevels = uint32_t(number("levels"));
        q.prefilterSamples = uint32_t(number("prefilter_samples"));
        q.filteredSampling = number("filtered") != 0.0;
        q.irradiance = ibl::parseIrradianceMode(text("irradiance")).value_or(ibl::IrradianceMode::Sh9);
        q.shSourceSize = uint32_t(number("sh_size"));
        q.irradianceSamples = uint32_t(number("irradiance_samples"));
        q.lutSize = uint32_t(number("lut_size"));
        q.lutSamples = uint32_t(number("lut_samples"));
        // Reports from before the bright-texel split sampled every texel.
        q.brightTexels = column.count("bright_texels") ? uint32_t(number("bright_texels")) : 0;
        row.precomputeMs = number("precompute_ms");
        row.ratioToCalibration = number("ratio_to_calibration");
        row.specularMeanRelative = number("specular_mean_relative");
        row.irradianceMeanRelative = number("irradiance_mean_relative");
        row.lutMax = std::max(number("lut_max_a"), number("lut_max_b"));
        row.imageMeanRelative = number("image_mean_relative");
        table.rows.push_back(std::move(row));
    }
    if (column.empty()) throw UserError(table.name + ": empty report");
    return table;
}

IblReportTable loadIblReport(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw UserError(path.string() + ": cannot read");
    std::ostringstream text;
    text << in.rdbuf();
    return parseIblReport(text.str(), path.string());
}

std::vector<IblReportTable> builtinIblReports() {
    std::vector<IblReportTable> tables;
    for (const auto& [name, csv] : builtinIblReportCsv()) tables.push_back(parseIblReport(csv, std::string(name)));
    return tables;
}

}  // namespace candela::ui
