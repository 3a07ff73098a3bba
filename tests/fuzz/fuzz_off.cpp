// Fuzz target "off": parse_off; a successful read is a valid mesh that every writer round-trips.
#include <string_view>

#include "mesh_checks.hpp"

TESSERA_FUZZ_TARGET(off, data, size) {
  auto m = tessera::parse_off(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.off");
  if (m.ok()) tessera_fuzz::check_mesh_round_trips(*m);
  return 0;
}
