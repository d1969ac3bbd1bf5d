// The two ways a set of bicubic patches is made ready for rays.
//
// Successive subdivision (planSubdivision, tessellatePatches): each patch is
// cut in u or in v, where it bends more, until every cell lies within the
// tolerance of its two triangles (flatnessBound), and the cells become
// triangles with normals and texture coordinates from the patch. Cuts are
// adaptive: a flat patch stays a few cells while a curved one is cut finely.
// Two patches sharing an edge share its cuts — the knots are kept per chain of
// shared edges — and evaluate its points from the same curve, so their
// triangles meet without cracks.
//
// The analytic method (patchPieces): each patch is cut, far more coarsely,
// into pieces flat enough that Newton iteration from the ray's crossing of the
// piece's corner triangles converges to the surface (kernels/geometry/patch.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/mesh.h"
#include "scene/patches/bezier_patch.h"

namespace prism {

// The knots of one patch's cells, increasing from 0 to 1 in each direction.
struct PatchGrid {
  std::vector<double> u, v;
};

// Throws std::length_error, saying what to change, when the tolerance asks for
// more than `max_triangles`.
std::vector<PatchGrid> planSubdivision(const std::vector<BezierPatch>& patches, double tolerance,
                                       std::size_t max_triangles);
std::shared_ptr<TriangleMesh> tessellatePatches(const std::vector<BezierPatch>& patches,
                                                const std::vector<PatchGrid>& plan, const std::string& source);

std::vector<PatchPiece> patchPieces(const std::vector<BezierPatch>& patches);

// The diagonal of the box of every control point.
double patchSetSize(const std::vector<BezierPatch>& patches);

}  // namespace prism
