#include <tessera/fabric/make_fabric.hpp>

#include <catch2/catch.hpp>

#include <tessera/fabric/tone_proportions.hpp>

#include "../core/packed_texture_support.hpp"
#include "fabric_test_support.hpp"

using namespace tessera;

TEST_CASE("make_fabric = source square, cat map, perturbation, tiling", "[make_fabric]") {
  const auto src = fabric_test::random_image<std::uint8_t, 3>(48, 48, 2);
  // same size, no perturbation: exactly the cat map
  image_buffer<std::uint8_t, 3> out(48, 48);
  REQUIRE(make_fabric(src, out, {.iterations = 31}).ok());
  CHECK(out == *cat_map(src, 31));
  // with perturbation: the perturbation of the cat map
  REQUIRE(make_fabric(src, out, {.iterations = 31, .perturbation = {.generations = 2, .seed = 3}}).ok());
  image_buffer<std::uint8_t, 3> expected(48, 48);
  REQUIRE(life_perturbation(*cat_map(src, 31), expected, {.generations = 2, .seed = 3}).ok());
  CHECK(out == expected);
  // any output size by tiling the periodic N x N result
  image_buffer<std::uint8_t, 3> wide(130, 70);
  REQUIRE(make_fabric(src, wide, {.iterations = 31, .tile_size = 48}).ok());
  const auto tile = *cat_map(src, 31);
  for (index_t y = 0; y < 70; ++y)
    for (index_t x = 0; x < 130; ++x) REQUIRE(wide.read(x, y) == tile.read(x % 48, y % 48));
}

TEST_CASE("make_fabric: a source that is not N x N is rejected unless options.fit says how to read it",
          "[make_fabric]") {
  const auto src = fabric_test::random_image<std::uint8_t, 3>(48, 48, 2);
  image_buffer<std::uint8_t, 3> wide(130, 70), small(20, 20);
  // default: reject, naming both sizes and the options that would accept it
  auto s = make_fabric(src, wide, {.iterations = 5});
  REQUIRE(s.code() == status_code::invalid_argument);
  CHECK(s.message().find("48 x 48") != std::string::npos);
  CHECK(s.message().find("130 x 130") != std::string::npos);
  CHECK(s.message().find("options.fit") != std::string::npos);
  CHECK(make_fabric(src, small).code() == status_code::invalid_argument);
  const auto tall = fabric_test::random_image<std::uint8_t, 3>(30, 44, 3);
  CHECK(make_fabric(tall, small, {.tile_size = 30}).code() == status_code::invalid_argument);

  // crop_or_repeat: generated at the output size (N = max side); the source repeated when smaller
  REQUIRE(make_fabric(src, wide, {.iterations = 5, .fit = source_fit::crop_or_repeat}).ok());
  image_buffer<std::uint8_t, 3> square(130, 130), src130(130, 130);
  for (index_t y = 0; y < 130; ++y)
    for (index_t x = 0; x < 130; ++x) src130.write(x, y, src.read(x % 48, y % 48));
  REQUIRE(cat_map(src130, square, 5).ok());
  for (index_t y = 0; y < 70; ++y)
    for (index_t x = 0; x < 130; ++x) REQUIRE(wide.read(x, y) == square.read(x, y));
  // ... and a centred window when larger
  REQUIRE(make_fabric(src, small, {.iterations = 0, .fit = source_fit::crop_or_repeat}).ok());
  CHECK(small.read(0, 0) == src.read(14, 14));

  // centered_square: the largest centred square of the source at its own side, tiled (no seams)
  REQUIRE(make_fabric(tall, wide, {.iterations = 9, .fit = source_fit::centered_square}).ok());
  image_buffer<std::uint8_t, 3> centre(30, 30);
  for (index_t y = 0; y < 30; ++y)
    for (index_t x = 0; x < 30; ++x) centre.write(x, y, tall.read(x, y + 7));
  const auto tile = *cat_map(centre, 9);
  for (index_t y = 0; y < 70; ++y)
    for (index_t x = 0; x < 130; ++x) REQUIRE(wide.read(x, y) == tile.read(x % 30, y % 30));
  REQUIRE(make_fabric(tall, wide, {.iterations = 9, .tile_size = 30, .fit = source_fit::centered_square}).ok());
  auto e = make_fabric(tall, wide, {.tile_size = 20, .fit = source_fit::centered_square});
  CHECK(e.code() == status_code::invalid_argument);
  CHECK(e.message().find("tile_size must be 0 or 30") != std::string::npos);
  CHECK(make_fabric(tall, wide, {.fit = static_cast<source_fit>(9)}).code() == status_code::invalid_argument);
}

TEST_CASE("make_fabric from a palette keeps its tone proportions", "[make_fabric]") {
  const palette bw = {{{0, 0, 0}, 0.75}, {{1, 1, 1}, 0.25}};
  image_buffer<std::uint8_t, 1> out(64, 64);
  REQUIRE(make_fabric(bw, {.layout = source_layout::blocks, .feature_size = 8}, out, {.iterations = 60}).ok());
  auto p = tone_proportions(out, bw);
  CHECK((*p)[0] == Approx(0.75));
}

TEST_CASE("presets: the paper's fabrics, deterministic, any size", "[make_fabric]") {
  for (fabric_preset preset : all_fabric_presets) {
    INFO(to_string(preset));
    CHECK(parse_fabric_preset(to_string(preset)).value() == preset);
    image_buffer<std::uint8_t, 3> a(80, 60), b(80, 60);
    REQUIRE(make_fabric(preset, a, {.tile_size = 40, .seed = 3}).ok());
    thread_pool_executor pool(2);
    REQUIRE(make_fabric(preset, b, {.tile_size = 40, .seed = 3}, pool).ok());
    CHECK(a == b);
    for (index_t y = 0; y < 60; ++y)
      for (index_t x = 0; x < 80; ++x) REQUIRE(a.read(x, y) == a.read(x % 40, y % 40));
  }
  const auto flannel = fabric_preset_recipe(fabric_preset::flannel);
  CHECK(flannel.options.iterations == 60);
  CHECK(fabric_preset_recipe(fabric_preset::twill).options.iterations == 31);
  CHECK(fabric_preset_recipe(fabric_preset::linen).options.iterations == 80);
  CHECK(fabric_preset_recipe(fabric_preset::tweed).options.perturbation.generations > 0);
  image_buffer<std::uint8_t, 3> f(64, 64);
  REQUIRE(make_fabric(fabric_preset::flannel, f).ok());
  CHECK((*tone_proportions(f, flannel.tones))[0] == Approx(0.75));
  CHECK_FALSE(parse_fabric_preset("velvet").ok());
  // a value outside the enum has no name and makes no fabric (no read past the name table)
  const auto bogus = static_cast<fabric_preset>(7), negative = static_cast<fabric_preset>(-1);
  CHECK(to_string(bogus) == "unknown");
  CHECK(to_string(negative) == "unknown");
  auto s = make_fabric(bogus, f);
  CHECK(s.code() == status_code::invalid_argument);
  CHECK(s.message().find("7") != std::string::npos);
}

TEST_CASE("make_fabric rejects bad input and can be cancelled", "[make_fabric]") {
  const auto src = fabric_test::random_image<std::uint8_t, 3>(16, 16, 2);
  image_buffer<std::uint8_t, 3> out(16, 16);
  CHECK(make_fabric(src, out, {.tile_size = -2}).message().find("-2") != std::string::npos);
  CHECK(make_fabric(src, out, {.tile_size = index_t{1} << 21}).code() == status_code::size_overflow);
  CHECK(make_fabric(src, out, {.perturbation = {.dead_count = 0}}).code() == status_code::invalid_argument);
  CHECK(make_fabric(palette{}, {}, out).code() == status_code::invalid_argument);
  image_view<const std::uint8_t, 3> empty;
  CHECK(make_fabric(empty, out).code() == status_code::invalid_argument);
  image_view<std::uint8_t, 3> empty_out;
  CHECK(make_fabric(src, empty_out).code() == status_code::invalid_argument);
  CHECK(make_fabric(fabric_preset::linen, empty_out).code() == status_code::invalid_argument);
  fabric_options o{.perturbation = {.generations = 2}};
  o.progress.callback = [](double f, std::string_view) { return f < 0.5; };
  CHECK(make_fabric(src, out, o).code() == status_code::cancelled);
}

TEST_CASE("make_fabric: an adapted texture exposing its rows gets the pixels of the per-pixel path", "[fabric]") {
  STATIC_REQUIRE(ContiguousImage<test_support::packed_texture>);
  auto fast = test_support::packed_texture::make(70, 50);
  auto slow = test_support::packed_texture_slow::make(70, 50);
  REQUIRE(make_fabric(fabric_preset::twill, fast, {.tile_size = 32}).ok());
  REQUIRE(make_fabric(fabric_preset::twill, slow, {.tile_size = 32}).ok());
  REQUIRE(fast.texels == slow.texels);
}
