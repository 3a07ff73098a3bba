# CLI tests of the surface family: tessera polycube on small procedural meshes (tests/data/surface),
# its outputs (deformed mesh, labels, quads, base) feeding a second run, and bad input (exit code 1
# with the status message).
set(_pc ${TESSERA_CLI_OUT}/surface)
file(MAKE_DIRECTORY ${_pc})
set(_pcdata ${PROJECT_SOURCE_DIR}/tests/data/surface)

tessera_cli_test(NAME "cli: polycube torus"
                 REGEX "\"polycube_ms\":[0-9.e+-]+,\"faces\":768,\"genus\":1,.*\"charts\":[1-9][0-9]*,\"corners\":[1-9][0-9]*,\"quads\":[1-9][0-9]*,\"flipped_faces\":0,\"area_distortion\":[0-9.e+-]+,\"angle_distortion\":[0-9.e+-]+,\"refined\":false,\"valid\":true"
                 COMMAND polycube --mesh ${_pcdata}/torus.obj --out ${_pc}/torus_pc.obj --tiles-across 8 --threads 2 --stats)
tessera_cli_test(NAME "cli: polycube L outputs" REGEX "wrote .*l_pc\\.obj \\(8 charts, 56 quads\\)"
                 COMMAND polycube --mesh ${_pcdata}/l_shape.off --out ${_pc}/l_pc.obj --tile 0.5 --labels-out ${_pc}/l.labels
                         --quads-out ${_pc}/l_quads.obj --base-out ${_pc}/l_base.obj --map-out ${_pc}/l.polycube)
set_tests_properties("cli: polycube L outputs" PROPERTIES FIXTURES_SETUP pc_labels)
tessera_cli_test(NAME "cli: polycube labels-in" REGEX "\"charts\":8,\"corners\":[0-9]+,\"quads\":56,.*\"valid\":true"
                 COMMAND polycube --mesh ${_pcdata}/l_shape.off --labels-in ${_pc}/l.labels --out ${_pc}/l_pc2.obj --tile 0.5 --stats)
set_tests_properties("cli: polycube labels-in" PROPERTIES FIXTURES_REQUIRED pc_labels)
tessera_cli_test(NAME "cli: polycube labels of another mesh" CODE 1 REGEX "labels for 768 faces"
                 COMMAND polycube --mesh ${_pcdata}/torus.obj --labels-in ${_pc}/l.labels --out ${_pc}/never.obj)
set_tests_properties("cli: polycube labels of another mesh" PROPERTIES FIXTURES_REQUIRED pc_labels)

# the labels drawn on the base mesh they belong to (tessera render --labels)
tessera_cli_test(NAME "cli: render polycube labels" REGEX "wrote .*l_labels\\.png"
                 COMMAND render --in ${_pc}/l_base.obj --labels ${_pc}/l.labels --out ${_pc}/l_labels.png --size 160x120)
set_tests_properties("cli: render polycube labels" PROPERTIES FIXTURES_REQUIRED pc_labels)
tessera_cli_test(NAME "cli: render labels of another mesh" CODE 1 REGEX "--labels: [0-9]+ labels for 768 faces"
                 COMMAND render --in ${_pcdata}/torus.obj --labels ${_pc}/l.labels --out ${_pc}/never.png)
set_tests_properties("cli: render labels of another mesh" PROPERTIES FIXTURES_REQUIRED pc_labels)
tessera_cli_test(NAME "cli: render labels file missing" CODE 1 REGEX "no_such\\.labels"
                 COMMAND render --in ${_pcdata}/torus.obj --labels ${_pc}/no_such.labels --out ${_pc}/never.png)

# tessera remesh: the CAD plate's slivers become even triangles (its creases kept), then its polycube;
# the result drawn with its triangles
tessera_cli_test(NAME "cli: remesh CAD plate"
                 REGEX "\"remesh_ms\":[0-9.e+-]+,\"faces_in\":664,\"faces\":[1-9][0-9]+,\"edge_length\":0\\.9375,\"feature_edges\":[1-9][0-9]*,.*\"min_angle\":(1[5-9]|[2-5][0-9])[0-9.e+-]*,"
                 COMMAND remesh ${_pcdata}/openscad_plate_three_holes.off --out ${_pc}/plate_rm.obj --stats)
set_tests_properties("cli: remesh CAD plate" PROPERTIES FIXTURES_SETUP remesh_plate)
tessera_cli_test(NAME "cli: polycube of the remeshed plate" REGEX "\"genus\":3,.*\"refined\":false,\"valid\":true"
                 COMMAND polycube --in ${_pc}/plate_rm.obj --out ${_pc}/plate_rm_pc.obj --tiles-across 8 --threads 2 --stats)
tessera_cli_test(NAME "cli: render --wire" REGEX "wrote .*plate_rm\\.png"
                 COMMAND render --in ${_pc}/plate_rm.obj --wire --out ${_pc}/plate_rm.png --size 160x120)
set_tests_properties("cli: polycube of the remeshed plate" "cli: render --wire" PROPERTIES FIXTURES_REQUIRED remesh_plate)
tessera_cli_test(NAME "cli: remesh open mesh" CODE 1 REGEX "remesh: mesh: is not closed"
                 COMMAND remesh --in ${_pcdata}/open_cube.obj --out ${_pc}/never.obj)
tessera_cli_test(NAME "cli: remesh edge and edges-across" CODE 1 REGEX "not both"
                 COMMAND remesh --in ${_pcdata}/torus.obj --out ${_pc}/never.obj --edge 0.1 --edges-across 8)
tessera_cli_test(NAME "cli: remesh edge too short" CODE 1 REGEX "would need about .* faces, more than max_faces"
                 COMMAND remesh --in ${_pcdata}/torus.obj --out ${_pc}/never.obj --edge 1e-6)
tessera_cli_test(NAME "cli: remesh feature angle out of range" CODE 1 REGEX "--feature-angle expects"
                 COMMAND remesh --in ${_pcdata}/torus.obj --out ${_pc}/never.obj --feature-angle 200)

tessera_cli_test(NAME "cli: polycube open mesh" CODE 1 REGEX "not closed"
                 COMMAND polycube --mesh ${_pcdata}/open_cube.obj --out ${_pc}/never.obj)
tessera_cli_test(NAME "cli: polycube tile too large" CODE 1 REGEX "larger than the mesh"
                 COMMAND polycube --mesh ${_pcdata}/torus.obj --out ${_pc}/never.obj --tile 100)
tessera_cli_test(NAME "cli: polycube negative tile" CODE 1 REGEX "--tile expects"
                 COMMAND polycube --mesh ${_pcdata}/torus.obj --out ${_pc}/never.obj --tile -1)
tessera_cli_test(NAME "cli: polycube tile and tiles-across" CODE 1 REGEX "not both"
                 COMMAND polycube --mesh ${_pcdata}/torus.obj --out ${_pc}/never.obj --tile 1 --tiles-across 3)
tessera_cli_test(NAME "cli: polycube distortion retries"
                 REGEX "\"quads\":[1-9][0-9]*,\"flipped_faces\":0,.*\"valid\":true"
                 COMMAND polycube --mesh ${_pcdata}/torus.obj --out ${_pc}/torus_pc_best.obj --tiles-across 8 --distortion-retries 2 --stats)
tessera_cli_test(NAME "cli: polycube distortion retries out of range" CODE 1 REGEX "--distortion-retries"
                 COMMAND polycube --mesh ${_pcdata}/torus.obj --out ${_pc}/never.obj --distortion-retries 9)
tessera_cli_test(NAME "cli: polycube missing mesh" CODE 1 REGEX "missing required option --in"
                 COMMAND polycube --out ${_pc}/never.obj)

# geo-wang map (paper 000 §4): the one-colour three-axis ring set of geometry.cmake on the torus, through
# a polycube built here or read back (the deformed mesh of "cli: polycube torus", its grid inferred);
# closed elements (no open edge), every vertex within the shell (max_offset <= 1); bad input.
set(_map_stats "\"map_ms\":[0-9.e+-]+,\"height\":[0-9.e+-]+,\"height_lowered\":0,\"quads\":[1-9][0-9]*,\"tiles_used\":[1-9][0-9]*,\"vertices\":[1-9][0-9]*,\"faces\":[1-9][0-9]*,\"elements\":[1-9][0-9]*,\"open_edges\":0,\"shell_repairs\":[0-9]+,\"max_offset\":(0\\.[0-9e+-]+|1),")
tessera_cli_test(NAME "cli: geo-wang map torus" REGEX "${_map_stats}.*\"refined\":false"
                 COMMAND geo-wang map --tiles ${TESSERA_CLI_OUT}/geometry/tiles3 --mesh ${_pcdata}/torus.obj
                         --out ${_pc}/torus_rings.obj --tiles-across 6 --seed 3 --threads 2 --stats)
set_tests_properties("cli: geo-wang map torus" PROPERTIES FIXTURES_REQUIRED geo_tiles3)
tessera_cli_test(NAME "cli: geo-wang map with a polycube" REGEX "${_map_stats}"
                 COMMAND geo-wang map --tiles ${TESSERA_CLI_OUT}/geometry/tiles3 --mesh ${_pcdata}/torus.obj
                         --polycube ${_pc}/torus_pc.obj --height 0.05 --with-base --out ${_pc}/torus_rings_pc.obj --stats)
set_tests_properties("cli: geo-wang map with a polycube" PROPERTIES FIXTURES_REQUIRED "geo_tiles3;pc_torus")
set_tests_properties("cli: polycube torus" PROPERTIES FIXTURES_SETUP pc_torus)
tessera_cli_test(NAME "cli: geo-wang map exact clip" REGEX "${_map_stats}"
                 COMMAND geo-wang map --tiles ${TESSERA_CLI_OUT}/geometry/tiles3 --mesh ${_pcdata}/torus.obj
                         --out ${_pc}/torus_rings_exact.obj --tiles-across 6 --seed 3 --clip exact --stats)
set_tests_properties("cli: geo-wang map exact clip" PROPERTIES FIXTURES_REQUIRED geo_tiles3)
tessera_cli_test(NAME "cli: geo-wang map bad clip" CODE 1 REGEX "--clip expects exact or midpoint"
                 COMMAND geo-wang map --tiles ${TESSERA_CLI_OUT}/geometry/tiles3 --mesh ${_pcdata}/torus.obj
                         --out ${_pc}/never.obj --clip fast)
set_tests_properties("cli: geo-wang map bad clip" PROPERTIES FIXTURES_REQUIRED geo_tiles3)
# --boolean (paper 000 Fig. 7): the exactly clipped rings (no crossing faces) sunk into the torus and
# joined with it / engraved into it by CGAL's corefinement, when the command was built with CGAL
if(TESSERA_HAS_CGAL)
  foreach(_op union difference)
    tessera_cli_test(NAME "cli: geo-wang map boolean ${_op}"
                     REGEX "${_map_stats}.*\"sink\":0\.[15],\"boolean_ms\":[0-9.e+-]+,\"boolean_faces\":[1-9][0-9]*"
                     COMMAND geo-wang map --tiles ${TESSERA_CLI_OUT}/geometry/tiles3 --mesh ${_pcdata}/torus.obj
                             --out ${_pc}/torus_rings_${_op}.obj --tiles-across 6 --seed 3 --clip exact --boolean ${_op}
                             --threads 2 --stats)
    set_tests_properties("cli: geo-wang map boolean ${_op}" PROPERTIES FIXTURES_REQUIRED geo_tiles3)
  endforeach()
  tessera_cli_test(NAME "cli: geo-wang map boolean and with-base" CODE 1 REGEX "give --with-base or --boolean"
                   COMMAND geo-wang map --tiles ${TESSERA_CLI_OUT}/geometry/tiles3 --mesh ${_pcdata}/torus.obj
                           --out ${_pc}/never.obj --boolean union --with-base)
else()
  tessera_cli_test(NAME "cli: geo-wang map boolean without CGAL" CODE 1 REGEX "built without CGAL"
                   COMMAND geo-wang map --tiles ${TESSERA_CLI_OUT}/geometry/tiles3 --mesh ${_pcdata}/torus.obj
                           --out ${_pc}/never.obj --boolean union)
endif()
tessera_cli_test(NAME "cli: geo-wang map bad boolean" CODE 1 REGEX "--boolean expects union, difference or intersection"
                 COMMAND geo-wang map --tiles ${TESSERA_CLI_OUT}/geometry/tiles3 --mesh ${_pcdata}/torus.obj
                         --out ${_pc}/never.obj --boolean xor)
tessera_cli_test(NAME "cli: geo-wang map bad sink" CODE 1 REGEX "--sink expects a number in \\[0, 0.95\\]"
                 COMMAND geo-wang map --tiles ${TESSERA_CLI_OUT}/geometry/tiles3 --mesh ${_pcdata}/torus.obj
                         --out ${_pc}/never.obj --sink 1)
tessera_cli_test(NAME "cli: geo-wang map planar set" CODE 1 REGEX "planar set"
                 COMMAND geo-wang map --tiles ${TESSERA_CLI_OUT}/geometry/tiles --mesh ${_pcdata}/torus.obj
                         --out ${_pc}/never.obj)
set_tests_properties("cli: geo-wang map planar set" PROPERTIES FIXTURES_REQUIRED geo_tiles)
tessera_cli_test(NAME "cli: geo-wang map open mesh" CODE 1 REGEX "not closed"
                 COMMAND geo-wang map --tiles ${TESSERA_CLI_OUT}/geometry/tiles3 --mesh ${_pcdata}/open_cube.obj
                         --out ${_pc}/never.obj)
set_tests_properties("cli: geo-wang map open mesh" PROPERTIES FIXTURES_REQUIRED geo_tiles3)
tessera_cli_test(NAME "cli: geo-wang map bad height" CODE 1 REGEX "--height expects"
                 COMMAND geo-wang map --tiles ${TESSERA_CLI_OUT}/geometry/tiles3 --mesh ${_pcdata}/torus.obj
                         --out ${_pc}/never.obj --height -1)
