// A program of a project that uses tessera: the umbrella header, PNG I/O, a raw-buffer mesh.
// Built by tests/consumer/find_package (against an installed tessera) and
// tests/consumer/add_subdirectory (tessera as a subproject). Usage: consumer OUTPUT_DIR
#include <tessera/tessera.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/io/png.hpp>

#include <cstdint>
#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: consumer OUTPUT_DIR\n");
    return 2;
  }
  auto img = tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::dots, {.width = 32, .height = 32});
  if (!img) return std::fprintf(stderr, "%s\n", img.error().to_string().c_str()), 1;
  const std::string path = std::string(argv[1]) + "/consumer.png";
  if (auto s = tessera::write_png(path, *img); !s) return std::fprintf(stderr, "%s\n", s.to_string().c_str()), 1;
  auto back = tessera::read_png<std::uint8_t, 3>(path);
  if (!back || !(*back == *img)) return std::fprintf(stderr, "PNG round trip failed\n"), 1;

  const float positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5, 6, 5, 5, 5, 6, 5};
  const std::uint32_t indices[] = {0, 1, 2, 3, 4, 5};
  auto mesh = tessera::make_mesh_view(positions, 6, indices, 2);
  if (!mesh || !tessera::validate_mesh(*mesh)) return std::fprintf(stderr, "mesh view failed\n"), 1;
  const auto components = tessera::connected_components(*mesh).count;
  std::printf("consumer: tessera %s, wrote %s, %td mesh components\n", TESSERA_VERSION_STRING, path.c_str(),
              components);
  return components == 2 ? 0 : 1;
}
