#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <string>

#include <tessera/io/polycube_file.hpp>

#include "../surface/shapes.hpp"

using namespace tessera;

TEST_CASE("polycube file: save and load give the same map") {
  polycube_options o;
  o.tiles_across = 5;
  auto map = build_polycube_map(shapes::torus(2, 0.7, 32, 12), o);
  REQUIRE(map);
  const std::string path = std::string(TESSERA_TEST_OUTPUT_DIR) + "/torus.polycube";
  REQUIRE(save_polycube_map(path, *map));
  auto back = load_polycube_map(path);
  INFO(back.error().to_string());
  REQUIRE(back);
  CHECK(back->polycube == map->polycube);
  CHECK(back->base.positions == map->base.positions);
  CHECK(back->labels == map->labels);
  CHECK(back->layout.quads.size() == map->layout.quads.size());
  CHECK(back->face_origin.empty());
  // a refined base keeps the input face of every face
  auto refined = *map;
  for (std::size_t f = 0; f < refined.base.faces.size(); ++f)
    refined.face_origin.push_back(static_cast<index_t>(f / 2 * 2));
  REQUIRE(save_polycube_map(path, refined));
  auto back2 = load_polycube_map(path);
  REQUIRE(back2);
  CHECK(back2->face_origin == refined.face_origin);
  // an input face on one line only, or after its own face, is refused naming the line
  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto last = text.rfind(' ');
  const std::string cut = std::string(TESSERA_TEST_OUTPUT_DIR) + "/torus_bad.polycube";
  std::ofstream(cut) << text.substr(0, last) << " 999999\n";
  CHECK(load_polycube_map(cut).error().code() == status_code::parse_error);
  const std::string lp = std::string(TESSERA_TEST_OUTPUT_DIR) + "/torus.labels";
  REQUIRE(write_polycube_labels(lp, map->labels));
  auto lab = read_polycube_labels(lp);
  REQUIRE(lab);
  CHECK(lab->size() == map->labels.size());
}

TEST_CASE("polycube file: bad files") {
  const std::string dir = TESSERA_TEST_OUTPUT_DIR;
  CHECK(load_polycube_map(dir + "/missing.polycube").error().code() == status_code::io_error);
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir + "/" + name) << text;
    return dir + "/" + name;
  };
  CHECK(load_polycube_map(write("a.polycube", "hello\n")).error().code() == status_code::parse_error);
  CHECK(load_polycube_map(write("b.polycube", "tessera-polycube 1\ntile 1\ncounts 100000000 1\n")).error().code() ==
        status_code::parse_error);
  CHECK(load_polycube_map(write("c.polycube", "tessera-polycube 1\ntile 1\ncounts 1 0\nv 1 2 nan 0 0 0\n"))
            .error()
            .code() == status_code::parse_error);
  CHECK(read_polycube_labels(write("d.labels", "0\n1\n6\n")).error().message().find("line 3") != std::string::npos);
}
