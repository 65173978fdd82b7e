// tinyobjloader's implementation, compiled here with the fuzzers' flags so that
// its parsing is instrumented too (Debian's prebuilt libtinyobjloader_double
// is not). TINYOBJLOADER_USE_DOUBLE comes from the target, as for prism_core.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
