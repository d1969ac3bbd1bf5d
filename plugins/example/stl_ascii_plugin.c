/* stl_ascii_plugin.c -- an example prism plugin: ASCII STL.
 *
 * Written the way a third party would write one: plain C99, built against
 * the installed <prism_plugin.h> alone, no prism internals. It shows the
 * whole contract: export one versioned entry point, describe the plugin,
 * push geometry through the host's sink, report errors in err (with the line)
 * instead of crashing, and stop when a sink callback returns non-zero.
 *
 * ASCII STL has no shared vertices: every facet brings its own three, so the
 * mesh has 3 vertices per triangle. Binary STL is refused as unsupported.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <prism_plugin.h>

/* Larger than any ASCII STL this example is meant for; keeps reads bounded. */
#define STL_MAX_BYTES (256L * 1024 * 1024)

typedef struct {
  const char* text; /* NUL-terminated file contents */
  const char* pos;
  unsigned long line;
  char token[64];
} StlCursor;

static void fail(PrismPluginError* err, unsigned long line, const char* message) {
  snprintf(err->message, sizeof err->message, "%s", message);
  err->line = line;
}

/* Reads the next whitespace-separated word into c->token; 0 at the end. */
static int next_token(StlCursor* c) {
  size_t n = 0;
  while (*c->pos == ' ' || *c->pos == '\t' || *c->pos == '\r' || *c->pos == '\n') {
    if (*c->pos == '\n') c->line++;
    c->pos++;
  }
  if (*c->pos == '\0') return 0;
  while (*c->pos != '\0' && *c->pos != ' ' && *c->pos != '\t' && *c->pos != '\r' && *c->pos != '\n') {
    if (n + 1 < sizeof c->token) c->token[n++] = *c->pos;
    c->pos++;
  }
  c->token[n] = '\0';
  return 1;
}

static int expect(StlCursor* c, const char* word, PrismPluginError* err) {
  char message[160];
  if (next_token(c) && strcmp(c->token, word) == 0) return 1;
  snprintf(message, sizeof message, "expected '%s'", word);
  fail(err, c->line, message);
  return 0;
}

static int read_float(StlCursor* c, float* out, PrismPluginError* err) {
  char* end = NULL;
  double v;
  if (!next_token(c)) {
    fail(err, c->line, "the file ends inside a facet");
    return 0;
  }
  errno = 0;
  v = strtod(c->token, &end);
  if (end == c->token || *end != '\0' || errno == ERANGE || !isfinite(v)) {
    fail(err, c->line, "expected a finite number");
    return 0;
  }
  *out = (float)v;
  return 1;
}

/* Reads the whole file into a NUL-terminated buffer the caller frees. */
static char* read_file(const char* path, PrismPluginError* err, int* status) {
  FILE* f = fopen(path, "rb");
  long size;
  char* text;
  *status = PRISM_PLUGIN_ERROR_IO;
  if (f == NULL) {
    fail(err, 0, "cannot open the file");
    return NULL;
  }
  if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
    fail(err, 0, "cannot tell the file's size");
    fclose(f);
    return NULL;
  }
  if (size > STL_MAX_BYTES) {
    *status = PRISM_PLUGIN_ERROR_LIMIT;
    fail(err, 0, "file too large for the example STL reader");
    fclose(f);
    return NULL;
  }
  text = (char*)malloc((size_t)size + 1);
  if (text == NULL) {
    *status = PRISM_PLUGIN_ERROR_OUT_OF_MEMORY;
    fail(err, 0, "out of memory");
    fclose(f);
    return NULL;
  }
  size = (long)fread(text, 1, (size_t)size, f);
  text[size] = '\0';
  fclose(f);
  if (memchr(text, '\0', (size_t)size) != NULL) {
    *status = PRISM_PLUGIN_ERROR_UNSUPPORTED;
    fail(err, 0, "binary STL is not supported by this example (ASCII only)");
    free(text);
    return NULL;
  }
  *status = PRISM_PLUGIN_OK;
  return text;
}

/* facet normal nx ny nz / outer loop / vertex x y z (3x) / endloop / endfacet */
static int read_facet(StlCursor* c, const PrismMeshSink* sink, uint32_t first_vertex, PrismPluginError* err) {
  float n[3], p[3];
  uint32_t corners[3];
  int k;
  if (!expect(c, "normal", err) || !read_float(c, &n[0], err) || !read_float(c, &n[1], err) ||
      !read_float(c, &n[2], err) || !expect(c, "outer", err) || !expect(c, "loop", err))
    return PRISM_PLUGIN_ERROR_PARSE;
  for (k = 0; k < 3; ++k) {
    if (!expect(c, "vertex", err) || !read_float(c, &p[0], err) || !read_float(c, &p[1], err) ||
        !read_float(c, &p[2], err))
      return PRISM_PLUGIN_ERROR_PARSE;
    if (sink->add_position(sink->host, p[0], p[1], p[2]) != 0) return PRISM_PLUGIN_ERROR_SINK;
    corners[k] = first_vertex + (uint32_t)k;
  }
  if (!expect(c, "endloop", err) || !expect(c, "endfacet", err)) return PRISM_PLUGIN_ERROR_PARSE;
  /* The facet normal is per face; prism keeps normals per vertex, and these
   * vertices are this facet's own, so it can serve as their normal. */
  for (k = 0; k < 3; ++k)
    if (sink->add_normal(sink->host, n[0], n[1], n[2]) != 0) return PRISM_PLUGIN_ERROR_SINK;
  if (sink->add_face(sink->host, corners, 3, -1) != 0) return PRISM_PLUGIN_ERROR_SINK;
  return PRISM_PLUGIN_OK;
}

static int load_stl(const char* path, const PrismMeshSink* sink, PrismPluginError* err) {
  StlCursor c;
  int status = PRISM_PLUGIN_OK;
  uint32_t vertices = 0;
  char* text = read_file(path, err, &status);
  if (text == NULL) return status;
  c.text = c.pos = text;
  c.line = 1;
  if (!next_token(&c) || strcmp(c.token, "solid") != 0) {
    fail(err, c.line, "not an ASCII STL file (it must start with 'solid')");
    free(text);
    return PRISM_PLUGIN_ERROR_PARSE;
  }
  if (sink->begin(sink->host, 0, 0) != 0) {
    free(text);
    return PRISM_PLUGIN_ERROR_SINK;
  }
  /* The solid's name may be several words: skip to the first keyword. */
  while (status == PRISM_PLUGIN_OK) {
    if (!next_token(&c)) {
      fail(err, c.line, "the file ends without 'endsolid'");
      status = PRISM_PLUGIN_ERROR_PARSE;
    } else if (strcmp(c.token, "endsolid") == 0) {
      break;
    } else if (strcmp(c.token, "facet") == 0) {
      if (vertices > 0xfffffff0u) {
        fail(err, c.line, "too many facets");
        status = PRISM_PLUGIN_ERROR_LIMIT;
      } else {
        status = read_facet(&c, sink, vertices, err);
        vertices += 3;
      }
    } else if (vertices > 0) {
      fail(err, c.line, "expected 'facet' or 'endsolid'");
      status = PRISM_PLUGIN_ERROR_PARSE;
    }
  }
  free(text);
  return status;
}

static const char* const stl_extensions[] = {"stl", NULL};

static const PrismPluginInfo stl_info = {
    sizeof(PrismPluginInfo), PRISM_PLUGIN_ABI_VERSION, "stl-example", stl_extensions,
    "ASCII STL (example plugin, plugins/example)", load_stl,
    NULL}; /* no probe: prism picks this plugin by the .stl extension only */

PRISM_PLUGIN_EXPORT const PrismPluginInfo* prism_plugin_entry_v1(void) { return &stl_info; }
