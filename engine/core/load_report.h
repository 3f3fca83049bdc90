#pragma once
// LoadReport: what reading one input met, one line each, kept beside what was read for the front
// end to print. The readers' results carry one each: scene::Scene (with what loading cost:
// scene::SceneLoadReport), assets::Environment, textures::DecodedTexture and reports::ComparedImage.

#include <string>
#include <vector>

namespace candela {

struct LoadReport {
    // Problems that make the result differ from what the file intends, such as a texture that
    // could not be decoded or values replaced (always printed).
    std::vector<std::string> warnings;
    // Facts that change nothing the file intends, such as what the glTF-Validator reports as
    // information (degenerate triangles) or the frame of an animated WebP drawn (printed with
    // --verbose).
    std::vector<std::string> notes;
};

}  // namespace candela
