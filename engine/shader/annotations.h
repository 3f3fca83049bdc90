#pragma once
// UI annotations of shader parameters, written in the GLSL as the original project wrote them: a
// block comment directly before a member declaration of a struct or an interface block.
//
//   struct TonemapParams {
//       /*Color*/ vec4 background;          → colour picker
//       /*Range(-8, 8)*/ float exposureEv;  → slider from -8 to 8
//       /*Ignore*/ float pad0;              → not shown (set by code)
//   };
//
// Several annotations may precede one declaration; a declaration with several names
// (`float a, b;`) gives each the annotations. Other comments are ignored. The shaders are compiled
// with their source text kept in the SPIR-V (glslangValidator -g), so the annotations reach the
// reflection with the SPIR-V itself, also for shaders compiled at run time.

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace candela::shader {

struct Annotation {
    bool color = false;
    bool ignore = false;
    std::optional<float> min, max;  // Range(MIN, MAX)
    friend bool operator==(const Annotation&, const Annotation&) = default;
};

// Annotations by "StructOrBlockName.memberName". Pure text processing: comments, strings of
// preprocessor lines and function bodies are skipped; malformed annotations are ignored.
std::map<std::string, Annotation> parseAnnotations(std::string_view glsl);

}  // namespace candela::shader
