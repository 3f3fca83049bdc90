#include "cli_values.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace candela::app {

uint32_t parseDimension(const std::string& flag, const std::string& value) {
    const bool digits = !value.empty() && value.size() <= 10 &&
                        std::all_of(value.begin(), value.end(), [](unsigned char c) { return std::isdigit(c); });
    const unsigned long long number = digits ? std::stoull(value) : 0;
    if (!digits || number > 0xffffffffull)
        throw UserError(flag + ": expected a whole number of pixels, got '" + value + "'");
    return static_cast<uint32_t>(number);
}

float parseNumber(const std::string& flag, const std::string& value) {
    size_t used = 0;
    float number = 0.0f;
    try {
        number = std::stof(value, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (value.empty() || used != value.size() || !std::isfinite(number))
        throw UserError(flag + ": expected a number, got '" + value + "'");
    return number;
}

std::string valueText(float value) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

std::string valueText(uint32_t value) { return std::to_string(value); }

std::vector<std::string> commaSeparated(const std::string& value) {
    std::vector<std::string> items;
    for (size_t start = 0;;) {
        const size_t comma = value.find(',', start);
        items.push_back(value.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) return items;
        start = comma + 1;
    }
}

std::array<float, 3> parseTriple(const std::string& flag, const std::string& value) {
    std::array<float, 3> out{};
    size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const size_t comma = value.find(',', start);
        if ((i < 2) != (comma != std::string::npos))
            throw UserError(flag + ": expected three comma-separated numbers, got '" + value + "'");
        out[i] = parseNumber(flag, value.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        start = comma + 1;
    }
    return out;
}

std::string sequenceFileName(const std::string& pattern, uint32_t index) {
    std::string out;
    int fields = 0;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            out += pattern[i];
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            out += '%';
            ++i;
            continue;
        }
        size_t j = i + 1;
        int width = 0;
        if (j < pattern.size() && pattern[j] == '0')
            while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && width < 100)
                width = width * 10 + (pattern[j++] - '0');
        if (j >= pattern.size() || pattern[j] != 'd')
            throw UserError("--out " + pattern + ": an image sequence needs one %d or %0Nd for the frame number (and %% for a %)");
        std::string number = std::to_string(index);
        if (int(number.size()) < width) number.insert(0, size_t(width) - number.size(), '0');
        out += number;
        ++fields;
        i = j;
    }
    if (fields != 1)
        throw UserError("--out " + pattern + ": an image sequence needs exactly one %d or %0Nd for the frame number");
    return out;
}

double parseSeconds(const std::string& flag, const std::string& value) {
    double seconds = 0.0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), seconds);
    if (error != std::errc() || end != value.data() + value.size() || !std::isfinite(seconds) || seconds < 0.0)
        throw UserError(flag + ": expected a number of seconds >= 0, got '" + value + "'");
    return seconds;
}

std::array<float, 3> parseHexColor(const std::string& flag, const std::string& value) {
    const bool ok = value.size() == 7 && value[0] == '#' &&
                    std::all_of(value.begin() + 1, value.end(), [](unsigned char c) { return std::isxdigit(c); });
    if (!ok) throw UserError(flag + ": expected #rrggbb, got '" + value + "'");
    std::array<float, 3> out{};
    for (int i = 0; i < 3; ++i) out[i] = static_cast<float>(std::stoi(value.substr(1 + 2 * i, 2), nullptr, 16)) / 255.0f;
    return out;
}

uint32_t parseCount(const std::string& flag, const std::string& value) {
    const uint32_t count = parseDimension(flag, value);
    if (count == 0) throw UserError(flag + ": must be at least 1");
    return count;
}

float parsePixels(const std::string& flag, const std::string& value, bool zeroAllowed) {
    const float pixels = parseNumber(flag, value);
    if (zeroAllowed ? !(pixels >= 0.0f) : !(pixels > 0.0f))
        throw UserError(flag + ": expected pixels " + (zeroAllowed ? "≥" : ">") + " 0, got '" + value + "'");
    return pixels;
}

std::string parsePath(const std::string& flag, const std::string& value) {
    if (value.empty()) throw UserError(flag + ": expected a file or folder name");
    return value;
}

std::string joinWords(const std::vector<std::string>& words, const std::string& conjunction) {
    std::string out;
    for (size_t i = 0; i < words.size(); ++i) out += (i == 0 ? "" : i + 1 == words.size() ? " " + conjunction + " " : ", ") + words[i];
    return out;
}

std::string joinChoices(const std::vector<std::string>& names, const std::string& otherForm) {
    std::vector<std::string> all = names;
    if (!otherForm.empty()) all.push_back(otherForm);
    return joinWords(all, "or");
}

}  // namespace candela::app
