// tinyexr compiled from Debian's header for the fuzz build (see third_party_readers.cpp), in a
// file of its own so that its sanitizer exceptions (tests/fuzz/CMakeLists.txt) stay narrow.
#define TINYEXR_IMPLEMENTATION
#include <tinyexr.h>
