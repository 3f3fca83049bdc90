#pragma once
// Candela's version: of the headers a program compiled against (the macros) and of the library it
// runs with (candela::version()). The API and ABI promise is in docs/embedding.md: within 0.y, a
// minor release may change both (the library's soname, libcandela.so.0.y, changes with it).

#define CANDELA_VERSION_MAJOR 0
#define CANDELA_VERSION_MINOR 3
#define CANDELA_VERSION_PATCH 0
// "MAJOR.MINOR.PATCH", from the three above.
#define CANDELA_VERSION_TEXT_(major, minor, patch) #major "." #minor "." #patch
#define CANDELA_VERSION_TEXT(major, minor, patch) CANDELA_VERSION_TEXT_(major, minor, patch)
#define CANDELA_VERSION_STRING CANDELA_VERSION_TEXT(CANDELA_VERSION_MAJOR, CANDELA_VERSION_MINOR, CANDELA_VERSION_PATCH)

// Marks what libcandela.so exports (everything else in it is hidden); default visibility in a
// program too, so that the exceptions' type information is the library's even when the program
// hides its own symbols.
#define CANDELA_API __attribute__((visibility("default")))

namespace candela {

// The library's version, "MAJOR.MINOR.PATCH": compare it with CANDELA_VERSION_STRING to see that a
// program runs with the library it was built for.
CANDELA_API const char* version() noexcept;

}  // namespace candela
