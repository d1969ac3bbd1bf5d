/* A Whitted material as the kernels see it; shared by host and kernels. */
#ifndef PRISM_MATERIAL_GPU_H
#define PRISM_MATERIAL_GPU_H

#define SHADING_PHONG 0
#define SHADING_BLINN 1
#define SHADING_COOK_TORRANCE 2

#define MICROFACET_BECKMANN 0
#define MICROFACET_GGX 1

#define TEXTURE_NONE 0
#define TEXTURE_CHECKER 1
#define TEXTURE_IMAGE 2

/* How an image texture repeats beyond [0, 1]. */
#define TEXTURE_WRAP_REPEAT 0
#define TEXTURE_WRAP_CLAMP 1
#define TEXTURE_WRAP_MIRROR 2

typedef struct MaterialGpu {
  float ambient[4]; /* rgb + unused lane, so each colour is one float4 */
  float diffuse[4];
  float specular[4];
  float checker1[4]; /* checker colours; they multiply ambient and diffuse */
  float checker2[4];
  float shininess;
  float reflect;  /* k_refl */
  float transmit; /* k_trans */
  float ior;
  int model;      /* SHADING_* */
  int texture;    /* TEXTURE_* */
  float texture_scale;
  /* Phong-lobe exponents of the reflected and the refracted ray around their
   * ideal directions; 0: the ideal direction itself (mirror, clear glass). */
  float gloss;
  float translucency;
  /* Cook-Torrance: the microfacets' roughness (Beckmann's m, the RMS slope; GGX's
   * alpha) and their distribution (MICROFACET_*). */
  float roughness;
  int distribution;
  /* An image texture: its first texel in the scene's texel array (linear
   * RGB, float4 each, rows top to bottom), its size and TEXTURE_WRAP_* mode. */
  int image_offset;
  int image_width;
  int image_height;
  int wrap;
  int pad;
} MaterialGpu;

#endif
