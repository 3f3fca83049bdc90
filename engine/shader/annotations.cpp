#include "shader/annotations.h"

#include <cctype>
#include <cstdlib>
#include <vector>

namespace candela::shader {

namespace {

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string trim(std::string_view s) {
    size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
    return std::string(s.substr(b, e - b));
}

// Applies the annotation in a block comment's text to `out`; false if it is not one.
bool applyAnnotation(const std::string& text, Annotation& out) {
    if (text == "Color") {
        out.color = true;
        return true;
    }
    if (text == "Ignore") {
        out.ignore = true;
        return true;
    }
    if (text.rfind("Range(", 0) == 0 && text.back() == ')') {
        const std::string args = text.substr(6, text.size() - 7);
        const size_t comma = args.find(',');
        if (comma == std::string::npos) return false;
        const std::string lo = trim(args.substr(0, comma)), hi = trim(args.substr(comma + 1));
        char* end = nullptr;
        const float min = std::strtof(lo.c_str(), &end);
        if (lo.empty() || *end) return false;
        const float max = std::strtof(hi.c_str(), &end);
        if (hi.empty() || *end || !(min < max)) return false;
        out.min = min;
        out.max = max;
        return true;
    }
    return false;
}

// The declared names of one member declaration ("vec4 a[2], b" → a, b).
std::vector<std::string> declaredNames(const std::string& declaration) {
    std::vector<std::string> names;
    size_t start = 0;
    int depth = 0;
    for (size_t i = 0; i <= declaration.size(); ++i) {
        const char c = i < declaration.size() ? declaration[i] : ',';
        if (c == '[' || c == '(') ++depth;
        if (c == ']' || c == ')') --depth;
        if (c != ',' || depth > 0) continue;
        // The declarator's name: the last identifier before any array brackets.
        std::string part = declaration.substr(start, i - start);
        if (const size_t bracket = part.find('['); bracket != std::string::npos) part.resize(bracket);
        size_t e = part.size();
        while (e > 0 && !isIdentifierChar(part[e - 1])) --e;
        size_t b = e;
        while (b > 0 && isIdentifierChar(part[b - 1])) --b;
        if (b < e) names.push_back(part.substr(b, e - b));
        start = i + 1;
    }
    return names;
}

}  // namespace

std::map<std::string, Annotation> parseAnnotations(std::string_view glsl) {
    std::map<std::string, Annotation> out;
    // Brace stack: the name of each open struct/block, or "" for other braces (functions, bodies).
    std::vector<std::string> scopes;
    std::string lastWord, wordBeforeLast;  // the last identifiers seen outside comments
    bool lastTokenWasIdentifier = false;
    Annotation pending;
    bool hasPending = false;
    std::string declaration;  // text of the member declaration being read (struct scope only)
    const auto inMemberScope = [&] { return !scopes.empty() && !scopes.back().empty(); };

    size_t i = 0;
    bool lineStart = true;
    while (i < glsl.size()) {
        const char c = glsl[i];
        if (lineStart && c == '#') {  // preprocessor line (with continuations)
            while (i < glsl.size() && glsl[i] != '\n') i += (glsl[i] == '\\' && i + 1 < glsl.size()) ? 2 : 1;
            continue;
        }
        if (c == '\n') lineStart = true;
        else if (!std::isspace(static_cast<unsigned char>(c))) lineStart = false;
        if (c == '/' && i + 1 < glsl.size() && glsl[i + 1] == '/') {
            while (i < glsl.size() && glsl[i] != '\n') ++i;
            continue;
        }
        if (c == '/' && i + 1 < glsl.size() && glsl[i + 1] == '*') {
            const size_t end = glsl.find("*/", i + 2);
            const std::string text = trim(glsl.substr(i + 2, (end == std::string_view::npos ? glsl.size() : end) - i - 2));
            if (inMemberScope() && trim(declaration).empty() && applyAnnotation(text, pending)) hasPending = true;
            i = end == std::string_view::npos ? glsl.size() : end + 2;
            continue;
        }
        if (isIdentifierChar(c)) {
            size_t e = i;
            while (e < glsl.size() && isIdentifierChar(glsl[e])) ++e;
            wordBeforeLast = lastTokenWasIdentifier ? lastWord : "";
            lastWord = std::string(glsl.substr(i, e - i));
            lastTokenWasIdentifier = true;
            if (inMemberScope()) declaration += lastWord;
            i = e;
            continue;
        }
        if (c == '{') {
            // A struct or interface block: `struct Name {`, `uniform Name {`, `buffer Name {`.
            const bool named = lastTokenWasIdentifier &&
                               (wordBeforeLast == "struct" || wordBeforeLast == "uniform" || wordBeforeLast == "buffer");
            scopes.push_back(named ? lastWord : "");
            declaration.clear();
            hasPending = false;
            pending = {};
        } else if (c == '}') {
            if (!scopes.empty()) scopes.pop_back();
            declaration.clear();
        } else if (c == ';' && inMemberScope()) {
            if (hasPending)
                for (const std::string& name : declaredNames(trim(declaration))) out[scopes.back() + "." + name] = pending;
            declaration.clear();
            hasPending = false;
            pending = {};
        } else if (inMemberScope()) {
            declaration += c;
        }
        if (!std::isspace(static_cast<unsigned char>(c))) lastTokenWasIdentifier = false;
        ++i;
    }
    return out;
}

}  // namespace candela::shader
