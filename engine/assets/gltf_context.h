#pragma once
// Internal to the glTF loader: what every loading step shares — the file name for error messages
// and the scene's warning and note lists. Not part of the public scene API.
//
// A warning is for what makes the render differ from what the file intends (a repaired value,
// something ignored, clamped or missing); a note, printed with --verbose only, for facts the
// Khronos glTF-Validator reports as information (degenerate triangles, unused data). The same
// fact about many elements is folded into one line per fact (tally()).

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace candela::assets::gltf {

enum class Severity : unsigned char { Warning, Note };

// A fact tally() counts, about elements of one kind (`element`, e.g. "primitive"). Counted facts
// have an amount per element and are worded for one and for many ("zero-area triangle dropped",
// "zero-area triangles dropped"); others are worded once (`many` null: "zero scale, not drawn").
struct Fact {
    const char* element;
    const char* one;
    const char* many = nullptr;
};

// One load in progress. Borrows `warnings` and `notes` (the Scene's), which must outlive it.
struct LoadContext {
    std::string path;                    // the file as the user named it
    std::vector<std::string>* warnings;  // non-fatal problems, each one line
    std::vector<std::string>* notes;     // facts for --verbose; null: dropped

    // Throws candela::UserError("PATH: problem"). `problem` is one line.
    [[noreturn]] void fail(const std::string& problem) const;
    // Records a warning once (the same text twice is kept once).
    void warn(const std::string& message) const;
    // Records a note once.
    void note(const std::string& message) const;
    // Counts `amount` of `fact` about the element `what` (e.g. "mesh 3 primitive 0"). finish()
    // turns each fact into one line: "mesh 3 primitive 0: 2 zero-area triangles dropped" when one
    // element has it, "100 primitives: 200 zero-area triangles dropped" when many do ("node 4:
    // zero scale, not drawn" and "3 nodes: zero scale, not drawn" for facts without amounts).
    void tally(Severity severity, const Fact& fact, const std::string& what, size_t amount = 1) const;
    // Writes the tallied facts as warnings and notes. Call once, when the load is complete.
    void finish() const;

    // Lines taken out of the lists (takeSince) to be recorded again after others (restore).
    struct Lines {
        std::vector<std::string> warnings, notes;
    };
    // Takes out the warnings recorded after the first `warningsAt` and the notes after the first
    // `notesAt` (as recorded: printable, each once, the cap's "further … suppressed" line included).
    Lines takeSince(size_t warningsAt, size_t notesAt) const;
    // Records `lines` (from takeSince) again after what was recorded since: each kept once, within
    // the cap, as if recorded now.
    void restore(const Lines& lines) const;

    struct Count {
        Severity severity = Severity::Warning;
        Fact fact{};
        std::string firstWhat;
        size_t elements = 0, amount = 0;
    };
    mutable std::map<std::string, Count> tallies{};  // by Fact::one, filled by tally()
};

// True when `value` is finite and a float can hold it (|value| <= FLT_MAX).
bool fitsFloat(double value);

// `value` as a float. Fails via ctx ("WHAT is beyond single precision") when it is not finite or
// too large for a float (converting it would be undefined behaviour).
float toFloat(const LoadContext& ctx, double value, const std::string& what);

// "mesh 2 ('Cube') primitive 0" style labels for messages: the index, and the name if there is one.
std::string label(const char* kind, int index, const std::string& name = {});

}  // namespace candela::assets::gltf
