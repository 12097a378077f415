// Checks an OBJ file's text line by line, so that every problem is one SceneError naming the line.
// tinyobjloader, which reads the file (obj_file.cpp), takes a malformed number for 0 and an index
// past the end for a good one without a word, and names no line for either.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace twinraster {

// What the check counted: the reader must find the same (a cross-check that both split the file
// into the same lines and statements).
struct ObjCounts {
  std::size_t vertices = 0;   // v lines
  std::size_t normals = 0;    // vn lines
  std::size_t texcoords = 0;  // vt lines
  std::size_t faces = 0;      // f lines
};

// Throws SceneError(file_name, "line N", problem) for the first bad v, vn, vt or f line (a
// malformed or absurd number, a wrong count of numbers, a face with fewer than 3 corners, a
// malformed corner, an index of 0 or out of range), for a NUL byte, or (file_name, "(file)", ...)
// for a file without faces. Other statements (o, g, s, usemtl, mtllib, l, comments...) are not
// looked at: they change nothing twinraster draws.
ObjCounts CheckObjText(std::string_view text, const std::string& file_name);

}  // namespace twinraster
