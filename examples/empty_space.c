/* Finds where a volume graph's density is certainly 0, through the C API's
 * interval bounds: the cube [-HALF, HALF]^3 cut into CELLS^3 boxes, each
 * bounded once (a renderer would skip the empty ones).
 *   empty_space GRAPH.json HALF [CELLS] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <shadetree.h>

int main(int argc, char** argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: empty_space GRAPH.json HALF [CELLS]\n");
    return 2;
  }
  const float half = strtof(argv[2], NULL);
  const int cells = argc > 3 ? atoi(argv[3]) : 16;
  if (!(half > 0.0f) || !isfinite(half) || cells < 1 || cells > 256) {
    fprintf(stderr, "error: HALF must be a finite number above 0 and CELLS from 1 to 256\n");
    return 2;
  }
  shadetree_graph* graph = NULL;
  shadetree_status status = shadetree_load(argv[1], SHADETREE_JIT, &graph);
  if (status != SHADETREE_OK) {
    fprintf(stderr, "%s\n", shadetree_last_error()); /* "error: ..." already */
    return (int)status;
  }
  const int density = shadetree_output_plane(graph, "density", 0);
  if (density < 0) {
    fprintf(stderr, "error: %s is not a volume graph\n", argv[1]);
    shadetree_free(graph);
    return 2;
  }
  const int inputs = shadetree_input_plane_count(), outputs = shadetree_output_plane_count(graph);
  float* lo = malloc(sizeof(float) * (size_t)inputs);
  float* hi = malloc(sizeof(float) * (size_t)inputs);
  float* out_lo = malloc(sizeof(float) * (size_t)outputs);
  float* out_hi = malloc(sizeof(float) * (size_t)outputs);
  /* Every input unknown but P (and the filter width, 0). */
  for (int i = 0; i < inputs; ++i) {
    lo[i] = -INFINITY;
    hi[i] = INFINITY;
  }
  const int width = shadetree_input_plane("filter_width", 0);
  lo[width] = hi[width] = 0.0f;
  const int p[3] = {shadetree_input_plane("P", 0), shadetree_input_plane("P", 1), shadetree_input_plane("P", 2)};
  const float side = 2.0f * half / (float)cells;
  long empty = 0;
  for (int z = 0; z < cells && status == SHADETREE_OK; ++z)
    for (int y = 0; y < cells && status == SHADETREE_OK; ++y)
      for (int x = 0; x < cells && status == SHADETREE_OK; ++x) {
        const int corner[3] = {x, y, z};
        for (int c = 0; c < 3; ++c) {
          lo[p[c]] = -half + side * (float)corner[c];
          hi[p[c]] = lo[p[c]] + side;
        }
        status = shadetree_bound(graph, 0.0f, lo, hi, out_lo, out_hi);
        empty += status == SHADETREE_OK && out_hi[density] <= 0.0f;
      }
  if (status == SHADETREE_OK)
    printf("%ld of %d boxes of [-%g, %g]^3 certainly empty\n", empty, cells * cells * cells, half, half);
  else
    fprintf(stderr, "%s\n", shadetree_last_error()); /* "error: ..." already */
  free(lo);
  free(hi);
  free(out_lo);
  free(out_hi);
  shadetree_free(graph);
  return (int)status;
}
