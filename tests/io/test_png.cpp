#include <tessera/io/png.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <tessera/core/image_view.hpp>
#include <tessera/core/random.hpp>

using tessera::image_buffer;
using tessera::index_t;
using tessera::status_code;

namespace {
std::string out_path(const std::string& name) { return std::string(TESSERA_TEST_OUTPUT_DIR) + "/" + name; }

template <class T, int C>
image_buffer<T, C> noise(index_t w, index_t h, std::uint64_t seed) {
  image_buffer<T, C> b(w, h);
  const tessera::counter_rng rng(seed);
  for (index_t i = 0; i < w * h * C; ++i) {
    if constexpr (std::is_same_v<T, float>)
      b.data()[i] = static_cast<float>(rng.uniform(i));
    else
      b.data()[i] = static_cast<T>(rng.below(std::uint64_t{std::numeric_limits<T>::max()} + 1, i));
  }
  return b;
}

std::vector<unsigned char> encode(const auto& img) { return *tessera::encode_png(img); }

// A PNG assembled by hand from raw (already filtered) scanlines, for the variants tessera's encoder
// never writes: palettes, low bit depths, transparency chunks, interlacing.
std::vector<unsigned char> handmade_png(std::uint32_t w, std::uint32_t h, int depth, int color_type, bool interlaced,
                                        const std::vector<unsigned char>& filtered,
                                        const std::vector<std::pair<std::string, std::vector<unsigned char>>>& extra) {
  using namespace tessera::detail;
  std::vector<unsigned char> file(png_signature, png_signature + 8), ihdr;
  put_be32(ihdr, w);
  put_be32(ihdr, h);
  ihdr.insert(ihdr.end(), {static_cast<unsigned char>(depth), static_cast<unsigned char>(color_type), 0, 0,
                           static_cast<unsigned char>(interlaced ? 1 : 0)});
  put_png_chunk(file, "IHDR", ihdr.data(), ihdr.size());
  for (const auto& [type, data] : extra) put_png_chunk(file, type.c_str(), data.data(), data.size());
  int zlen = 0;
  unsigned char* z =
      stbi_zlib_compress(const_cast<unsigned char*>(filtered.data()), static_cast<int>(filtered.size()), &zlen, 8);
  put_png_chunk(file, "IDAT", z, static_cast<std::size_t>(zlen));
  std::free(z);
  put_png_chunk(file, "IEND", nullptr, 0);
  return file;
}

void fix_crc(std::vector<unsigned char>& png, std::size_t chunk_start) {
  const std::uint32_t len = tessera::detail::get_be32(png.data() + chunk_start);
  const std::uint32_t crc = tessera::detail::png_crc(png.data() + chunk_start + 4, len + 4);
  for (int i = 0; i < 4; ++i) png[chunk_start + 8 + len + i] = static_cast<unsigned char>(crc >> (24 - 8 * i));
}
}  // namespace

TEMPLATE_TEST_CASE("png: lossless round trips for every channel type and count", "[png]", std::uint8_t, std::uint16_t) {
  auto check = [&]<int C>() {
    const auto img = noise<TestType, C>(7, 5, C);
    const std::string path =
        out_path("roundtrip_" + std::to_string(sizeof(TestType)) + "_" + std::to_string(C) + ".png");
    REQUIRE(tessera::write_png(path, img).ok());
    const auto info = tessera::read_png_info(path);
    REQUIRE(info.ok());
    REQUIRE(info->width == 7);
    REQUIRE(info->height == 5);
    REQUIRE(info->channels == C);
    REQUIRE(info->bit_depth == 8 * static_cast<int>(sizeof(TestType)));
    REQUIRE_FALSE(info->palette);
    const auto back = tessera::read_png<TestType, C>(path);
    REQUIRE(back.ok());
    REQUIRE(*back == img);
  };
  check.template operator()<1>();
  check.template operator()<2>();
  check.template operator()<3>();
  check.template operator()<4>();
}

TEST_CASE("png: float images are stored as 16-bit and read back within quantization", "[png]") {
  auto img = noise<float, 3>(9, 4, 3);
  img.data()[0] = -0.5f;  // clamped
  img.data()[1] = 2.0f;
  img.data()[2] = std::numeric_limits<float>::quiet_NaN();  // becomes 0
  const std::string path = out_path("float.png");
  REQUIRE(tessera::write_png(path, img).ok());
  REQUIRE(tessera::read_png_info(path)->bit_depth == 16);
  const auto back = tessera::read_png<float, 3>(path);
  REQUIRE(back.ok());
  REQUIRE(back->data()[0] == 0.0f);
  REQUIRE(back->data()[1] == 1.0f);
  REQUIRE(back->data()[2] == 0.0f);
  for (index_t i = 3; i < 9 * 4 * 3; ++i) REQUIRE(std::abs(back->data()[i] - img.data()[i]) <= 0.5f / 65535 + 1e-7f);
}

TEST_CASE("png: depth and channel conversion on read", "[png]") {
  image_buffer<std::uint8_t, 3> rgb(2, 1);
  rgb.write(0, 0, {200, 100, 50});
  rgb.write(1, 0, {0, 0, 255});
  const auto png8 = encode(rgb);
  // 8-bit read as 16: exact v * 257; alpha added opaque
  const auto wide = tessera::decode_png<std::uint16_t, 4>(png8.data(), png8.size());
  REQUIRE(wide->read(0, 0) == std::array<std::uint16_t, 4>{200 * 257, 100 * 257, 50 * 257, 65535});
  // colour to grey: Rec. 601 luma, as convert_pixel
  const auto grey = tessera::decode_png<std::uint8_t, 1>(png8.data(), png8.size());
  REQUIRE(grey->read(0, 0)[0] == tessera::convert_pixel<std::uint8_t>(rgb.read(0, 0)));
  REQUIRE(grey->read(1, 0)[0] == 29);
  // 16-bit read as 8: rounded to nearest (not truncated)
  image_buffer<std::uint16_t, 1> g16(3, 1);
  g16.write(0, 0, {128});    // 0.498 of a level -> 0
  g16.write(1, 0, {129});    // 0.502 -> 1
  g16.write(2, 0, {65535});  // -> 255
  const auto png16 = encode(g16);
  const auto g8 = tessera::decode_png<std::uint8_t, 1>(png16.data(), png16.size());
  REQUIRE(g8->read(0, 0)[0] == 0);
  REQUIRE(g8->read(1, 0)[0] == 1);
  REQUIRE(g8->read(2, 0)[0] == 255);
}

TEST_CASE("png: any Image can be written, through views and strides", "[png]") {
  std::vector<std::uint8_t> raw = {10, 20, 0, 30, 40, 0};  // 2 x 2 grey with stride 3
  const auto view = *tessera::make_image_view<1>(raw.data(), 2, 2, 3);
  const auto png = encode(view);
  const auto back = tessera::decode_png<std::uint8_t, 1>(png.data(), png.size());
  REQUIRE(back->read(1, 1)[0] == 40);
  REQUIRE(back->read(0, 1)[0] == 30);
}

TEST_CASE("png: palettes, low bit depths, transparency and interlacing decode", "[png]") {
  // 4 x 2 palette image, 2 bits per index, with a tRNS entry making colour 1 half transparent
  const std::vector<unsigned char> plte = {255, 0, 0, 0, 255, 0, 0, 0, 255, 9, 9, 9};
  const std::vector<unsigned char> trns = {255, 128};
  // row 0: indices 0 1 2 3 -> 00 01 10 11 = 0x1b; row 1: 3 2 1 0 -> 0xe4 (filter byte 0 each)
  const auto pal = handmade_png(4, 2, 2, 3, false, {0, 0x1b, 0, 0xe4}, {{"PLTE", plte}, {"tRNS", trns}});
  const auto info = tessera::decode_png_info(pal.data(), pal.size());
  REQUIRE(info->palette);
  REQUIRE(info->file_bit_depth == 2);
  REQUIRE(info->channels == 4);
  const auto img = tessera::decode_png<std::uint8_t, 4>(pal.data(), pal.size());
  REQUIRE(img.ok());
  REQUIRE(img->read(0, 0) == std::array<std::uint8_t, 4>{255, 0, 0, 255});
  REQUIRE(img->read(1, 0) == std::array<std::uint8_t, 4>{0, 255, 0, 128});
  REQUIRE(img->read(3, 0) == std::array<std::uint8_t, 4>{9, 9, 9, 255});
  REQUIRE(img->read(0, 1) == std::array<std::uint8_t, 4>{9, 9, 9, 255});

  // 1-bit grey, 9 pixels wide (a partial last byte): 101010101 -> 0xaa 0x80
  const auto bits = handmade_png(9, 1, 1, 0, false, {0, 0xaa, 0x80}, {});
  const auto b = tessera::decode_png<std::uint8_t, 1>(bits.data(), bits.size());
  REQUIRE(b.ok());
  for (index_t x = 0; x < 9; ++x) REQUIRE(b->read(x, 0)[0] == (x % 2 == 0 ? 255 : 0));

  // Adam7-interlaced 2 x 2 RGB: pass 1 holds (0,0), pass 6 (1,0), pass 7 row 1
  const auto inter = handmade_png(2, 2, 8, 2, true, {0, 1, 2, 3, 0, 4, 5, 6, 0, 7, 8, 9, 10, 11, 12}, {});
  REQUIRE(tessera::decode_png_info(inter.data(), inter.size())->interlaced);
  const auto i = tessera::decode_png<std::uint8_t, 3>(inter.data(), inter.size());
  REQUIRE(i.ok());
  REQUIRE(i->read(0, 0) == std::array<std::uint8_t, 3>{1, 2, 3});
  REQUIRE(i->read(1, 0) == std::array<std::uint8_t, 3>{4, 5, 6});
  REQUIRE(i->read(0, 1) == std::array<std::uint8_t, 3>{7, 8, 9});
  REQUIRE(i->read(1, 1) == std::array<std::uint8_t, 3>{10, 11, 12});
}

TEST_CASE("png: truncation at every offset is a parse error naming the data", "[png]") {
  const auto png = encode(noise<std::uint8_t, 4>(5, 3, 7));
  for (std::size_t n = 0; n < png.size(); ++n) {
    const auto r = tessera::decode_png<std::uint8_t, 4>(png.data(), n, "cut.png");
    REQUIRE_FALSE(r.ok());
    REQUIRE(r.error().code() == status_code::parse_error);
    REQUIRE(r.error().message().rfind("cut.png", 0) == 0);
    REQUIRE(r.error().message().find("byte") != std::string::npos);
    REQUIRE_FALSE(tessera::decode_png_info(png.data(), n, "cut.png").ok());
  }
  // and through real files, at a few offsets
  for (std::size_t n : {std::size_t{0}, std::size_t{5}, std::size_t{20}, png.size() / 2, png.size() - 1}) {
    const std::string path = out_path("truncated.png");
    REQUIRE(tessera::detail::write_file(path, std::string_view(reinterpret_cast<const char*>(png.data()), n)).ok());
    const auto r = tessera::read_png<float, 3>(path);
    REQUIRE(r.error().code() == status_code::parse_error);
    REQUIRE(r.error().message().rfind(path, 0) == 0);
  }
}

TEST_CASE("png: any single flipped byte is detected", "[png]") {
  const auto png = encode(noise<std::uint16_t, 2>(4, 4, 9));
  for (std::size_t i = 0; i < png.size(); ++i)
    for (unsigned char mask : {0x01, 0x80, 0xff}) {
      auto bad = png;
      bad[i] ^= mask;
      const auto r = tessera::decode_png<std::uint16_t, 2>(bad.data(), bad.size(), "flip.png");
      REQUIRE(r.error().code() == status_code::parse_error);
    }
}

TEST_CASE("png: corrupt compressed data with valid checksums never crashes", "[png]") {
  const auto png = encode(noise<std::uint8_t, 3>(6, 5, 11));
  const std::size_t idat = 8 + 25;  // signature, IHDR chunk
  const std::uint32_t len = tessera::detail::get_be32(png.data() + idat);
  int decoded = 0, rejected = 0;
  for (std::size_t i = 0; i < len; ++i) {
    auto bad = png;
    bad[idat + 8 + i] ^= 0x5a;
    fix_crc(bad, idat);
    const auto r = tessera::decode_png<std::uint8_t, 3>(bad.data(), bad.size(), "evil.png");
    if (r.ok())
      ++decoded;
    else {
      ++rejected;
      REQUIRE(r.error().code() == status_code::parse_error);
      REQUIRE(r.error().message().rfind("evil.png", 0) == 0);
    }
  }
  REQUIRE(rejected > 0);  // most corruptions break the zlib stream or its checksum
  REQUIRE(decoded + rejected == static_cast<int>(len));
}

TEST_CASE("png: hostile headers are rejected before decoding", "[png]") {
  auto png = encode(noise<std::uint8_t, 1>(4, 4, 5));
  // claim 100000 x 100000 pixels with a few bytes of data: no 10 GB allocation, a parse error
  for (int i = 0; i < 4; ++i) png[16 + i] = png[20 + i] = static_cast<unsigned char>((100000u >> (24 - 8 * i)) & 0xff);
  fix_crc(png, 8);
  auto r = tessera::decode_png<std::uint8_t, 1>(png.data(), png.size(), "huge.png");
  REQUIRE(r.error().code() == status_code::parse_error);
  REQUIRE(r.error().message().find("declares 100000 x 100000") != std::string::npos);

  // invalid IHDR fields
  auto bad_depth = encode(noise<std::uint8_t, 3>(2, 2, 5));
  bad_depth[24] = 4;  // RGB at 4 bits does not exist
  fix_crc(bad_depth, 8);
  r = tessera::decode_png<std::uint8_t, 1>(bad_depth.data(), bad_depth.size());
  REQUIRE(r.error().message().find("bit depth") != std::string::npos);
  auto zero = encode(noise<std::uint8_t, 3>(2, 2, 5));
  for (int i = 16; i < 20; ++i) zero[static_cast<std::size_t>(i)] = 0;
  fix_crc(zero, 8);
  REQUIRE(tessera::decode_png<std::uint8_t, 1>(zero.data(), zero.size()).error().code() == status_code::parse_error);
}

TEST_CASE("png: files that are missing, empty or not PNG", "[png]") {
  auto missing = tessera::read_png<std::uint8_t, 3>(out_path("does_not_exist.png"));
  REQUIRE(missing.error().code() == status_code::io_error);
  REQUIRE(missing.error().message().find("does_not_exist.png") != std::string::npos);
  REQUIRE(tessera::read_png_info(TESSERA_TEST_OUTPUT_DIR).error().code() == status_code::io_error);  // a directory

  const std::string empty = out_path("empty.png"), text = out_path("text.png");
  REQUIRE(tessera::detail::write_file(empty, "").ok());
  REQUIRE(tessera::detail::write_file(text, "P3 this is not a png file\n").ok());
  REQUIRE(tessera::read_png<std::uint8_t, 3>(empty).error().code() == status_code::parse_error);
  const auto t = tessera::read_png_info(text);
  REQUIRE(t.error().code() == status_code::parse_error);
  REQUIRE(t.error().message().find("not a PNG") != std::string::npos);
}

TEST_CASE("png: write errors", "[png]") {
  const image_buffer<std::uint8_t, 3> img(2, 2);
  const auto s = tessera::write_png(out_path("no_such_dir/x.png"), img);
  REQUIRE(s.code() == status_code::io_error);
  REQUIRE(s.message().find("no_such_dir/x.png") != std::string::npos);
  REQUIRE(tessera::write_png(out_path("empty_image.png"), image_buffer<std::uint8_t, 3>{}).code() ==
          status_code::invalid_argument);
}

TEST_CASE("png: a small valid file inflating to gigabytes stops at the decoded-size limit", "[png][bad_input]") {
  // 32000 x 32000 grey declared over ~1 MB of IDAT: passes the compression-ratio check (deflate can
  // expand ~1000:1, so a real file this small exists), but would decode to 1 GB (4 GB as float).
  // The limit is checked before stb sees the data, so the IDAT bytes need not inflate.
  using namespace tessera::detail;
  std::vector<unsigned char> file(png_signature, png_signature + 8), ihdr;
  put_be32(ihdr, 32000);
  put_be32(ihdr, 32000);
  ihdr.insert(ihdr.end(), {8, 0, 0, 0, 0});
  put_png_chunk(file, "IHDR", ihdr.data(), ihdr.size());
  const std::vector<unsigned char> idat(995 * 1024, 0);
  put_png_chunk(file, "IDAT", idat.data(), idat.size());
  put_png_chunk(file, "IEND", nullptr, 0);
  REQUIRE(tessera::decode_png_info(file.data(), file.size()).ok());  // the structure is fine
  auto r = tessera::decode_png<float, 1>(file.data(), file.size(), "bomb.png");
  REQUIRE(r.error().code() == status_code::size_overflow);
  REQUIRE_THAT(r.error().message(), Catch::StartsWith("bomb.png") && Catch::Contains("32000 x 32000") &&
                                        Catch::Contains("1024000000 pixels") && Catch::Contains("limit"));
  // raising the limits reaches the decoder (which then finds the zeros are not a zlib stream)
  auto raised =
      tessera::decode_png<std::uint8_t, 1>(file.data(), file.size(), "bomb.png",
                                           {.max_pixels = std::uint64_t{1} << 31, .max_bytes = std::uint64_t{1} << 31});
  REQUIRE(raised.error().code() == status_code::parse_error);
}

TEST_CASE("png: the decoded-size limits are options", "[png][bad_input]") {
  const auto png = encode(noise<std::uint8_t, 3>(64, 32, 9));
  REQUIRE(tessera::decode_png<std::uint8_t, 3>(png.data(), png.size()).ok());
  auto few = tessera::decode_png<std::uint8_t, 3>(png.data(), png.size(), "p.png", {.max_pixels = 2047});
  REQUIRE(few.error().code() == status_code::size_overflow);
  REQUIRE_THAT(few.error().message(), Catch::Contains("64 x 32") && Catch::Contains("2047 pixels"));
  REQUIRE(tessera::decode_png<std::uint8_t, 3>(png.data(), png.size(), "p.png", {.max_pixels = 2048}).ok());
  // bytes count the larger of the decoder's buffer (6144) and the output (float RGBA: 32768)
  REQUIRE(tessera::decode_png<std::uint8_t, 3>(png.data(), png.size(), "p.png", {.max_bytes = 6144}).ok());
  REQUIRE(tessera::decode_png<float, 4>(png.data(), png.size(), "p.png", {.max_bytes = 32767}).error().code() ==
          status_code::size_overflow);
  REQUIRE(tessera::decode_png<float, 4>(png.data(), png.size(), "p.png", {.max_bytes = 32768}).ok());
  const std::string path = out_path("limits.png");
  REQUIRE(tessera::write_png(path, noise<std::uint8_t, 3>(64, 32, 9)).ok());
  REQUIRE(tessera::read_png<std::uint8_t, 3>(path, {.max_pixels = 100}).error().code() == status_code::size_overflow);
}

TEST_CASE("png: zero-length IDAT chunks are skipped, not handed to the decoder", "[png][bad_input]") {
  // a zero-length first IDAT is valid PNG; stb would memcpy from its (still null) buffer
  const std::vector<unsigned char> filtered = {0, 10, 20, 30, 0, 40, 50, 60};  // 3 x 2 grey, filter 0
  const auto plain = handmade_png(3, 2, 8, 0, false, filtered, {});
  const auto empty_first = handmade_png(3, 2, 8, 0, false, filtered, {{"IDAT", {}}});
  REQUIRE(empty_first.size() == plain.size() + 12);
  auto a = tessera::decode_png<std::uint8_t, 1>(plain.data(), plain.size());
  auto b = tessera::decode_png<std::uint8_t, 1>(empty_first.data(), empty_first.size(), "empty_idat.png");
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  for (index_t y = 0; y < 2; ++y)
    for (index_t x = 0; x < 3; ++x) REQUIRE(*b->pixel_ptr(x, y) == *a->pixel_ptr(x, y));
  REQUIRE(*b->pixel_ptr(2, 1) == 60);
  // an empty IDAT after the data too, and bytes after IEND
  auto tail = empty_first;
  tail.insert(tail.end(), {1, 2, 3});
  REQUIRE(tessera::decode_png<std::uint8_t, 1>(tail.data(), tail.size()).ok());
  // only empty IDATs: no image data
  std::vector<unsigned char> none(empty_first.begin(), empty_first.begin() + 8 + 25 + 12);
  tessera::detail::put_png_chunk(none, "IEND", nullptr, 0);
  REQUIRE(tessera::decode_png<std::uint8_t, 1>(none.data(), none.size()).error().code() == status_code::parse_error);
}
