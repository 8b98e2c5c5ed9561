/* shadetree's C API: load, check and compile node graphs (JIT or
 * interpreter), set their params, run their kernels over planes of samples
 * and render texture graphs into images, from C or any language with a C
 * foreign-function interface. Link with libshadetree (CMake:
 * find_package(shadetree) and target shadetree::shadetree).
 *
 *   shadetree_graph* graph;
 *   if (shadetree_load("marble.json", SHADETREE_JIT, &graph) != SHADETREE_OK) {
 *     fprintf(stderr, "%s\n", shadetree_last_error());
 *     return 1;
 *   }
 *   shadetree_set_param(graph, "scale", "14");
 *   float* rgba = malloc(sizeof(float) * 4 * 512 * 512);
 *   shadetree_render_texture(graph, 512, 512, 0.0f, rgba);
 *   shadetree_write_image("marble.png", rgba, 512, 512, 4);
 *   shadetree_free(graph);
 *
 * Every function that can fail returns a status; on failure
 * shadetree_last_error() gives the one-line message the command line would
 * print (file, node, input and problem). A graph may be used from one
 * thread at a time; different graphs from different threads. */
#ifndef SHADETREE_H
#define SHADETREE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The command line's exit statuses. */
typedef enum shadetree_status {
  SHADETREE_OK = 0,
  SHADETREE_FAILURE = 1,       /* I/O, backend or internal failure */
  SHADETREE_INVALID_INPUT = 2  /* a malformed graph, a bad param value, a wrong argument */
} shadetree_status;

typedef enum shadetree_backend {
  SHADETREE_JIT = 0,         /* LLVM ORC, vectorized for the host */
  SHADETREE_INTERPRETER = 1  /* the reference backend */
} shadetree_backend;

/* A graph, checked and compiled into a kernel, with its params. */
typedef struct shadetree_graph shadetree_graph;

/* The message of the last failure on this thread ("" if none). */
const char* shadetree_last_error(void);

/* Loads a graph file (files it names are read from its folder), checks and
 * compiles it for `backend` (a shadetree_backend; an int, so that any
 * value a caller passes is defined and checked). *graph is NULL on
 * failure. */
shadetree_status shadetree_load(const char* path, int backend, shadetree_graph** graph);

/* The same from JSON text; `name` stands for the file in messages. */
shadetree_status shadetree_load_text(const char* json, const char* name, int backend, shadetree_graph** graph);

void shadetree_free(shadetree_graph* graph);

/* "texture", "surface" or "volume". */
const char* shadetree_kind(const shadetree_graph* graph);

/* Sets a param, written as for `shadetree render --set` ("14",
 * "0.2,0.4,0.8", "true"); checked against its type and range. Params are
 * bound when a kernel runs: setting one never recompiles. */
shadetree_status shadetree_set_param(shadetree_graph* graph, const char* name, const char* value);

/* The plane indices of shadetree_run: the input plane of component
 * `component` of the global `global` ("P", "N", "uv", "I", "surface",
 * "filter_width", "density", "L"), and the output plane of component
 * `component` of output `output` ("color", "alpha", "density"...) of the
 * graph's kind. -1 if there is no such plane. */
int shadetree_input_plane(const char* global, int component);
int shadetree_output_plane(const shadetree_graph* graph, const char* output, int component);
/* The number of input planes, and of the graph's output planes. */
int shadetree_input_plane_count(void);
int shadetree_output_plane_count(const shadetree_graph* graph);

/* Runs the kernel over `count` samples: inputs[i] is input plane i (count
 * floats; NULL for a global the graph does not read, and only those), and
 * outputs[i] output plane i (NULL: not written). Time is frame / 24. */
shadetree_status shadetree_run(shadetree_graph* graph, float frame, const float* const* inputs,
                               float* const* outputs, size_t count);

/* Encloses what shadetree_run computes over a box of its inputs: lo[i] and
 * hi[i] bound input plane i (shadetree_input_plane_count() of each; an
 * infinite bound where nothing is known), and out_lo[i], out_hi[i] receive
 * an interval holding output plane i of every sample in the box (-inf and
 * +inf where nothing is known; the planes of outputs the graph does not
 * provide are left alone). For culling: where a volume's density is at most
 * 0 over a box, no sample in it holds anything. With SHADETREE_JIT the
 * graph's interval program is compiled on the first call (tens to hundreds
 * of milliseconds) and kept; its enclosures are the interpreter's to the
 * bit. */
shadetree_status shadetree_bound(shadetree_graph* graph, float frame, const float* lo, const float* hi,
                                 float* out_lo, float* out_hi);

/* A graph of any kind through its driver, as `shadetree render` renders
 * it (a texture over its render domain, a surface graph on its scene or
 * the preview sphere, a volume through the ray marcher) at width x height,
 * at `frame`: RGBA floats, row by row from the top (alpha 1 where the
 * graph has none), into `rgba` (4 * width * height floats). On all cores. */
shadetree_status shadetree_render(shadetree_graph* graph, int width, int height, float frame, float* rgba);

/* As shadetree_render, refusing graphs that are not textures. */
shadetree_status shadetree_render_texture(shadetree_graph* graph, int width, int height, float frame, float* rgba);

/* Writes pixels (channels 1 to 4, interleaved, rows from the top) to a
 * .png (8-bit) or .exr (float) file, through a temporary file renamed into
 * place only once complete. */
shadetree_status shadetree_write_image(const char* path, const float* pixels, int width, int height, int channels);

#ifdef __cplusplus
}
#endif

#endif /* SHADETREE_H */
