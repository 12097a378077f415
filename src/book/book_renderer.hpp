// `render --rules book`: a scene drawn as the chapter's live demos draw it (raster-06/07/08),
// on the CPU, so that the image is the demo's canvas pixel for pixel: wireframe triangles in the
// scene's order, no clipping, no depth, a later pixel over an earlier one.
#pragma once

#include "image/image.hpp"
#include "scene/scene.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace twinraster::book {

// A scene the book's rules cannot draw: `where` is a JSON path in the scene ("canvas",
// "instances[1]"), `problem` says what and why.
class BookRulesError : public std::runtime_error {
 public:
  BookRulesError(std::string where, std::string problem)
      : std::runtime_error(where + ": " + problem), where_(std::move(where)), problem_(std::move(problem)) {}
  const std::string& where() const { return where_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string where_, problem_;
};

// What the demos cannot express, checked before drawing: an odd canvas width or height (the
// demo's PutPixel centres the canvas on Cw/2, Ch/2 in whole pixels). Throws BookRulesError.
void CheckBookRules(const Scene& scene);

// The chapter's RenderScene as raster-08 runs it: M_Camera once; per instance
// M_Camera · (T · (R · S)), every vertex through MultiplyMV and ProjectVertex, then each of the
// model's triangles by DrawWireframeTriangle in its colour. The canvas starts as the scene's
// background (the demos' page is white behind a transparent canvas), opaque.
// With an unrotated camera at the origin and an unrotated, unscaled instance every product is by
// 0 or 1 and so exact: the vertices are raster-06/07's model vertex + position, bit for bit.
// Throws BookRulesError for what CheckBookRules refuses, and for a triangle with a vertex that
// projects beyond kFarthestEndpoint (book_lines.hpp) or to no number at all (camera z = 0).
Image RenderScene(const Scene& scene);

}  // namespace twinraster::book
