// Built with -fno-exceptions (docs/no_exceptions.md): every public header (the umbrella, io/ and the
// Eigen and glm adapters) compiles without exceptions, and the parts that once needed them run:
// patch synthesis (nanoflann's kd-tree), Wang tiles, the thread pool, errors as statuses.
#include <tessera/adapters/eigen.hpp>
#include <tessera/adapters/glm.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/io/files.hpp>
#include <tessera/io/geometric_tiles.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/io/mesh_preview.hpp>
#include <tessera/io/obj.hpp>
#include <tessera/io/off.hpp>
#include <tessera/io/ply.hpp>
#include <tessera/io/png.hpp>
#include <tessera/io/polycube_file.hpp>
#include <tessera/io/terrain_uv_file.hpp>
#include <tessera/io/tile_manifest.hpp>
#include <tessera/io/wang_tiles.hpp>
#include <tessera/tessera.hpp>

#include <cstdint>
#include <cstdio>

#if TESSERA_HAS_EXCEPTIONS
#error "tests/structural/no_exceptions.cpp must be compiled with -fno-exceptions"
#endif

namespace {
int check(bool ok, const char* what) {
  if (!ok) std::fprintf(stderr, "no_exceptions: %s failed\n", what);
  return ok ? 0 : 1;
}
}  // namespace

int main() {
  using rgb8 = tessera::image_buffer<std::uint8_t, 3>;
  tessera::thread_pool_executor pool(2);
  auto ex = tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::dots, {.width = 64, .height = 64});
  if (!ex) return check(false, "make_exemplar");
  auto model = tessera::build_patch_model(*ex, {}, pool);  // the kd-tree of nanoflann
  if (!model) return check(false, "build_patch_model");
  rgb8 a(96, 80), b(96, 80);
  int failures = check(tessera::synthesize(*model, a, {.seed = 4}, pool).ok(), "synthesize (pool)");
  failures += check(tessera::synthesize(*model, b, {.seed = 4}).ok(), "synthesize (serial)");
  failures += check(a == b, "the same pixels for any executor");
  auto set = tessera::build_wang_tiles(*ex, {.tile_size = 24, .horizontal_colors = 2, .vertical_colors = 2}, pool);
  failures += check(set.ok(), "build_wang_tiles");
  // bad input is a status, not an exception
  failures += check(!tessera::build_patch_model(rgb8(0, 0)).ok(), "an empty exemplar is an error");
  failures += check(!tessera::read_png<std::uint8_t, 3>("/nonexistent/no.png").ok(), "a missing file is an error");
  std::printf("no_exceptions: %s\n", failures == 0 ? "ok" : "FAILED");
  return failures == 0 ? 0 : 1;
}
