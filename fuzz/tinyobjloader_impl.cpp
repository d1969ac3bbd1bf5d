// tinyobjloader's implementation, compiled from Debian's header so that the
// sanitizers see inside it too (the packaged shared library is not
// instrumented). The main build links libtinyobjloader instead.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
