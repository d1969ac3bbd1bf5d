// The benchmark's million-triangle mesh made from a smaller one by uniform Loop
// subdivision (OpenMesh's subdivider), so that it need not be shipped.
#pragma once

#include <string>

namespace prism::bench {

// Reads `in` (any format OpenMesh reads; triangles), applies `steps` Loop
// subdivisions (each multiplies the triangle count by 4) and writes `out` as
// binary little-endian PLY, through a temporary file renamed into place.
// Throws with the file's name if it cannot be read or written.
void writeLoopSubdivided(const std::string& in, const std::string& out, int steps);

}  // namespace prism::bench
