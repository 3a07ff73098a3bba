// Fuzz target "obj": parse_obj; a successful read is a valid mesh that every writer round-trips.
#include <string_view>

#include "mesh_checks.hpp"

TESSERA_FUZZ_TARGET(obj, data, size) {
  auto m = tessera::parse_obj(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.obj");
  if (m.ok()) tessera_fuzz::check_mesh_round_trips(*m);
  return 0;
}
