// Fuzz target "ply": parse_ply (ASCII and both binary encodings: the corpus holds each); a successful read is a valid mesh that every writer round-trips.
#include <string_view>

#include "mesh_checks.hpp"

TESSERA_FUZZ_TARGET(ply, data, size) {
  auto m = tessera::parse_ply(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.ply");
  if (m.ok()) tessera_fuzz::check_mesh_round_trips(*m);
  return 0;
}
