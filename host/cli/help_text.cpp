#include "help_text.h"

namespace prism_cli {

const char* const kMainHelp =
    R"(prism - a Whitted/Cook ray tracer for any OpenCL device (PoCL on a CPU, or a GPU)

Usage:
  prism render SCENE.json -o OUT [options]   render a scene to an image file
  prism render MESH.ply -o OUT [options]     render a mesh file (.obj .ply .off ...)
                                             with a camera that frames it
  prism trace SCENE|MESH --rays IN --hits OUT   closest (or any) hits of a file of rays
  prism info [--json] MESH                   what a mesh file holds
  prism plugins                              the mesh-format plugins found
  prism devices                              list the OpenCL devices prism can use
  prism COMMAND --help                       options of one command
  prism --help                               this help
  prism --version                            print the version

Examples:
  prism devices
  prism render scenes/whitted.json -o whitted.png
  prism render scenes/whitted.json -o big.exr --width 1920 --height 1080 --spp 16
  prism render scenes/whitted.json -o depth.exr --aov depth --device cpu

Output formats, chosen by the extension of OUT:
  .png  8-bit sRGB      .exr .tif  32-bit float, linear
  .pfm  float, linear   .hdr       Radiance RGBE, linear

Environment:
  PRISM_CACHE_DIR   compiled kernels are cached here; default
                    $XDG_CACHE_HOME/prism/kernels, else ~/.cache/prism/kernels. The
                    first render on a device compiles them, later renders load
                    them. Delete the folder or pass --no-cache to compile afresh.
  PRISM_KERNEL_DIR  read the OpenCL kernel sources from this folder instead of the
                    copies built into the library (for kernel development; point it
                    at the kernels/ folder of a source tree).

Exit codes: 0 success; 1 failure (scene, device or file); 2 bad command line;
130 interrupted by Ctrl-C.

Documentation: docs/cli.md (this tool), docs/scene-format.md (scene files).
)";

const char* const kRenderHelp =
    R"(Usage: prism render SCENE.json -o OUT [options]
       prism render MESH -o OUT [options]

Renders the scene file SCENE.json (format: docs/scene-format.md) and writes the image
to OUT. Options override the scene's own film and render settings; whatever is not
given keeps the scene's value.

Given a mesh file instead (.obj, .ply, .off, or any extension a plugin reads; see
'prism plugins'), prism renders it alone at 800x600: the camera looks at the centre of
its bounding box from the +Z side, a little above and to the right, far enough that
the bounding sphere fills 90% of a 40-degree vertical field of view; a white headlight
sits at the camera; the mesh keeps its file's materials (MTL) or gets a light grey
Phong material; vertex normals are interpolated when the file has them. The camera
options below move that camera.

Output:
  -o, --output OUT  the image to write (required). Its extension picks the format:
                      .png        8-bit, sRGB-encoded colour, RGB
                      .exr, .tif  32-bit float, linear, RGBA
                      .pfm        32-bit float, linear, RGB
                      .hdr        Radiance RGBE, linear, RGB
                    In .exr and .tif, alpha is the fraction of a pixel's primary rays
                    that hit something; the RGB formats show the background colour.
                    The file appears only when complete; a failed render or write
                    leaves no file.
  --aov NAME        write an auxiliary image instead of the colour image:
                      depth   distance along the primary ray to the first hit,
                              +inf on a miss (1 channel)
                      normal  world-space unit normal facing the ray, 0 on a miss
                              (3 channels; a .png stores n*0.5+0.5, like a normal map)
                      primid  index of the hit primitive, -1 on a miss (1 channel)
                      albedo  diffuse colour at the hit, 0 on a miss (3 channels)
                    depth and primid need a float format: .exr, .pfm or .tif
                    (.hdr works but turns +inf and -1 into other values; .png is
                    refused). AOVs come from one sample of each pixel: the centre
                    (none, quincunx), the first sample (grid, jitter, poisson,
                    random) or the top-left corner (adaptive).

Image and sampling (default: the scene's value):
  --width W         image width in pixels (W >= 1)
  --height H        image height in pixels (H >= 1)
  --spp N           samples per pixel (N >= 1) for --aa grid, jitter, poisson and random;
                    none, quincunx and adaptive place their own samples (spp 1)
  --max-depth D     levels of reflected and refracted rays after the primary ray
                    (0: primary rays and shadows only)
  --min-weight X    adaptive depth control: a ray whose weight (its share of the pixel)
                    falls below X is not traced; 0 traces every ray to --max-depth
  --seed S          seed of the sample positions (jitter, poisson, random; 0 to
                    2^64-1). The same scene, seed and device give the same image,
                    bit for bit.

Anti-aliasing (default: the scene's film block; see docs/sampling.md):
  --aa MODE         where primary rays pass through each pixel:
                      none      the pixel centre (the default at --spp 1)
                      grid      the centres of an n x n grid (--spp n*n)
                      quincunx  the 4 corners, shared with the neighbours, and the
                                centre: (W+1)(H+1) + W*H rays, about 2 per pixel
                      adaptive  the corners, subdivided where they differ by more
                                than --aa-threshold, down to --aa-max-level
                      jitter    one random point in each of N strata (the default
                                when --spp is above 1)
                      poisson   a Poisson-disk pattern of N points (N <= 4096),
                                shifted randomly in each pixel
                      random    N independent random points
                      auto      none at --spp 1, jitter above (the default)
  --filter F        how samples become pixels: box (radius 0.5, the mean of the
                    pixel's samples; default), tent (1), gaussian (1.5) or mitchell (2).
                    Quincunx always uses its tent weights (centre 1/2, corners 1/8),
                    adaptive its area average.
  --aa-threshold X  adaptive: split a square whose corner colours differ by more than
                    X in some channel (default 0.1)
  --aa-max-level N  adaptive: at most N splits of a pixel's side, 0..8 (default 2:
                    up to 5 x 5 points a pixel)

Camera (default: the scene's camera):
  --camera-pos X,Y,Z   where the camera stands
  --camera-look X,Y,Z  the point it looks at
  --camera-up X,Y,Z    its up direction (not parallel to the view direction)
  --fov DEG            vertical field of view in degrees, 0 < DEG < 180
  --aperture R         lens radius in scene units: depth of field (0: a pinhole)
  --focus-distance D   distance of the plane in focus along the view direction
                       (default: the scene's, else the distance to the look-at point)

Speed:
  --accel A         spatial index for ray queries: auto (default: none for scenes
                    of at most 4 primitives, where a tree costs more than it
                    saves, else bvh), bvh, octree, bsp, or none (every ray
                    against every primitive)
  --first-hit M     how primary visibility is found: zbuffer (a first-hit pass over
                    screen tiles of primitives, no ray traversal), trace (primary
                    rays through the --accel structure), or auto (default: zbuffer
                    whenever the camera allows it: no aperture, no shutter
                    interval). Both give the same image.
  --inside-test T   the point-in-polygon test of polygons that name none:
                    crossing (default, the Jordan curve test), radial (the
                    angle-sum test) or left-right (convex polygons only). All
                    three give the same image.
  --shadows S       how point lights' shadow feelers find occluders: accel (the
                    --accel structure), lightbuffer (a direction cube around
                    each point light whose cells list the primitives in that
                    direction; at most 64 point lights), or auto (default: the
                    light buffer when its cells list few candidates). The same
                    shadows either way.
  --bounds B        bounding volumes: aabb (default, boxes) or kdop (Kay and
                    Kajiya's "set of normals": slabs along four diagonals
                    around each analytic object, tested before it, and around
                    each BVH child besides its box; pays in scenes of many
                    analytic objects). The same image either way.

Device:
  --device D        the OpenCL device: an index from 'prism devices', 'cpu', 'gpu', or
                    part of the device name (case-insensitive). Default: the first
                    GPU, else the first device. 'all', or a list such as 0,2, shares
                    each frame over several devices: a faster one takes more of it,
                    one that fails mid-frame is left out with a warning, and the
                    image is the same bit for bit as on one device of that kind.
                    Under 'mpirun -np N prism render ...' (a build with MPI) the N
                    processes share each frame, each on its --device, a rank
                    with faster devices taking more of it; rank 0 writes the
                    image, the same bit for bit as one process's
  --no-cache        compile the kernels afresh, without reading or filling the kernel
                    cache (see PRISM_CACHE_DIR in 'prism --help')

Animation (a scene with an "animation" block of frames):
  --frames K|A-B    render only frame K, or frames A to B (from 0); default: all.
                    Each frame is its own file: a run of '#' in -o becomes the
                    frame number (-o shot_###.png: shot_007.png), else _NNNN goes
                    before the extension (-o shot.png: shot_0007.png). Under
                    mpirun the frames are dealt whole to the ranks, each writing
                    its own; the last frames, fewer than the ranks, are each
                    shared by a group of ranks

Messages:
  --stats           after the summary, where the render's time went: set-up (kernels,
                    structure) and tracing, and each kernel's device time (profiled);
                    with several devices, how much of the frame each one traced
  --check-nan       watch every ray's contribution for NaN and infinity; name the first
                    (its sample, pixel, ray and hit) and the first such pixel of the
                    image, and exit with 3 if there is one (the image is still written);
                    without it, such pixels draw a warning with their count, exit 0
  --quiet           no progress bar and no summary line (warnings and errors still
                    go to stderr)
  -h, --help        this help

While rendering, a progress bar appears on stderr if it is a terminal and the render
takes longer than a second; Ctrl-C stops the render and writes nothing. At the end
prism prints one summary line on stdout: size, samples, device, time, anti-aliasing,
primary rays per pixel, how first hits were found, rays traced by kind, Mrays/s and
the output file. Warnings about the scene (unknown keys and the
like) go to stderr as "prism: warning: ...".

Options take their value as '--spp 16' or '--spp=16'.

Examples:
  prism render scenes/whitted.json -o whitted.png
  prism render scenes/whitted.json -o preview.png --width 320 --height 180 --spp 1
  prism render scenes/whitted.json -o final.exr --spp 64 --max-depth 8 --seed 7
  prism render scenes/whitted.json -o smooth.png --aa quincunx
  prism render scenes/whitted.json -o fine.png --aa grid --spp 16 --filter mitchell
  prism render scenes/whitted.json -o normals.png --aov normal
  prism render scenes/whitted.json -o high.png --camera-pos 0,6,9 --fov 35
  prism render scenes/whitted.json -o out.png --device 1 --no-cache
  prism render scenes/animation.json -o frames/ball_##.png --frames 0-5

Exit codes: 0 success; 1 failure (scene, device or file); 2 bad command line;
130 interrupted. More: docs/cli.md.
)";

const char* const kDevicesHelp =
    R"(Usage: prism devices

Lists the OpenCL devices prism can render on, one block per device: the index that
'prism render --device N' takes, the name, type, vendor, platform, compute units,
global memory, OpenCL C version and driver. The device used when --device is not
given (the first GPU, else the first device) is marked "default". 'prism render
--device all' (or a list such as 0,2) shares each frame over several devices.

No devices? prism needs an OpenCL runtime. PoCL runs on any CPU; on Debian or Ubuntu:
  sudo apt-get install pocl-opencl-icd
GPUs need their vendor's OpenCL driver. 'clinfo' shows what the OpenCL loader sees.

Exit codes: 0 when at least one device is found; 1 when there is none.
More: docs/cli.md.
)";

const char* const kInfoHelp =
    R"(Usage: prism info [--json] FILE

Reads a mesh file with the format plugins (see 'prism plugins') and prints what it
holds: vertex, face and triangle counts (after triangulating polygons and expanding
triangle strips; zero-area triangles are counted apart), the attributes present,
the bounding box, the materials, the plugin that read it, and any warnings. A point
cloud (no faces) is reported with 0 triangles.

  --json      print the same as a JSON object
  -h, --help  this help

Exit codes: 0 success; 1 the file could not be read (the message names it and why);
2 bad command line.
)";

const char* const kPluginsHelp =
    R"(Usage: prism plugins

Lists the mesh-format plugins prism found, what extensions each reads, and every
shared library it looked at but refused, with the reason (not loadable, missing
entry symbol, wrong ABI version). Search order: the folders in $PRISM_PLUGIN_PATH
(colon-separated), then plugins/ next to libprism. The plugin ABI is documented in
docs/plugins.md.
)";

const char* const kTraceHelp =
    R"(Usage: prism trace SCENE.json|MESH --rays IN --hits OUT [options]

Traces a file of rays against a scene or a mesh file and writes one hit per ray:
prism as a ray-query engine for other programs (the C API does the same with
prismIntersect and prismOccluded).

  --rays IN      rays: no header, 32-byte little-endian records
                   float ox, oy, oz, tmin, dx, dy, dz, tmax
                 (the direction need not be unit length; t is in its units)
  --hits OUT     hits: one 16-byte record per ray, in ray order
                   float t; int32 prim; float u, v
                 t = +inf and prim = -1 on a miss. prim numbers the primitives as
                 the primid AOV does: objects in scene order, a mesh counting its
                 triangles in file order (polygons fanned as (v0, vk, vk+1);
                 zero-area triangles keep their numbers). u, v: barycentrics of
                 vertices 1 and 2 (0 for analytic objects). A file is written
                 whole or not at all (a temporary beside it, then renamed; through
                 a symbolic link, beside the file it names); a pipe or device such
                 as /dev/stdout is written in place. A short write is an error.
                 Rays with a NaN or infinite component or no direction are misses.
  --occluded     answer any-hit instead: t = 0 where something lies in
                 (tmin, tmax), +inf where nothing does; prim = -1, u = v = 0
  --accel A      bvh (default), octree, bsp, none, or auto (none for at most 4
                 primitives, else bvh)
  --device D     the OpenCL device, as for 'prism render'
  --no-cache     compile the kernels afresh
  --quiet        no summary line

The summary gives the throughput of the tracing alone (no load, build, upload or
compilation) in Mrays/s.
)";

}  // namespace prism_cli
