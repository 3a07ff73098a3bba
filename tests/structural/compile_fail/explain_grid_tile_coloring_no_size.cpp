// expect: tessera::GridTileColoring: the type has no grid size\. Add members `index_t cols\(\) const`
#include <tessera/tiling/tile_lookup.hpp>
struct coloring {  // a TileColoring, but compose_tiles needs to know its columns
  tessera::index_t num_faces() const { return 4; }
  int num_colors(int) const { return 2; }
  int edge_color(tessera::index_t, int) const { return 0; }
};
int main() { tessera::explain_grid_tile_coloring<coloring>(); }
