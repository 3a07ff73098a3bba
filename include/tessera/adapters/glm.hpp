// tessera/adapters/glm.hpp: GLM vectors through tessera's concepts.
//
//   pixel_traits<glm::vec<C, T, Q>>   glm vectors as pixels: glm::u8vec4 (RGBA8), glm::u16vec1,
//                                     glm::vec3 (float RGB), ... (C in 1..4; T uint8, uint16, float)
//   glm vectors as positions and uvs need nothing here: core/mesh.hpp's point_traits reads p[i]
//   and knows glm's length(), so a glm::vec2 position is (x, y, 0)
//
// With these, an engine's own image whose read() returns glm::u8vec4, or a mesh whose position()
// returns glm::vec3, models Image / Mesh directly (see examples/08_glm.cpp). Only the glm forward
// declarations are included; include the glm vector headers you use as usual.
#pragma once

#include <glm/fwd.hpp>

#include <type_traits>

#include "../core/config.hpp"
#include "../core/image.hpp"

TESSERA_NAMESPACE_BEGIN

/// glm vectors as pixels: C channels of T. The Pixel concept accepts C in 1..4 and T in uint8,
/// uint16, float; glm::dvec3 or glm::ivec4 are known here but do not model Pixel, so
/// explain_image() names the problem.
template <glm::length_t C, class T, glm::qualifier Q>
requires std::is_arithmetic_v<T>
struct pixel_traits<glm::vec<C, T, Q>> {
  using channel_type = T;
  static constexpr int channels = static_cast<int>(C);
  static constexpr T get(const glm::vec<C, T, Q>& p, int c) noexcept { return p[static_cast<glm::length_t>(c)]; }
  static constexpr void set(glm::vec<C, T, Q>& p, int c, T v) noexcept { p[static_cast<glm::length_t>(c)] = v; }
};

TESSERA_NAMESPACE_END
