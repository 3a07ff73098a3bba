#include <tessera/io/patch_model_file.hpp>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <tessera/core/random.hpp>
#include <tessera/image/patch_synthesis.hpp>

namespace {

template <class T, int C>
tessera::image_buffer<T, C> noise_image(tessera::index_t w, tessera::index_t h, std::uint64_t seed) {
  tessera::image_buffer<T, C> img(w, h);
  tessera::counter_rng rng(seed, 1);
  std::uint64_t i = 0;
  for (tessera::index_t y = 0; y < h; ++y)
    for (tessera::index_t x = 0; x < w; ++x) {
      tessera::pixel<T, C> p{};
      for (int c = 0; c < C; ++c) {
        const double u = rng.uniform(i++);
        if constexpr (std::is_same_v<T, float>)
          p[static_cast<std::size_t>(c)] = static_cast<float>(u);
        else
          p[static_cast<std::size_t>(c)] = static_cast<T>(u * 255);
      }
      img.write(x, y, p);
    }
  return img;
}

template <class T, int C>
void check_round_trip(const tessera::patch_model_options& o) {
  const auto ex = noise_image<T, C>(24, 20, 5);
  auto model = tessera::build_patch_model(ex, o);
  REQUIRE(model.ok());
  auto bytes = tessera::encode_patch_model(*model, o);
  REQUIRE(bytes.ok());
  auto fmt = tessera::patch_model_file_format(bytes->data(), bytes->size());
  REQUIRE(fmt.ok());
  CHECK(fmt->type == tessera::channel_type_of<T>);
  CHECK(fmt->channels == C);
  auto back = tessera::decode_patch_model<T, C>(bytes->data(), bytes->size());
  REQUIRE(back.ok());
  CHECK(back->model.patch_width() == model->patch_width());
  CHECK(back->model.overlap() == model->overlap());
  CHECK(back->model.has_seams() == model->has_seams());
  CHECK(back->model.exemplar() == model->exemplar());
  for (tessera::index_t p = 0; p < model->num_patches(); ++p)
    for (int s = 0; s < 4; ++s) {
      const auto a = model->compatible(p, s), b = back->model.compatible(p, s);
      REQUIRE(std::equal(a.begin(), a.end(), b.begin(), b.end()));
    }
  tessera::image_buffer<T, C> x(40, 30), y(40, 30);
  const tessera::patch_synthesis_options so{.origin = {-7, 3}, .seed = 9};
  REQUIRE(tessera::synthesize(*model, x, so).ok());
  REQUIRE(tessera::synthesize(back->model, y, so).ok());
  CHECK(x == y);
  // encoding the decoded model gives the same bytes
  auto again = tessera::encode_patch_model(back->model, back->options);
  REQUIRE(again.ok());
  CHECK(*again == *bytes);
}

}  // namespace

TEST_CASE("patch_model_file: round trip keeps the sets and the synthesis", "[io][patch_model_file]") {
  check_round_trip<std::uint8_t, 3>({.patch_width = 6, .patch_height = 5, .overlap = 2});
  check_round_trip<std::uint16_t, 1>({.patch_width = 6, .patch_height = 6, .overlap = 3, .candidates = 4});
  check_round_trip<float, 4>({.patch_width = 5, .patch_height = 5, .overlap = 2, .seams = true});
}

TEST_CASE("patch_model_file: bad bytes are statuses naming what is wrong", "[io][patch_model_file]") {
  const auto ex = noise_image<std::uint8_t, 3>(24, 20, 2);
  const tessera::patch_model_options o{.patch_width = 6, .patch_height = 6, .overlap = 2};
  auto model = tessera::build_patch_model(ex, o);
  REQUIRE(model.ok());
  const std::vector<unsigned char> good = *tessera::encode_patch_model(*model, o);
  auto decode = [](const std::vector<unsigned char>& b) {
    return tessera::decode_patch_model<std::uint8_t, 3>(b.data(), b.size());
  };
  REQUIRE(decode(good).ok());

  CHECK(decode({}).error().code() == tessera::status_code::parse_error);
  CHECK(tessera::decode_patch_model<std::uint8_t, 3>(nullptr, 0).error().message().find("too short") !=
        std::string::npos);
  auto bad_magic = good;
  bad_magic[0] = 'X';
  CHECK(decode(bad_magic).error().message().find("magic") != std::string::npos);
  auto other_version = good;
  other_version[8] = 7;
  const auto v = decode(other_version).error();
  CHECK(v.code() == tessera::status_code::unsupported);
  CHECK(v.message().find("version 7") != std::string::npos);
  for (std::size_t cut : {good.size() - 1, good.size() / 2, std::size_t{20}}) {
    const std::vector<unsigned char> truncated(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(cut));
    CHECK(decode(truncated).error().code() == tessera::status_code::parse_error);
  }
  auto flipped = good;
  flipped[100] ^= 1;
  CHECK(decode(flipped).error().message().find("checksum") != std::string::npos);
  // wrong format for the decoder
  auto as_grey = tessera::decode_patch_model<std::uint8_t, 1>(good.data(), good.size());
  CHECK(as_grey.error().message().find("holds uint8 x 3") != std::string::npos);
  // a header field out of range, with a valid checksum: reported as the field, not as a checksum
  auto refix = [](std::vector<unsigned char> b) {
    const std::uint64_t h = tessera::detail::fnv1a64(b.data(), b.size() - 8);
    for (int i = 0; i < 8; ++i)
      b[b.size() - 8 + static_cast<std::size_t>(i)] = static_cast<unsigned char>(h >> (8 * i));
    return b;
  };
  auto huge = good;
  huge[66 + 7] = 0x7f;  // the exemplar width (bytes 66-73) gets a huge most significant byte
  CHECK(decode(refix(huge)).error().message().find("exemplar size") != std::string::npos);
  auto channels = good;
  channels[13] = 9;
  CHECK(decode(refix(channels)).error().message().find("channel count 9") != std::string::npos);
  auto bad_patch = good;
  bad_patch[16] = 1;  // patch_width 1
  CHECK(decode(refix(bad_patch)).error().message().find("is invalid") != std::string::npos);
  // an empty model cannot be encoded
  CHECK(tessera::encode_patch_model(tessera::patch_model<std::uint8_t, 3>{}, o).error().code() ==
        tessera::status_code::invalid_argument);
}

TEST_CASE("patch_model_file: files", "[io][patch_model_file]") {
  const auto ex = noise_image<std::uint8_t, 1>(20, 20, 3);
  const tessera::patch_model_options o{.patch_width = 5, .patch_height = 5, .overlap = 2};
  auto model = tessera::build_patch_model(ex, o);
  REQUIRE(model.ok());
  const std::string path = std::string(P_tmpdir) + "/tessera_test_model.tspm";
  REQUIRE(tessera::save_patch_model(path, *model, o).ok());
  auto back = tessera::load_patch_model<std::uint8_t, 1>(path);
  REQUIRE(back.ok());
  CHECK(back->model.exemplar() == ex);
  std::remove(path.c_str());
  auto missing = tessera::load_patch_model<std::uint8_t, 1>(path);
  CHECK(missing.error().code() == tessera::status_code::io_error);
}
