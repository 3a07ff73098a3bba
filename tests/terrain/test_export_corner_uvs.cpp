#include <tessera/terrain/export_corner_uvs.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <tessera/io/terrain_uv_file.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/terrain/build_exemplar_pyramid.hpp>
#include <tessera/terrain/render_terrain_frame.hpp>

#include "terrain_test_scenes.hpp"

using tessera::index_t;

namespace {
std::uint32_t le32(const std::vector<unsigned char>& b, std::size_t at) {
  return static_cast<std::uint32_t>(b[at]) | static_cast<std::uint32_t>(b[at + 1]) << 8 |
         static_cast<std::uint32_t>(b[at + 2]) << 16 | static_cast<std::uint32_t>(b[at + 3]) << 24;
}
float lef32(const std::vector<unsigned char>& b, std::size_t at) {
  const std::uint32_t v = le32(b, at);
  float f;
  std::memcpy(&f, &v, 4);
  return f;
}
}  // namespace

TEST_CASE("terrain uv file: what --uv-out writes reads back and textures every visible face", "[terrain][uv]") {
  // a low view over a coarse terrain: faces under the eye cross the near plane
  const auto mesh = terrain_test::prepared_terrain(6, 1, 6);
  const auto cam = terrain_test::low_camera(64, 40);
  const auto proj = tessera::project_mesh(mesh, cam).value();
  REQUIRE(proj.near_clipped > 0);
  const auto ex =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::sand, {.width = 40, .height = 32}).value();
  const auto pyramid = tessera::build_exemplar_pyramid(ex, {.min_scale = 0.5, .levels = 8}).value();
  const auto field = tessera::assign_scale_field(mesh, proj, {.min_scale = 0.5, .max_levels = 8}).value();
  const auto syn = tessera::synthesize_triangles(mesh, proj, field, 40, 32).value();
  const auto uv = tessera::export_corner_uvs(mesh, proj, field, syn).value();

  const std::string path = (std::filesystem::temp_directory_path() / "tessera_test_terrain_uv.bin").string();
  REQUIRE(tessera::write_terrain_uv_file(path, uv));
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const auto nf = static_cast<std::size_t>(mesh.num_faces());

  // the documented layout, decoded here byte by byte (independently of decode_terrain_uvs)
  REQUIRE(raw.size() == 40 + 44 * nf);
  REQUIRE(std::memcmp(raw.data(), "TSUV", 4) == 0);
  REQUIRE(le32(raw, 4) == 3);
  REQUIRE(le32(raw, 8) == nf);
  REQUIRE(le32(raw, 12) == 64);
  REQUIRE(le32(raw, 16) == 40);
  REQUIRE(le32(raw, 20) == 40);
  REQUIRE(le32(raw, 24) == 32);
  REQUIRE(le32(raw, 28) == static_cast<std::uint32_t>(field.levels));
  REQUIRE(lef32(raw, 32) == 0.5f);
  REQUIRE(le32(raw, 36) == 0);  // screen mapping
  index_t near = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const std::size_t r = 40 + 44 * f;
    const auto state = le32(raw, r + 40);
    const auto level = static_cast<std::int32_t>(le32(raw, r + 32));
    REQUIRE(state == proj.state[f]);
    if (state == 0) {
      REQUIRE(level == -1);
      REQUIRE(lef32(raw, r + 36) == 0.0f);
      REQUIRE(std::isnan(lef32(raw, r + 24)));
      continue;
    }
    REQUIRE(level == field.level[f]);
    REQUIRE(lef32(raw, r + 36) == field.scale[f]);
    REQUIRE(lef32(raw, r + 24) == static_cast<float>(syn.offset[f].x));
    REQUIRE(lef32(raw, r + 28) == static_cast<float>(syn.offset[f].y));
    for (std::size_t k = 0; k < 3; ++k) {
      const tessera::vec2 p = proj.screen[static_cast<std::size_t>(mesh.faces[f][k])];
      const float u = lef32(raw, r + 8 * k), v = lef32(raw, r + 8 * k + 4);
      if (std::isnan(p.x)) {  // behind the eye: no screen position, so no corner coordinate
        REQUIRE(state == 2);
        REQUIRE(std::isnan(u));
        continue;
      }
      REQUIRE(u == static_cast<float>(p.x + syn.offset[f].x));
      REQUIRE(v == static_cast<float>(p.y + syn.offset[f].y));
    }
    near += state == 2 ? 1 : 0;
  }
  REQUIRE(near == proj.near_clipped);

  // the reader gives back what was written
  const auto back = tessera::read_terrain_uv_file(path).value();
  REQUIRE(back.level == uv.level);
  REQUIRE(back.scale == uv.scale);
  REQUIRE(back.state == uv.state);
  REQUIRE(back.viewport_width == 64);
  REQUIRE(back.exemplar_height == 32);
  for (std::size_t f = 0; f < nf; ++f)
    if (uv.state[f] != 0) REQUIRE(back.offset[f] == uv.offset[f]);

  // an engine texturing each pixel from the file alone (uv = pixel centre + offset, sampled in the
  // exemplar shrunk by scale) reproduces the frame, near-clipped faces included
  tessera::image_buffer<float, 3> frame(64, 40);
  REQUIRE(tessera::render_terrain_frame(mesh, proj, field, syn, pyramid, frame, {.feather = 0}));
  tessera::detail::visibility_buffer vb;
  tessera::serial_executor serial;
  REQUIRE(tessera::detail::render_visibility(mesh, proj, vb, false, 64, serial));
  index_t on_near = 0;
  for (index_t y = 0; y < 40; ++y)
    for (index_t x = 0; x < 64; ++x) {
      const std::int32_t f = vb.face[static_cast<std::size_t>(y * 64 + x)];
      if (f < 0) continue;
      const auto fi = static_cast<std::size_t>(f);
      const double s = back.scale[fi];
      const double u = static_cast<double>(x) + 0.5 + back.offset[fi][0],
                   v = static_cast<double>(y) + 0.5 + back.offset[fi][1];
      const auto c = pyramid.sample(s, u + 0.5 * static_cast<double>(back.exemplar_width) * s,
                                    v + 0.5 * static_cast<double>(back.exemplar_height) * s);
      for (std::size_t k = 0; k < 3; ++k) REQUIRE(frame.read(x, y)[k] == Approx(c[k]).margin(1e-4));
      on_near += back.state[fi] == 2 ? 1 : 0;
    }
  REQUIRE(on_near > 0);

  // damaged files are refused with a reason
  std::vector<unsigned char> bad = raw;
  bad.pop_back();
  REQUIRE(tessera::decode_terrain_uvs(bad.data(), bad.size()).error().message().find("do not hold") !=
          std::string::npos);
  bad = raw;
  bad[4] = 1;
  REQUIRE(tessera::decode_terrain_uvs(bad.data(), bad.size()).error().message().find("version 1") != std::string::npos);
  bad[0] = 'X';
  REQUIRE(tessera::decode_terrain_uvs(bad.data(), bad.size()).error().message().find("TSUV") != std::string::npos);
  REQUIRE_FALSE(tessera::decode_terrain_uvs(bad.data(), 3));
  bad = raw;
  bad[36] = 7;
  REQUIRE(tessera::decode_terrain_uvs(bad.data(), bad.size()).error().message().find("mapping 7") != std::string::npos);
  // a version 2 file (no mapping field) still reads, as screen mapping
  std::vector<unsigned char> v2(raw.begin(), raw.begin() + 36);
  v2[4] = 2;
  v2.insert(v2.end(), raw.begin() + 40, raw.end());
  const auto old = tessera::decode_terrain_uvs(v2.data(), v2.size());
  REQUIRE(old);
  REQUIRE(old->mapping == 0);
  REQUIRE(old->level == back.level);
  REQUIRE(tessera::read_terrain_uv_file(path + ".missing").error().code() == tessera::status_code::io_error);
  tessera::terrain_uv_buffer uneven = uv;
  uneven.state.pop_back();
  REQUIRE(tessera::write_terrain_uv_file(path, uneven).message().find("different lengths") != std::string::npos);
  std::remove(path.c_str());
}
