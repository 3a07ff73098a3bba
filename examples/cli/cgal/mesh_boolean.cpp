// cli::mesh_boolean (mesh_boolean.hpp): tessera::mesh_boolean through CGAL when built with it.
#include "../mesh_boolean.hpp"

#if defined(TESSERA_HAS_CGAL) && TESSERA_HAS_CGAL
#include <tessera/adapters/cgal_boolean.hpp>
#endif

namespace cli {
#if defined(TESSERA_HAS_CGAL) && TESSERA_HAS_CGAL
bool has_mesh_boolean() { return true; }
tessera::result<tessera::tri_mesh> mesh_boolean(const tessera::tri_mesh& a, const tessera::tri_mesh& b,
                                                std::string_view op, const tessera::progress& progress) {
  using tessera::boolean_op;
  if (op != "union" && op != "difference" && op != "intersection")
    return tessera::status::invalid_argument("a Boolean is union, difference or intersection");
  const boolean_op o = op == "union"        ? boolean_op::unite
                       : op == "difference" ? boolean_op::subtract
                                            : boolean_op::intersect;
  return tessera::mesh_boolean(a, b, o, {.progress = progress});
}
#else
bool has_mesh_boolean() { return false; }
tessera::result<tessera::tri_mesh> mesh_boolean(const tessera::tri_mesh&, const tessera::tri_mesh&, std::string_view,
                                                const tessera::progress&) {
  return tessera::status::unsupported(
      "this tessera command was built without CGAL, which computes the Booleans: install libcgal-dev and "
      "reconfigure with -DTESSERA_WITH_CGAL=ON (the command is then GPL: CGAL's licence)");
}
#endif
}  // namespace cli
