#include <tessera/tiling/tile_set_edges.hpp>

#include <tessera/core/tile_coloring.hpp>

#include <catch2/catch.hpp>

using tessera::index_t;
using tessera::tile_set_edges;
using tessera::wang_edges;

TEST_CASE("tile set edges: lookups agree with brute force", "[tiling]") {
  // a set with a duplicate (two variants of one combination) and gaps
  std::vector<wang_edges> tiles = {{0, 1, 1, 0}, {1, 0, 0, 1}, {0, 1, 1, 0}, {1, 1, 0, 0}, {0, 0, 1, 1}, {2, 1, 0, 1}};
  auto set = tile_set_edges::create(3, 2, tiles);
  REQUIRE(set.ok());
  REQUIRE(set->size() == 6);
  REQUIRE(set->distinct_combinations() == 5);
  REQUIRE_FALSE(set->is_complete());
  for (int n = 0; n < 3; ++n)
    for (int e = 0; e < 2; ++e)
      for (int s = 0; s < 3; ++s)
        for (int w = 0; w < 2; ++w) {
          const wang_edges q{n, e, s, w};
          std::vector<index_t> expect;
          for (index_t i = 0; i < 6; ++i)
            if (tiles[static_cast<std::size_t>(i)] == q) expect.push_back(i);
          auto got = set->variants(q);
          REQUIRE(std::vector<index_t>(got.begin(), got.end()) == expect);
          REQUIRE(set->find(q) == (expect.empty() ? -1 : expect.front()));
        }
  for (int n = 0; n < 3; ++n)
    for (int w = 0; w < 2; ++w) {
      std::vector<index_t> expect;
      for (index_t i = 0; i < 6; ++i)
        if (tiles[static_cast<std::size_t>(i)].north == n && tiles[static_cast<std::size_t>(i)].west == w)
          expect.push_back(i);
      auto got = set->matching(n, w);
      REQUIRE(std::vector<index_t>(got.begin(), got.end()) == expect);
    }
  auto west1 = set->with_west(1);
  REQUIRE(std::vector<index_t>(west1.begin(), west1.end()) == std::vector<index_t>{1, 4, 5});
  auto north0 = set->with_north(0);
  REQUIRE(std::vector<index_t>(north0.begin(), north0.end()) == std::vector<index_t>{0, 2, 4});
  REQUIRE(set->find({9, 0, 0, 0}) == -1);  // out-of-range queries find nothing
  REQUIRE_FALSE(set->check_scanline_fillable().ok());
}

TEST_CASE("tile set edges: modular subsets (Cohen's 8 tiles) and hash moduli", "[tiling]") {
  auto cohen = tile_set_edges::modular_subset(2, 2, 2);
  REQUIRE(cohen.ok());
  REQUIRE(cohen->size() == 8);
  REQUIRE(cohen->hash_modulus() == 2);
  REQUIRE(cohen->check_scanline_fillable().ok());
  for (int n = 0; n < 2; ++n)
    for (int w = 0; w < 2; ++w) {
      REQUIRE(cohen->matching(n, w).size() == 2);  // two tiles for every (north, west) pair, as in Cohen et al.
      int south_east_pairs = 0;                    // and every (south, east) pair also twice
      for (const auto& t : cohen->tiles()) south_east_pairs += t.south == n && t.east == w;
      REQUIRE(south_east_pairs == 2);
    }
  for (const auto& t : cohen->tiles()) REQUIRE((t.north ^ t.east ^ t.south ^ t.west) == 0);

  auto sub = tile_set_edges::modular_subset(4, 6, 2);
  REQUIRE(sub.ok());
  REQUIRE(sub->size() == 4 * 4 * 6 * 6 / 2);
  REQUIRE(sub->hash_modulus() == 2);
  auto complete = tile_set_edges::complete(3, 3);
  REQUIRE(complete.ok());
  REQUIRE(complete->is_complete());
  REQUIRE(complete->hash_modulus() == 1);
  auto by3 = tile_set_edges::modular_subset(3, 3, 3);
  REQUIRE(by3->hash_modulus() == 3);
  REQUIRE(by3->size() == 27);

  // removing one tile of Cohen's set leaves a set no modulus supports
  std::vector<wang_edges> seven(cohen->tiles().begin() + 1, cohen->tiles().end());
  auto partial = tile_set_edges::create(2, 2, seven);
  REQUIRE(partial.ok());
  REQUIRE(partial->hash_modulus() == 0);

  REQUIRE(tile_set_edges::modular_subset(2, 3, 2).error().code() == tessera::status_code::invalid_argument);
  REQUIRE_FALSE(tile_set_edges::modular_subset(2, 2, 0).ok());
}

TEST_CASE("tile set edges: bad input", "[tiling]") {
  REQUIRE(tile_set_edges::create(2, 2, {}).error().code() == tessera::status_code::invalid_argument);
  REQUIRE_FALSE(tile_set_edges::create(0, 2, {{0, 0, 0, 0}}).ok());
  auto bad = tile_set_edges::create(2, 2, {{0, 0, 0, 0}, {0, 0, 2, 0}});
  REQUIRE(bad.error().code() == tessera::status_code::out_of_range);
  REQUIRE_THAT(bad.error().message(), Catch::Contains("tile 1") && Catch::Contains("south colour 2"));
  REQUIRE_FALSE(tile_set_edges::complete(2, 0).ok());
}

TEST_CASE("check_coloring_against_set reports the first face without a tile", "[tiling]") {
  auto cohen = tile_set_edges::modular_subset(2, 2, 2);
  tessera::stored_tile_coloring c{2, 2, {{0, 0, 0, 0}, {1, 1, 1, 1}, {0, 1, 0, 0}}};  // face 2: xor = 1, not in the set
  auto s = tessera::check_coloring_against_set(c, *cohen);
  REQUIRE(s.code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(s.message(), Catch::Contains("face 2") && Catch::Contains("east 1"));
  c.colors.pop_back();
  REQUIRE(tessera::check_coloring_against_set(c, *cohen).ok());
  tessera::stored_tile_coloring wrong_counts{3, 2, {{0, 0, 0, 0}}};
  REQUIRE_THAT(tessera::check_coloring_against_set(wrong_counts, *cohen).message(), Catch::Contains("3 horizontal"));
  tessera::stored_tile_coloring out_of_range{2, 2, {{0, 0, 5, 0}}};
  REQUIRE(tessera::check_coloring_against_set(out_of_range, *cohen).code() == tessera::status_code::out_of_range);
}
