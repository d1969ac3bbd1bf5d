/* An orthonormal basis around a unit vector. */
#ifndef PRISM_SHADING_FRAME_H
#define PRISM_SHADING_FRAME_H

/* t, b with (t, b, n) right-handed and orthonormal, continuous except where n.z
 * changes sign (Duff et al., "Building an Orthonormal Basis, Revisited", 2017). */
inline void orthonormal_basis(float3 n, float3* t, float3* b) {
  float sign = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (sign + n.z);
  float c = n.x * n.y * a;
  *t = (float3)(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
  *b = (float3)(c, sign + n.y * n.y * a, -n.y);
}

#endif
