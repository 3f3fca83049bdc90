#include "reports/image_diff.h"

#include "reports/compared_image.h"

#include "core/errors.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace candela::reports {
namespace {

std::string number(const char* format, double value) {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// The reasons a compared pair is over its thresholds, "" when it is not.
std::string overThresholds(const DiffPair& pair, const DiffSettings& settings) {
    std::string why;
    const auto add = [&](const std::string& reason) { why += (why.empty() ? "" : "; ") + reason; };
    if (settings.maxFlip && pair.flip.mean > *settings.maxFlip)
        add("mean FLIP " + number("%.6f", pair.flip.mean) + " > --max-flip " + number("%g", *settings.maxFlip));
    if (settings.maxFraction && pair.pixels.fractionOverThreshold > *settings.maxFraction)
        add(number("%.4g", pair.pixels.fractionOverThreshold * 100.0) + "% of pixels differ by more than " +
            number("%g", settings.thresholdLevels) + (pair.hdr ? "/255" : " levels") + " > --max-fraction " +
            number("%g", *settings.maxFraction));
    return why;
}

}  // namespace

DiffPair diffImages(const std::filesystem::path& reference, const std::filesystem::path& test, const std::string& name,
                    const DiffSettings& settings, std::vector<float>* errorMap) {
    const std::optional<ComparedFormat> referenceFormat = comparedFormat(reference), testFormat = comparedFormat(test);
    for (const auto& [path, format] : {std::pair{&reference, referenceFormat}, std::pair{&test, testFormat}})
        if (!format) throw UserError(path->string() + ": not a .png or .exr file");
    if (*referenceFormat != *testFormat)
        throw UserError(test.string() + ": a " + (*testFormat == ComparedFormat::Png ? "PNG" : "EXR") + " against the " +
                        (*referenceFormat == ComparedFormat::Png ? "PNG " : "EXR ") + reference.string() +
                        " (compare PNG with PNG, EXR with EXR)");
    DiffPair pair{.name = name, .referencePath = reference.string(), .testPath = test.string()};
    pair.hdr = *referenceFormat == ComparedFormat::Exr;
    if (errorMap) errorMap->clear();

    ComparedImage ref, tst;
    try {
        ref = readComparedImage(reference);
        pair.width = ref.width;
        pair.height = ref.height;
        tst = readComparedImage(test);
    } catch (const UserError& e) {
        pair.status = DiffStatus::Unreadable;
        pair.message = e.what();
        return pair;
    }
    for (ComparedImage* image : {&ref, &tst}) pair.warnings.insert(pair.warnings.end(), image->report.warnings.begin(), image->report.warnings.end());
    if (ref.width != tst.width || ref.height != tst.height) {
        pair.status = DiffStatus::SizeMismatch;
        pair.message = "reference " + std::to_string(ref.width) + "x" + std::to_string(ref.height) + ", test " +
                       std::to_string(tst.width) + "x" + std::to_string(tst.height);
        return pair;
    }

    std::vector<float> error;
    if (pair.hdr) {
        pair.exposures = flipExposures(ref.linear);
        error = hdrFlip(ref.linear, tst.linear, settings.pixelsPerDegree, *pair.exposures);
        pair.pixels = pixelDifference(ref.linear.rgb, tst.linear.rgb, settings.thresholdLevels / 255.0);
    } else {
        error = ldrFlip(ref.linear, tst.linear, settings.pixelsPerDegree);
        pair.pixels = pixelDifference(ref.rgb8, tst.rgb8, settings.thresholdLevels);
    }
    pair.flip = flipStatistics(error);
    pair.message = overThresholds(pair, settings);
    pair.status = pair.message.empty() ? DiffStatus::Ok : DiffStatus::OverThreshold;
    if (errorMap) *errorMap = std::move(error);
    return pair;
}

std::vector<MatchedFile> matchFolders(const std::filesystem::path& reference, const std::filesystem::path& test) {
    std::map<std::string, MatchedFile> files;
    for (const auto& [root, isReference] : {std::pair{&reference, true}, std::pair{&test, false}}) {
        std::error_code ec;
        auto it = std::filesystem::recursive_directory_iterator(*root, ec);
        if (ec) throw UserError(root->string() + ": cannot read the folder: " + ec.message());
        for (; it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
            if (ec) throw UserError(root->string() + ": cannot read the folder: " + ec.message());
            std::error_code typeError;
            if (!it->is_regular_file(typeError) || !comparedFormat(it->path())) continue;
            const std::string name = it->path().lexically_relative(*root).generic_string();
            MatchedFile& file = files[name];
            file.name = name;
            (isReference ? file.reference : file.test) = it->path();
        }
    }
    std::vector<MatchedFile> out;
    for (auto& [name, file] : files) out.push_back(std::move(file));
    return out;
}

}  // namespace candela::reports
