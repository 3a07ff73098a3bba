# CLI tests of the geometry family: exemplar -> mesh-quilt, geo-wang build -> geo-wang tile -> render,
# and bad input (exit code 1 with the status message). Every test checks the exit code and the output
# (tessera_cli_test, tests/cli/README.md).
set(_geo ${TESSERA_CLI_OUT}/geometry)
file(MAKE_DIRECTORY ${_geo})
set(_clean "\"open_edges_inside\":0,\"nonmanifold_edges\":0,\"intersecting_pairs\":0")

tessera_cli_test(NAME "cli: exemplar rings" REGEX "\"kind\":\"rings\".*\"elements\":[1-9][0-9]*,${_clean}"
                 COMMAND exemplar rings --size 6.4 --segments 12 --out ${_geo}/rings.obj --stats)
set_tests_properties("cli: exemplar rings" PROPERTIES FIXTURES_SETUP geo_rings)
tessera_cli_test(NAME "cli: exemplar weave" REGEX "\"kind\":\"weave\".*\"elements\":[1-9][0-9]*,${_clean}"
                 COMMAND exemplar weave --size 4 --segments 4 --out ${_geo}/weave.obj --stats)
tessera_cli_test(NAME "cli: exemplar stones" REGEX "wrote .*stones\\.ply \\([1-9][0-9]* vertices, [1-9][0-9]* faces\\)"
                 COMMAND exemplar stones --size 4 --segments 1 --out ${_geo}/stones.ply)
tessera_cli_test(NAME "cli: exemplar chain mail" REGEX "\"kind\":\"rings\".*${_clean}"
                 COMMAND exemplar rings --chain-mail --size 4 --segments 12 --out ${_geo}/mail.obj --stats)

tessera_cli_test(NAME "cli: mesh-quilt"
                 REGEX "\"quilt_ms\":.*\"merges_attempted\":[0-9]+,\"merges_succeeded\":[0-9]+,.*\"icp_iterations\":[1-9][0-9]*,.*${_clean}"
                 COMMAND mesh-quilt --exemplar ${_geo}/rings.obj --size 8,6 --out ${_geo}/quilt.obj --stats)
set_tests_properties("cli: mesh-quilt" PROPERTIES FIXTURES_REQUIRED geo_rings)

tessera_cli_test(NAME "cli: geo-wang build"
                 REGEX "\"build_ms\":.*\"tile_size\":4.8,.*\"frame_merges_attempted\":[0-9]+,\"frame_merged\":[0-9]+,\"frame_dropped\":[0-9]+,.*${_clean},\"corner_crossings\":0,\"border_mismatch\":0"
                 COMMAND geo-wang build --exemplar ${_geo}/rings.obj --colors 1,1 --tile 4.8 --out ${_geo}/tiles --stats)
set_tests_properties("cli: geo-wang build" PROPERTIES FIXTURES_REQUIRED geo_rings FIXTURES_SETUP geo_tiles)
tessera_cli_test(NAME "cli: geo-wang tile" REGEX "\"tiling_ms\":.*\"tiles\":12,.*${_clean},\"corner_crossings\":0,\"border_mismatch\":0"
                 COMMAND geo-wang tile --tiles ${_geo}/tiles --grid 4x3 --out ${_geo}/plane.obj --stats)
set_tests_properties("cli: geo-wang tile" PROPERTIES FIXTURES_REQUIRED geo_tiles FIXTURES_SETUP geo_plane)
tessera_cli_test(NAME "cli: render" REGEX "\"render_ms\":[0-9.e+-]+,\"faces\":[1-9][0-9]*,\"width\":200,\"height\":150"
                 COMMAND render ${_geo}/plane.obj --out ${_geo}/plane.png --view top --grid 4.8 --image-size 200x150 --stats)
set_tests_properties("cli: render" PROPERTIES FIXTURES_REQUIRED geo_plane)
tessera_cli_test(NAME "cli: render without stats" REGEX "wrote .*plane_oblique\\.png"
                 COMMAND render ${_geo}/plane.obj --out ${_geo}/plane_oblique.png --image-size 120x90)
set_tests_properties("cli: render without stats" PROPERTIES FIXTURES_REQUIRED geo_plane)

# three-axis sets (paper 000 §3.1, §5): six tiles for one colour per axis, borders identical per axis
# and colour; a plane of the tiles of one face
tessera_cli_test(NAME "cli: geo-wang build three-axis"
                 REGEX "\"tiles\":6,\"three_axis\":true,.*${_clean},\"corner_crossings\":0,\"border_mismatch\":0"
                 COMMAND geo-wang build --exemplar ${_geo}/rings.obj --colors 1,1,1 --tile 4.8 --out ${_geo}/tiles3 --stats)
set_tests_properties("cli: geo-wang build three-axis" PROPERTIES FIXTURES_REQUIRED geo_rings FIXTURES_SETUP geo_tiles3)
tessera_cli_test(NAME "cli: geo-wang tile one face of a three-axis set"
                 REGEX "\"tiling_ms\":.*\"tiles\":6,.*${_clean},\"corner_crossings\":0,\"border_mismatch\":0"
                 COMMAND geo-wang tile --tiles ${_geo}/tiles3 --face -X --grid 3x2 --out ${_geo}/plane3.obj --stats)
set_tests_properties("cli: geo-wang tile one face of a three-axis set" PROPERTIES FIXTURES_REQUIRED geo_tiles3)
tessera_cli_test(NAME "cli: geo-wang build rejects four colour counts" CODE 1
                 REGEX "--colors expects two integers NH,NV or three NX,NY,NZ in \\[1, 4096\\], got '2,2,2,2'"
                 COMMAND geo-wang build --exemplar ${_geo}/rings.obj --colors 2,2,2,2 --tile 4.8 --out ${_geo}/bad)
set_tests_properties("cli: geo-wang build rejects four colour counts" PROPERTIES FIXTURES_REQUIRED geo_rings)

# bad input: exit code 1 and the message naming the parameter and the value
tessera_cli_test(NAME "cli: geo-wang build rejects zero colours" CODE 1 REGEX "--colors expects two integers NH,NV or three NX,NY,NZ in \\[1, 4096\\], got '0,2'"
                 COMMAND geo-wang build --exemplar ${_geo}/rings.obj --colors 0,2 --tile 4.8 --out ${_geo}/bad)
set_tests_properties("cli: geo-wang build rejects zero colours" PROPERTIES FIXTURES_REQUIRED geo_rings)
tessera_cli_test(NAME "cli: geo-wang build rejects a huge colour count" CODE 1 REGEX "--colors expects two integers NH,NV or three NX,NY,NZ in \\[1, 4096\\], got '1e300,2'"
                 COMMAND geo-wang build --exemplar ${_geo}/rings.obj --colors 1e300,2 --tile 4.8 --out ${_geo}/bad)
tessera_cli_test(NAME "cli: geo-wang build rejects a negative tile" CODE 1 REGEX "--tile expects a number in \\[0, 1e\\+06\\], got '-3'"
                 COMMAND geo-wang build --exemplar ${_geo}/rings.obj --colors 1,1 --tile -3 --out ${_geo}/bad)
tessera_cli_test(NAME "cli: geo-wang build rejects a tall edge" CODE 1 REGEX "edge_height 3 leaves no interior in a tile of size 4.8"
                 COMMAND geo-wang build --exemplar ${_geo}/rings.obj --colors 1,1 --tile 4.8 --edge-height 3 --out ${_geo}/bad)
set_tests_properties("cli: geo-wang build rejects a tall edge" PROPERTIES FIXTURES_REQUIRED geo_rings)
tessera_cli_test(NAME "cli: geo-wang tile reports a missing directory" CODE 1 REGEX "nowhere/tiles\\.json: cannot open the tile manifest"
                 COMMAND geo-wang tile --tiles ${_geo}/nowhere --grid 2x2 --out ${_geo}/x.obj)
tessera_cli_test(NAME "cli: geo-wang tile rejects a bad grid" CODE 1 REGEX "--grid expects positive integers WxH, got '0x3'"
                 COMMAND geo-wang tile --tiles ${_geo}/tiles --grid 0x3 --out ${_geo}/x.obj)
tessera_cli_test(NAME "cli: mesh-quilt rejects a missing exemplar" CODE 1 REGEX "none\\.obj"
                 COMMAND mesh-quilt --exemplar ${_geo}/none.obj --size 4,4 --out ${_geo}/x.obj)
tessera_cli_test(NAME "cli: mesh-quilt rejects a negative lambda" CODE 1 REGEX "--lambda expects a number in \\[0, 1e\\+06\\], got '-1'"
                 COMMAND mesh-quilt --exemplar ${_geo}/rings.obj --size 4,4 --lambda -1 --out ${_geo}/x.obj)
tessera_cli_test(NAME "cli: mesh-quilt rejects a zero size" CODE 1 REGEX "--size expects positive numbers WxH, at most 1e\\+06 each, got '0,4'"
                 COMMAND mesh-quilt --exemplar ${_geo}/rings.obj --size 0,4 --out ${_geo}/x.obj)
set_tests_properties("cli: mesh-quilt rejects a zero size" PROPERTIES FIXTURES_REQUIRED geo_rings)
tessera_cli_test(NAME "cli: exemplar rejects an unknown kind" CODE 1 REGEX "unknown exemplar kind 'bricks' \\(rings, stones or weave\\)"
                 COMMAND exemplar bricks --out ${_geo}/x.obj)
tessera_cli_test(NAME "cli: exemplar rejects a huge size" CODE 1 REGEX "--size expects a number in \\[0.5, 256\\], got '1e9'"
                 COMMAND exemplar rings --size 1e9 --out ${_geo}/x.obj)
tessera_cli_test(NAME "cli: render rejects an unknown view" CODE 1 REGEX "--view expects oblique, top, front or side, got 'under'"
                 COMMAND render ${_geo}/rings.obj --out ${_geo}/x.png --view under)
