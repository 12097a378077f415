// `explain SCENE --html FILE`: the scene's chain drawn, a panel per space, as the chapter's
// figures draw them: the model in model space; the world from above and from the side with the
// instances, the camera and its frustum; camera space; clip space and NDC; the canvas with the
// final pixel. Each panel shows its matrix by the chapter's name and the traced vertex there; a
// lit scene also shows the normal, N and the lights. It draws a typed Explanation and computes
// no number of its own beyond fitting the drawings to their panels.
#pragma once

#include "chain/explanation.hpp"

#include <string>

namespace twinraster::explain_report {

// The page follows the first explained instance's traced vertex (instances[0].traced). Edges are
// drawn between traced vertices only: `explanation` should trace every vertex
// (ExplainVertices::kAll). Numbers have six significant digits; a negative zero shows as 0.
std::string ChainPageHtml(const Explanation& explanation);

// The page in its two parts, for a page that redraws the chain as it changes (page/): the head
// (PageStart, the style sheet and the title, left open for the body to follow), and the panels
// (the paragraph naming the traced vertex, then a figure per space), which are all that change.
// ChainPageHtml is the head, the panels and markup::kPageEnd.
std::string ChainPageHead(const Explanation& explanation);
std::string ChainPanelsHtml(const Explanation& explanation);

}  // namespace twinraster::explain_report
