/* Renders a texture graph to an image through the C API:
 *   render_texture GRAPH.json OUT.png [SIZE [NAME=VALUE]] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <shadetree.h>

int main(int argc, char** argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: render_texture GRAPH.json OUT.png [SIZE [NAME=VALUE]]\n");
    return 2;
  }
  const int size = argc > 3 ? atoi(argv[3]) : 256;
  shadetree_graph* graph = NULL;
  shadetree_status status = shadetree_load(argv[1], SHADETREE_JIT, &graph);
  if (status == SHADETREE_OK && argc > 4) {
    char* equals = strchr(argv[4], '=');
    if (equals) *equals = '\0';
    status = shadetree_set_param(graph, argv[4], equals ? equals + 1 : "");
  }
  float* rgba = malloc(sizeof(float) * 4 * (size_t)(size > 0 ? size : 1) * (size_t)(size > 0 ? size : 1));
  if (status == SHADETREE_OK) status = shadetree_render_texture(graph, size, size, 0.0f, rgba);
  if (status == SHADETREE_OK) status = shadetree_write_image(argv[2], rgba, size, size, 4);
  if (status != SHADETREE_OK) fprintf(stderr, "%s\n", shadetree_last_error()); /* "error: ..." already */
  free(rgba);
  shadetree_free(graph);
  return (int)status;
}
