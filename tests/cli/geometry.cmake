# CLI tests of the geometry family: exemplar -> mesh-quilt, geo-wang build -> geo-wang tile -> render,
# and bad input (exit code 1 with a status message).
set(_geo ${TESSERA_CLI_OUT}/geometry)
file(MAKE_DIRECTORY ${_geo})

add_test(NAME "cli: exemplar rings" COMMAND $<TARGET_FILE:tessera_cli> exemplar rings --size 6.4 --segments 12 --out ${_geo}/rings.obj --stats)
set_tests_properties("cli: exemplar rings" PROPERTIES FIXTURES_SETUP geo_rings
  PASS_REGULAR_EXPRESSION "\"open_edges_inside\":0,\"nonmanifold_edges\":0,\"intersecting_pairs\":0")
add_test(NAME "cli: exemplar weave and stones" COMMAND $<TARGET_FILE:tessera_cli> exemplar weave --size 4 --segments 4 --out ${_geo}/weave.obj)
add_test(NAME "cli: exemplar stones" COMMAND $<TARGET_FILE:tessera_cli> exemplar stones --size 4 --segments 1 --out ${_geo}/stones.ply)

add_test(NAME "cli: mesh-quilt" COMMAND $<TARGET_FILE:tessera_cli> mesh-quilt --exemplar ${_geo}/rings.obj --size 8,6 --out ${_geo}/quilt.obj --stats)
set_tests_properties("cli: mesh-quilt" PROPERTIES FIXTURES_REQUIRED geo_rings
  PASS_REGULAR_EXPRESSION "\"quilt_ms\":.*\"open_edges_inside\":0,\"nonmanifold_edges\":0,\"intersecting_pairs\":0")

add_test(NAME "cli: geo-wang build" COMMAND $<TARGET_FILE:tessera_cli> geo-wang build --exemplar ${_geo}/rings.obj --colors 1,1 --tile 4.8
         --out ${_geo}/tiles --stats)
set_tests_properties("cli: geo-wang build" PROPERTIES FIXTURES_REQUIRED geo_rings FIXTURES_SETUP geo_tiles
  PASS_REGULAR_EXPRESSION "\"build_ms\":.*\"open_edges_inside\":0,\"nonmanifold_edges\":0,\"intersecting_pairs\":0,\"border_mismatch\":0")
add_test(NAME "cli: geo-wang tile" COMMAND $<TARGET_FILE:tessera_cli> geo-wang tile --tiles ${_geo}/tiles --grid 4x3 --out ${_geo}/plane.obj --stats)
set_tests_properties("cli: geo-wang tile" PROPERTIES FIXTURES_REQUIRED geo_tiles FIXTURES_SETUP geo_plane
  PASS_REGULAR_EXPRESSION "\"tiling_ms\":.*\"open_edges_inside\":0,\"nonmanifold_edges\":0,\"intersecting_pairs\":0,\"border_mismatch\":0")
add_test(NAME "cli: render" COMMAND $<TARGET_FILE:tessera_cli> render ${_geo}/plane.obj --out ${_geo}/plane.png --view top --grid 4.8 --image-size 200x150)
set_tests_properties("cli: render" PROPERTIES FIXTURES_REQUIRED geo_plane)

add_test(NAME "cli: geo-wang build rejects zero colours" COMMAND $<TARGET_FILE:tessera_cli> geo-wang build --exemplar ${_geo}/rings.obj
         --colors 0,2 --tile 4.8 --out ${_geo}/bad)
set_tests_properties("cli: geo-wang build rejects zero colours" PROPERTIES FIXTURES_REQUIRED geo_rings WILL_FAIL TRUE)
add_test(NAME "cli: geo-wang tile reports a missing directory" COMMAND $<TARGET_FILE:tessera_cli> geo-wang tile --tiles ${_geo}/nowhere
         --grid 2x2 --out ${_geo}/x.obj)
set_tests_properties("cli: geo-wang tile reports a missing directory" PROPERTIES WILL_FAIL TRUE)
add_test(NAME "cli: mesh-quilt rejects a missing exemplar" COMMAND $<TARGET_FILE:tessera_cli> mesh-quilt --exemplar ${_geo}/none.obj --size 4,4
         --out ${_geo}/x.obj)
set_tests_properties("cli: mesh-quilt rejects a missing exemplar" PROPERTIES WILL_FAIL TRUE)
add_test(NAME "cli: exemplar rejects an unknown kind" COMMAND $<TARGET_FILE:tessera_cli> exemplar bricks --out ${_geo}/x.obj)
set_tests_properties("cli: exemplar rejects an unknown kind" PROPERTIES WILL_FAIL TRUE)
