// tinyobjloader's implementation for the browser module, from the header Debian's
// libtinyobjloader-dev installs (its compiled library is for the build machine only).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
