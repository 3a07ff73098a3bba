#include <tessera/io/wang_tiles.hpp>

#include <tessera/image/exemplars.hpp>

#include <filesystem>
#include <fstream>

#include <catch2/catch.hpp>

#include "../image/quilt_test_support.hpp"

using tessera::index_t;

namespace {
std::string wang_scratch(const std::string& name) {
  const auto dir = std::filesystem::path(TESSERA_TEST_OUTPUT_DIR) / "wang_io" / name;
  std::filesystem::remove_all(dir);
  return dir.string();
}
}  // namespace

TEST_CASE("wang tile io: save then load is bit-exact", "[wang]") {
  const auto ex = quilt_test::exemplar<std::uint8_t, 4>(tessera::exemplar_kind::dots, 40);
  auto set = tessera::build_wang_tiles(ex, {.tile_size = 16, .horizontal_colors = 2, .vertical_colors = 1});
  REQUIRE(set.ok());
  const auto dir = wang_scratch("roundtrip");
  REQUIRE(tessera::save_wang_tiles(dir, *set, {{"exemplar_seed", 1}}).ok());
  REQUIRE(std::filesystem::exists(std::filesystem::path(dir) / "tile_3.png"));
  auto back = tessera::load_wang_tiles<std::uint8_t, 4>(dir);
  REQUIRE(back.ok());
  REQUIRE(back->size() == set->size());
  REQUIRE(back->tile_size() == 16);
  for (index_t t = 0; t < set->size(); ++t) {
    REQUIRE(back->edges()[t] == set->edges()[t]);
    for (index_t y = 0; y < 16; ++y)
      for (index_t x = 0; x < 16; ++x) REQUIRE(back->tile(t).read(x, y) == set->tile(t).read(x, y));
  }
  REQUIRE(tessera::read_tile_manifest(dir)->extra_value("exemplar_seed") == 1);
  // the loaded set measures the same shared border, so its atlas promises the same mip levels
  REQUIRE(back->shared_border() == set->shared_border());
  REQUIRE(back->exact_mip_levels() == set->exact_mip_levels());
  REQUIRE(back->exact_mip_levels() == 2);  // tiles of 16: border 2
}

TEST_CASE("wang tile io: missing and mismatched files are named", "[wang]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::sand, 32);
  auto set = tessera::build_wang_tiles(ex, {.tile_size = 8, .horizontal_colors = 1, .vertical_colors = 2});
  const auto dir = wang_scratch("broken");
  REQUIRE(tessera::save_wang_tiles(dir, *set).ok());
  // a tile of the wrong size
  REQUIRE(tessera::write_png((std::filesystem::path(dir) / "tile_1.png").string(),
                             tessera::image_buffer<std::uint8_t, 3>(9, 8))
              .ok());
  auto wrong = tessera::load_wang_tiles<std::uint8_t, 3>(dir);
  REQUIRE(wrong.error().code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(wrong.error().message(), Catch::Contains("tile_1.png is 9 x 8") && Catch::Contains("tile_size 8"));
  // a file that is not a PNG
  std::ofstream(std::filesystem::path(dir) / "tile_1.png") << "not a png";
  REQUIRE(tessera::load_wang_tiles<std::uint8_t, 3>(dir).error().code() == tessera::status_code::parse_error);
  // a missing tile
  std::filesystem::remove(std::filesystem::path(dir) / "tile_2.png");
  auto missing = tessera::load_wang_tiles<std::uint8_t, 3>(dir);
  REQUIRE(missing.error().code() == tessera::status_code::io_error);
  REQUIRE_THAT(missing.error().message(), Catch::Contains("tile_2.png"));
  // no directory at all
  REQUIRE(tessera::load_wang_tiles<std::uint8_t, 3>(wang_scratch("nothing")).error().code() ==
          tessera::status_code::io_error);
  // a malformed manifest
  std::ofstream(std::filesystem::path(dir) / "tiles.json") << "{\"tile_size\": 8,";
  auto malformed = tessera::load_wang_tiles<std::uint8_t, 3>(dir);
  REQUIRE(malformed.error().code() == tessera::status_code::parse_error);
  REQUIRE_THAT(malformed.error().message(), Catch::Contains("tiles.json"));
}
