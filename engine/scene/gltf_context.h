#pragma once
// Internal to the glTF loader: what every loading step shares — the file name for error messages
// and the scene's warning list. Not part of the public scene API.

#include <string>
#include <vector>

namespace candela::scene::gltf {

// One load in progress. Borrows `warnings` (the Scene's), which must outlive it.
struct LoadContext {
    std::string path;                    // the file as the user named it
    std::vector<std::string>* warnings;  // non-fatal problems, each one line

    // Throws candela::UserError("PATH: problem"). `problem` is one line.
    [[noreturn]] void fail(const std::string& problem) const;
    // Records a warning once (the same text twice is kept once).
    void warn(const std::string& message) const;
};

// True when `value` is finite and a float can hold it (|value| <= FLT_MAX).
bool fitsFloat(double value);

// `value` as a float. Fails via ctx ("WHAT is beyond single precision") when it is not finite or
// too large for a float (converting it would be undefined behaviour).
float toFloat(const LoadContext& ctx, double value, const std::string& what);

// "mesh 2 ('Cube') primitive 0" style labels for messages: the index, and the name if there is one.
std::string label(const char* kind, int index, const std::string& name = {});

}  // namespace candela::scene::gltf
