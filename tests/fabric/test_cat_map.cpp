#include <tessera/fabric/cat_map.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include <catch2/catch.hpp>

#include "fabric_test_support.hpp"

using namespace tessera;
using fabric_test::random_image;

namespace {
constexpr std::array<cat_map_strategy, 3> strategies = {cat_map_strategy::automatic, cat_map_strategy::direct,
                                                        cat_map_strategy::separable};

// n applications of the reference step.
template <class Img>
Img steps(Img img, int n, const cat_map_options& o = {}) {
  Img tmp = img;
  for (int i = 0; i < n; ++i) {
    REQUIRE(cat_map_step(img, tmp, o).ok());
    std::swap(img, tmp);
  }
  return img;
}

// A one-channel image whose pixels are all distinct (value = index), as floats (exact below 2^24).
image_buffer<float, 1> unique_image(index_t n) {
  image_buffer<float, 1> img(n, n);
  for (index_t i = 0; i < n * n; ++i) img.data()[i] = static_cast<float>(i);
  return img;
}
}  // namespace

TEST_CASE("cat_map_step moves (x, y) to [1 1, 1 2] (x, y) mod N", "[cat_map]") {
  const index_t n = 7;
  const auto img = unique_image(n);
  image_buffer<float, 1> out(n, n);
  REQUIRE(cat_map_step(img, out).ok());
  for (index_t y = 0; y < n; ++y)
    for (index_t x = 0; x < n; ++x) REQUIRE(out.read((x + y) % n, (x + 2 * y) % n)[0] == img.read(x, y)[0]);
  // the generalized family: (x + a y, b x + (ab+1) y)
  REQUIRE(cat_map_step(img, out, {.family = {2, 3}}).ok());
  for (index_t y = 0; y < n; ++y)
    for (index_t x = 0; x < n; ++x) REQUIRE(out.read((x + 2 * y) % n, (3 * x + 7 * y) % n)[0] == img.read(x, y)[0]);
}

TEST_CASE("a jump of n steps equals n single steps, forward and inverse", "[cat_map]") {
  for (index_t n : {1, 2, 3, 5, 8, 12, 31, 64, 101}) {
    for (cat_map_family f : {cat_map_family{1, 1}, cat_map_family{2, 3}, cat_map_family{-1, 4}}) {
      const auto img = random_image<std::uint8_t, 3>(n, n, static_cast<std::uint64_t>(n));
      auto expected = img;
      for (int k = 0; k <= 25; ++k) {
        for (cat_map_strategy s : strategies) {
          INFO("N = " << n << ", a = " << f.a << ", b = " << f.b << ", n = " << k << ", strategy " << int(s));
          const cat_map_options o{.family = f, .strategy = s};
          auto jumped = cat_map(img, k, o);
          REQUIRE(jumped.ok());
          REQUIRE(*jumped == expected);
          auto back = cat_map(*jumped, -k, o);
          REQUIRE(back.ok());
          REQUIRE(*back == img);
        }
        expected = steps(expected, 1, {.family = f});
      }
    }
  }
}

TEST_CASE("jumps by huge step counts reduce modulo the period", "[cat_map]") {
  const index_t n = 50;
  const auto img = random_image<std::uint16_t, 2>(n, n, 9);
  const auto period = static_cast<std::int64_t>(*cat_map_period(n));
  for (std::int64_t k : std::vector<std::int64_t>{INT64_MAX, INT64_MIN, INT64_MIN + 1, std::int64_t{1} << 40,
                                                  -(std::int64_t{3} << 50)}) {
    const std::int64_t r = ((k % period) + period) % period;
    for (cat_map_strategy s : strategies) {
      auto a = cat_map(img, k, {.strategy = s});
      auto b = cat_map(img, r, {.strategy = s});
      REQUIRE(a.ok());
      REQUIRE(*a == *b);
    }
  }
}

TEST_CASE("the period returns the image exactly and no smaller n does", "[cat_map]") {
  // exhaustive over n for small N, with an image whose pixels are all distinct
  for (index_t n : {1, 2, 3, 4, 5, 6, 7, 10, 16, 25, 30, 47, 64}) {
    const auto img = unique_image(n);
    const auto period = *cat_map_period(n);
    auto cur = img, tmp = img;
    for (std::uint64_t k = 1; k <= period; ++k) {
      REQUIRE(cat_map_step(cur, tmp).ok());
      std::swap(cur, tmp);
      INFO("N = " << n << ", step " << k << " of period " << period);
      REQUIRE((cur == img) == (k == period));
    }
  }
  // larger N (the paper's 400, 4096 is too large for a unit test): the jump by the period is the
  // identity, and the jump by period / q is not for any prime q dividing the period
  for (index_t n : {97, 128, 400}) {
    const auto img = unique_image(n);
    const auto period = *cat_map_period(n);
    REQUIRE(*cat_map(img, static_cast<std::int64_t>(period)) == img);
    for (const auto& q : detail::factorize(period))
      REQUIRE_FALSE(*cat_map(img, static_cast<std::int64_t>(period / q.p)) == img);
  }
}

TEST_CASE("the cat map permutes pixels: the histogram is unchanged", "[cat_map]") {
  const auto img = random_image<std::uint8_t, 4>(90, 90, 3);
  auto sorted_pixels = [](const image_buffer<std::uint8_t, 4>& b) {
    std::vector<std::array<std::uint8_t, 4>> px;
    for (index_t y = 0; y < b.height(); ++y)
      for (index_t x = 0; x < b.width(); ++x) px.push_back(b.read(x, y));
    std::sort(px.begin(), px.end());
    return px;
  };
  for (std::int64_t k : {1, 31, 60, 80, -7}) {
    auto out = cat_map(img, k, {.family = {3, 2}});
    REQUIRE(out.ok());
    REQUIRE(sorted_pixels(*out) == sorted_pixels(img));
  }
}

TEST_CASE("cat map output does not depend on the executor or thread count", "[cat_map]") {
  const auto img = random_image<std::uint8_t, 4>(200, 200, 5);
  for (cat_map_strategy s : strategies) {
    auto serial = cat_map(img, 60, {.strategy = s});
    for (int threads : {1, 2, 3, 5}) {
      thread_pool_executor pool(threads);
      auto parallel = cat_map(img, 60, {.strategy = s}, pool);
      REQUIRE(*parallel == *serial);
      image_buffer<std::uint8_t, 4> stepped(200, 200);
      REQUIRE(cat_map_step(img, stepped, {}, pool).ok());
      REQUIRE(stepped == *cat_map(img, 1));
    }
  }
}

TEST_CASE("cat map over views, a user type, other formats and in place", "[cat_map]") {
  const index_t n = 40;
  // image_view over a caller's buffer, with padding in the stride
  std::vector<std::uint8_t> raw(static_cast<std::size_t>(n * (n * 4 + 12)));
  for (std::size_t i = 0; i < raw.size(); ++i) raw[i] = static_cast<std::uint8_t>(i * 31 + 7);
  image_view<std::uint8_t, 4> view(raw.data(), n, n, n * 4 + 12);
  const auto as_buffer = *to_buffer(view);
  std::vector<std::uint8_t> raw_out(raw.size(), 0);
  image_view<std::uint8_t, 4> view_out(raw_out.data(), n, n, n * 4 + 12);
  REQUIRE(cat_map(image_view<const std::uint8_t, 4>(view), view_out, 31).ok());
  REQUIRE(*to_buffer(view_out) == *cat_map(as_buffer, 31));
  for (index_t y = 0; y < n; ++y)  // padding untouched
    for (index_t i = n * 4; i < n * 4 + 12; ++i) REQUIRE(raw_out[static_cast<std::size_t>(y * (n * 4 + 12) + i)] == 0);

  // in place on the view gives the same result
  REQUIRE(cat_map(view, view, 31).ok());
  REQUIRE(*to_buffer(view) == *to_buffer(view_out));

  // a member-style user type
  const auto tex = fabric_test::random_user_texture(n, n, 11);
  fabric_test::user_texture out(n, n);
  REQUIRE(cat_map(tex, out, -12).ok());
  auto tex_buf = *to_buffer(tex);
  REQUIRE(*to_buffer(out) == *cat_map(tex_buf, -12));

  // converting formats: float input, uint8 output equals converting afterwards
  const auto f = random_image<float, 3>(n, n, 2);
  image_buffer<std::uint8_t, 3> u8(n, n);
  REQUIRE(cat_map(f, u8, 5).ok());
  REQUIRE(u8 == *to_buffer<std::uint8_t, 3>(*cat_map(f, 5)));
}

TEST_CASE("cat_map_step and cat_map work in place and on overlapping views", "[cat_map]") {
  const index_t n = 23;
  const auto img = random_image<std::uint8_t, 3>(n, n, 5);
  for (const cat_map_family f : {cat_map_family{1, 1}, cat_map_family{2, 3}}) {
    INFO("a = " << f.a << ", b = " << f.b);
    const auto once = steps(img, 1, {.family = f});
    auto same = img;  // input and output are the same image
    REQUIRE(cat_map_step(same, same, {.family = f}).ok());
    REQUIRE(same == once);
    for (cat_map_strategy s : strategies) {
      auto jumped = img;
      REQUIRE(cat_map(jumped, jumped, 17, {.family = f, .strategy = s}).ok());
      REQUIRE(jumped == steps(img, 17, {.family = f}));
    }
  }
  // two views of one buffer, the output three rows below the input: they overlap in n - 3 rows
  std::vector<std::uint8_t> raw(static_cast<std::size_t>((n + 3) * n * 3));
  for (std::size_t i = 0; i < raw.size(); ++i) raw[i] = static_cast<std::uint8_t>(i * 53 + 11);
  image_view<std::uint8_t, 3> in(raw.data(), n, n, n * 3), out(raw.data() + 3 * n * 3, n, n, n * 3);
  const auto before = *to_buffer(in);
  REQUIRE(cat_map_step(image_view<const std::uint8_t, 3>(in), out).ok());
  REQUIRE(*to_buffer(out) == steps(before, 1));
  for (std::size_t i = 0; i < raw.size(); ++i) raw[i] = static_cast<std::uint8_t>(i * 53 + 11);
  REQUIRE(cat_map(image_view<const std::uint8_t, 3>(in), out, -40).ok());
  REQUIRE(*to_buffer(out) == *cat_map(before, -40));
}

TEST_CASE("non-square images: rejected by default, centred square or square tiles on request", "[cat_map]") {
  const auto img = random_image<std::uint8_t, 3>(60, 36, 4);
  image_buffer<std::uint8_t, 3> out(60, 36);

  auto s = cat_map(img, out, 5);
  REQUIRE(s.code() == status_code::invalid_argument);
  CHECK(s.message().find("60 x 36") != std::string::npos);
  CHECK(s.message().find("square") != std::string::npos);
  REQUIRE(cat_map_step(img, out).code() == status_code::invalid_argument);

  // centred square: 36 x 36 at x = 12, the rest unchanged
  REQUIRE(cat_map(img, out, 5, {.non_square = non_square_mode::centered_square}).ok());
  image_buffer<std::uint8_t, 3> square(36, 36);
  for (index_t y = 0; y < 36; ++y)
    for (index_t x = 0; x < 36; ++x) square.write(x, y, img.read(x + 12, y));
  const auto mapped = *cat_map(square, 5);
  for (index_t y = 0; y < 36; ++y)
    for (index_t x = 0; x < 60; ++x)
      REQUIRE(out.read(x, y) == (x >= 12 && x < 48 ? mapped.read(x - 12, y) : img.read(x, y)));

  // square tiles: gcd(60, 36) = 12 by default; each tile mapped on its own
  for (index_t tile : {0, 12, 25}) {
    REQUIRE(cat_map(img, out, 7, {.non_square = non_square_mode::square_tiles, .tile_size = tile}).ok());
    const index_t t = tile == 0 ? 12 : tile;
    for (index_t ty = 0; ty + t <= 36; ty += t)
      for (index_t tx = 0; tx + t <= 60; tx += t) {
        image_buffer<std::uint8_t, 3> part(t, t);
        for (index_t y = 0; y < t; ++y)
          for (index_t x = 0; x < t; ++x) part.write(x, y, img.read(tx + x, ty + y));
        const auto m = *cat_map(part, 7);
        for (index_t y = 0; y < t; ++y)
          for (index_t x = 0; x < t; ++x) REQUIRE(out.read(tx + x, ty + y) == m.read(x, y));
      }
    // the remainder outside whole tiles is unchanged (25: columns 50.., rows 25..)
    if (t == 25) {
      REQUIRE(out.read(55, 3) == img.read(55, 3));
      REQUIRE(out.read(3, 30) == img.read(3, 30));
    }
  }
  for (index_t bad : {-1, 37, 1000}) {
    auto e = cat_map(img, out, 7, {.non_square = non_square_mode::square_tiles, .tile_size = bad});
    REQUIRE(e.code() == status_code::invalid_argument);
    CHECK(e.message().find("tile_size") != std::string::npos);
  }
}

TEST_CASE("cat map rejects empty and mismatched images", "[cat_map]") {
  image_view<const std::uint8_t, 3> empty;
  image_buffer<std::uint8_t, 3> out(4, 4);
  CHECK(cat_map(empty, out, 1).code() == status_code::invalid_argument);
  CHECK(cat_map_step(empty, out).code() == status_code::invalid_argument);
  CHECK_FALSE(cat_map(empty, 1).ok());
  const auto img = random_image<std::uint8_t, 3>(5, 5, 1);
  auto s = cat_map(img, out, 1);
  CHECK(s.code() == status_code::invalid_argument);
  CHECK(s.message().find("4 x 4") != std::string::npos);
  CHECK(out == image_buffer<std::uint8_t, 3>(4, 4));  // untouched
}

TEST_CASE("the separable kernel equals the direct gather for every factorization case", "[cat_map]") {
  // random matrices of determinant 1 mod N, including ones where neither diagonal entry is a unit
  // (three passes), checked against the one-pass gather
  const counter_rng rng(17);
  int three_pass = 0;
  for (index_t n : {6, 8, 12, 30, 64, 90}) {
    const auto img = random_image<std::uint8_t, 3>(n, n, static_cast<std::uint64_t>(n));
    const auto un = static_cast<detail::u64>(n);
    for (int trial = 0; trial < 40; ++trial) {
      // [a b; c d] = [1 s; 0 1][1 0; t 1][1 r; 0 1] [1 0; q 1]: products of shears have determinant 1
      auto draw = [&](int k) { return rng.below(un, n, trial, k); };
      detail::mat2 g = detail::mat_identity(un);
      g = detail::mat_mul(g, {1, draw(0), 0, 1}, un);
      g = detail::mat_mul(g, {1, 0, draw(1), 1}, un);
      g = detail::mat_mul(g, {1, draw(2), 0, 1}, un);
      g = detail::mat_mul(g, {1, 0, draw(3), 1}, un);
      if (trial == 0) g = {2 % un, 3 % un, 1 % un, 2 % un};  // det 1, both diagonal entries even
      three_pass += detail::plan_separable(g, un).size() == 3;
      image_buffer<std::uint8_t, 3> direct(n, n), separable(n, n);
      serial_executor exec;
      detail::apply_gather<std::uint8_t, 3>(img.cview(), direct.view(), g, -1, exec);
      detail::apply_gather<std::uint8_t, 3>(img.cview(), separable.view(), g, 0, exec);
      INFO("N = " << n << " g = [" << g.a << " " << g.b << "; " << g.c << " " << g.d << "]");
      REQUIRE(direct == separable);
      for (index_t y = 0; y < n; ++y)
        for (index_t x = 0; x < n; ++x) {
          const auto sx =
              static_cast<index_t>((g.a * static_cast<detail::u64>(x) + g.b * static_cast<detail::u64>(y)) % un);
          const auto sy =
              static_cast<index_t>((g.c * static_cast<detail::u64>(x) + g.d * static_cast<detail::u64>(y)) % un);
          REQUIRE(direct.read(x, y) == img.read(sx, sy));
        }
    }
  }
  CHECK(three_pass >= 6);
}
