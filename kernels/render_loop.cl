/* render_loop: the render loop's kernels other than extend, shade and the area
 * lights' pair, built as one program. Each keeps its own file; a cold start
 * builds this once where it would build seven programs, and PoCL pays about a quarter of a second per program built on top
 * of what their code costs (docs/architecture.md, "Kernel programs"). */
#include "generate.cl"
#include "count_rays.cl"
#include "scan_blocks.cl"
#include "scatter_rays.cl"
#include "accumulate.cl"
#include "supersample.cl"
#include "resolve.cl"
