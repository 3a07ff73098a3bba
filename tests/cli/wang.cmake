# tessera quilt / wang build / wang tile: outputs (files checked for size and content), --stats keys,
# and the documented bad inputs (exit code 1 and the message). Every tessera run goes through
# tessera_cli_test (tests/cli/README.md); tiles.json is checked by wang_support/check_tiles_json.cmake.
set(_o ${TESSERA_CLI_OUT}/wang)
file(MAKE_DIRECTORY ${_o})
set(_num "[0-9.e+-]+")
set(_check_tiles ${CMAKE_CURRENT_LIST_DIR}/wang_support/check_tiles_json.cmake)

# _wang_fail(NAME REGEX ARGS...): `tessera ARGS` exits with 1 and prints REGEX
function(_wang_fail name regex)
  tessera_cli_test(NAME "cli: ${name}" CODE 1 REGEX "${regex}" COMMAND ${ARGN})
endfunction()
# _wang_png_size(NAME FILE W H FIXTURE): `tessera info FILE --stats` reports a W x H image
function(_wang_png_size name file w h fixture)
  tessera_cli_test(NAME "cli: ${name}" REGEX "\"width\":${w},\"height\":${h},\"channels\":[1-4]," COMMAND info ${file} --stats)
  set_tests_properties("cli: ${name}" PROPERTIES FIXTURES_REQUIRED ${fixture})
endfunction()

# --- quilt -----------------------------------------------------------------------------------------
tessera_cli_test(NAME "cli: quilt with stats"
                 REGEX "^{\"command\":\"quilt\",\"mode\":\"quilt\",\"width\":96,\"height\":80,\"quilt_ms\":${_num}}\n$"
                 COMMAND quilt --exemplar cells --exemplar-size 64 --size 96x80 --patch 16 --out ${_o}/quilt.png --stats
                         --threads 2)
set_tests_properties("cli: quilt with stats" PROPERTIES FIXTURES_SETUP wang_quilt)
_wang_png_size("quilt wrote a 96 x 80 png" ${_o}/quilt.png 96 80 wang_quilt)
tessera_cli_test(NAME "cli: quilt seamless with options"
                 REGEX "^{\"command\":\"quilt\",\"mode\":\"seamless\",\"width\":64,\"height\":64,\"quilt_ms\":${_num}}\n$"
                 COMMAND quilt --exemplar sand --exemplar-size 64 --size 64x64 --patch 20 --overlap 5 --tolerance 0.2
                         --seamless --out ${_o}/quilt_seamless.png --stats --repeat 2)
tessera_cli_test(NAME "cli: quilt help lists its options" REGEX "--seamless.*--mask" COMMAND quilt --help)
_wang_fail("quilt without --size" "missing required option --size" quilt --exemplar sand --out ${_o}/bad.png)
_wang_fail("quilt with a patch larger than the exemplar" "patch_size 80 does not fit the 64 x 64 exemplar"
           quilt --exemplar sand --exemplar-size 64 --size 32x32 --patch 80 --out ${_o}/bad.png)
_wang_fail("quilt with a too wide overlap" "overlap 9 must be in \\[1, patch_size / 2 = 8\\]"
           quilt --exemplar sand --exemplar-size 64 --size 32x32 --patch 16 --overlap 9 --out ${_o}/bad.png)
_wang_fail("quilt with a negative patch" "--patch expects an integer in \\[0, 65536\\], got '-3'"
           quilt --exemplar sand --size 32x32 --patch -3 --out ${_o}/bad.png)
_wang_fail("quilt with a NaN tolerance" "--tolerance expects a finite number, got 'nan'"
           quilt --exemplar sand --size 32x32 --tolerance nan --out ${_o}/bad.png)
_wang_fail("quilt with a size beyond the cap" "--size expects at most 65536 per side and 268435456 in all, got '20000x20000'"
           quilt --exemplar sand --size 20000x20000 --out ${_o}/bad.png)
_wang_fail("quilt with an unknown exemplar" "neither a readable file" quilt --exemplar nosuch --size 32x32 --out ${_o}/bad.png)
_wang_fail("quilt with --mask but no --in" "--mask and --in go together" quilt --mask ${_o}/quilt.png --out ${_o}/bad.png)
_wang_fail("quilt with a missing mask file" "no_such.png: cannot open" quilt --in sand --mask ${_o}/no_such.png
           --out ${_o}/bad.png)

# --- wang build ------------------------------------------------------------------------------------
# the complete 2 x 2 set of 32-pixel tiles: 3 exact mip levels by default (border 4)
tessera_cli_test(NAME "cli: wang build with stats"
                 REGEX "^{\"command\":\"wang build\",\"tiles\":16,\"tile_size\":32,\"build_ms\":${_num},\"seam_ratio_mean\":${_num},\"seam_ratio_max\":${_num},\"atlas\":\"edge_ordered\",\"atlas_mip_levels\":3,\"shared_border\":([4-9]|1[0-6])}\n$"
                 COMMAND wang build --exemplar bricks --exemplar-size 96 --colors 2,2 --tile 32 --out ${_o}/tiles --stats
                         --threads 2)
set_tests_properties("cli: wang build with stats" PROPERTIES FIXTURES_SETUP wang_tiles)
add_test(NAME "cli: wang build wrote tiles.json with 16 complete-set tiles"
         COMMAND ${CMAKE_COMMAND} -DDIR=${_o}/tiles -DCOUNT=16 -DTILE=32 -DNH=2 -DNV=2 -DSET=complete -P ${_check_tiles})
set_tests_properties("cli: wang build wrote tiles.json with 16 complete-set tiles" PROPERTIES FIXTURES_REQUIRED wang_tiles)
# edge-ordered atlas: nv^2 x nh^2 tiles of 32
_wang_png_size("wang build wrote a 128 x 128 atlas" ${_o}/tiles/atlas.png 128 128 wang_tiles)
_wang_png_size("wang build wrote 32 x 32 tiles" ${_o}/tiles/tile_15.png 32 32 wang_tiles)

# Cohen's 8 tiles of 24: padded atlas (3 x 3 slots of 24 + 2 x 2), 2 exact mip levels
tessera_cli_test(NAME "cli: wang build a Cohen subset"
                 REGEX "^{\"command\":\"wang build\",\"tiles\":8,\"tile_size\":24,[^\n]*\"atlas\":\"padded\",\"atlas_mip_levels\":2,"
                 COMMAND wang build --exemplar grass --exemplar-size 64 --colors 2,2 --tile 24 --subset --out ${_o}/subset --stats)
set_tests_properties("cli: wang build a Cohen subset" PROPERTIES FIXTURES_SETUP wang_subset)
add_test(NAME "cli: wang build wrote tiles.json with Cohen's 8 tiles"
         COMMAND ${CMAKE_COMMAND} -DDIR=${_o}/subset -DCOUNT=8 -DTILE=24 -DNH=2 -DNV=2 -DSET=modular2 -P ${_check_tiles})
set_tests_properties("cli: wang build wrote tiles.json with Cohen's 8 tiles" PROPERTIES FIXTURES_REQUIRED wang_subset)
_wang_png_size("wang build wrote an 84 x 84 padded atlas" ${_o}/subset/atlas.png 84 84 wang_subset)

# --mip-levels 4 on tiles of 32: border 8
tessera_cli_test(NAME "cli: wang build for 4 mip levels"
                 REGEX "\"atlas\":\"edge_ordered\",\"atlas_mip_levels\":[45],\"shared_border\":([89]|1[0-6])}\n$"
                 COMMAND wang build --exemplar weave --exemplar-size 64 --colors 2,2 --tile 32 --mip-levels 4
                         --out ${_o}/mip4 --stats)
tessera_cli_test(NAME "cli: wang build help lists its options" REGEX "--colors NH,NV.*--mip-levels L" COMMAND wang build --help)
_wang_fail("wang build with tiles larger than the exemplar" "tile_size 64 is larger than the 48 x 48 exemplar"
           wang build --exemplar sand --exemplar-size 48 --tile 64 --out ${_o}/bad)
_wang_fail("wang build with zero colours" "--colors expects two integers NH,NV or three NX,NY,NZ in \\[1, 4096\\], got '0,2'"
           wang build --exemplar sand --exemplar-size 48 --colors 0,2 --tile 16 --out ${_o}/bad)
_wang_fail("wang build with 1e10 colours" "--colors expects two integers NH,NV or three NX,NY,NZ in \\[1, 4096\\], got '1e10,2'"
           wang build --exemplar sand --exemplar-size 48 --colors 1e10,2 --tile 16 --out ${_o}/bad)
_wang_fail("wang build with fractional colours" "--colors expects two integers NH,NV or three NX,NY,NZ in \\[1, 4096\\], got '2.5,2'"
           wang build --exemplar sand --exemplar-size 48 --colors 2.5,2 --tile 16 --out ${_o}/bad)
_wang_fail("wang build with one number for --colors" "--colors expects two integers NH,NV or three NX,NY,NZ in \\[1, 4096\\], got '3'"
           wang build --exemplar sand --colors 3 --tile 16 --out ${_o}/bad)
_wang_fail("wang build with 64 x 64 colours" "size_overflow: wang tile set: 16777216 tiles of 16 x 16 pixels"
           wang build --exemplar sand --exemplar-size 48 --colors 64,64 --tile 16 --out ${_o}/bad)
_wang_fail("wang build a subset of odd colour counts" "modulus 2 must be >= 1 and divide"
           wang build --exemplar sand --exemplar-size 48 --colors 3,3 --subset --tile 16 --out ${_o}/bad)
_wang_fail("wang build with a tile of 3" "--tile expects an integer in \\[4, 65536\\], got '3'"
           wang build --exemplar sand --exemplar-size 48 --tile 3 --out ${_o}/bad)
_wang_fail("wang build with 17 mip levels" "--mip-levels expects an integer in \\[0, 16\\], got '17'"
           wang build --exemplar sand --exemplar-size 48 --tile 16 --mip-levels 17 --out ${_o}/bad)
_wang_fail("wang build with mip levels the tile size does not allow"
           "tile_size 36 must be a multiple of 2\\^\\(mip_levels - 1\\) = 8 for 4 exact mip levels"
           wang build --exemplar sand --exemplar-size 48 --tile 36 --mip-levels 4 --out ${_o}/bad)

# --- wang tile -------------------------------------------------------------------------------------
foreach(_coloring scanline hash periodic)
  tessera_cli_test(NAME "cli: wang tile ${_coloring}"
                   REGEX "^{\"command\":\"wang tile\",\"coloring\":\"${_coloring}\",\"width\":160,\"height\":128,\"tiling_ms\":${_num},\"mpixels_per_s\":${_num}}\n$"
                   COMMAND wang tile --tiles ${_o}/tiles --grid 5x4 --coloring ${_coloring} --out ${_o}/tiled_${_coloring}.png
                           --stats --repeat 3)
  set_tests_properties("cli: wang tile ${_coloring}" PROPERTIES FIXTURES_REQUIRED wang_tiles FIXTURES_SETUP wang_tiled)
endforeach()
_wang_png_size("wang tile wrote a 160 x 128 png" ${_o}/tiled_hash.png 160 128 wang_tiled)
tessera_cli_test(NAME "cli: wang tile a subset with the hash colouring"
                 REGEX "^{\"command\":\"wang tile\",\"coloring\":\"hash\",\"width\":96,\"height\":96,"
                 COMMAND wang tile --tiles ${_o}/subset --grid 4x4 --coloring hash --out ${_o}/tiled_subset.png --stats)
set_tests_properties("cli: wang tile a subset with the hash colouring" PROPERTIES FIXTURES_REQUIRED wang_subset)
# the same grass tiling with outlines: the red tile borders make a mask for the inpainting test below
tessera_cli_test(NAME "cli: wang tile outlined" COMMAND wang tile --tiles ${_o}/subset --grid 4x4 --seed 4 --outline
                                                        --out ${_o}/outlined.png)
tessera_cli_test(NAME "cli: wang tile plain" COMMAND wang tile --tiles ${_o}/subset --grid 4x4 --seed 4 --out ${_o}/plain.png)
set_tests_properties("cli: wang tile outlined" "cli: wang tile plain" PROPERTIES FIXTURES_REQUIRED wang_subset
                     FIXTURES_SETUP wang_plain)
tessera_cli_test(NAME "cli: quilt fills a mask"
                 REGEX "^{\"command\":\"quilt\",\"mode\":\"inpaint\",\"width\":96,\"height\":96,\"quilt_ms\":${_num}}\n$"
                 COMMAND quilt --in ${_o}/plain.png --mask ${_o}/outlined.png --patch 12 --out ${_o}/filled.png --stats)
set_tests_properties("cli: quilt fills a mask" PROPERTIES FIXTURES_REQUIRED wang_plain)
_wang_fail("quilt with a mask of another size" "mask is 160 x 128 but image is 96 x 96"
           quilt --in ${_o}/plain.png --mask ${_o}/tiled_hash.png --out ${_o}/bad.png)
set_tests_properties("cli: quilt with a mask of another size" PROPERTIES FIXTURES_REQUIRED "wang_plain;wang_tiled")

_wang_fail("wang tile without a tile directory" "no_such/tiles.json: cannot open"
           wang tile --tiles ${_o}/no_such --grid 2x2 --out ${_o}/bad.png)
_wang_fail("wang tile with an unknown colouring" "--coloring expects hash, scanline or periodic, got 'spiral'"
           wang tile --tiles ${_o}/tiles --grid 2x2 --coloring spiral --out ${_o}/bad.png)
_wang_fail("wang tile with a bad grid" "--grid expects positive integers WxH, got '0x2'"
           wang tile --tiles ${_o}/tiles --grid 0x2 --out ${_o}/bad.png)
_wang_fail("wang tile with period 0" "--period expects an integer in \\[1, 8192\\], got '0'"
           wang tile --tiles ${_o}/tiles --grid 2x2 --coloring periodic --period 0 --out ${_o}/bad.png)
set_tests_properties("cli: wang tile with an unknown colouring" "cli: wang tile with a bad grid" "cli: wang tile with period 0"
                     PROPERTIES FIXTURES_REQUIRED wang_tiles)
# a directory with a missing tile and one with a tile of the wrong size (not tessera runs: plain exit codes)
add_test(NAME "cli: wang tile prepare broken directories"
         COMMAND ${CMAKE_COMMAND} -E chdir ${_o} sh -c
                 "rm -rf missing wrong && cp -r tiles missing && cp -r tiles wrong && rm missing/tile_5.png && cp quilt.png wrong/tile_2.png")
set_tests_properties("cli: wang tile prepare broken directories" PROPERTIES FIXTURES_REQUIRED "wang_tiles;wang_quilt"
                     FIXTURES_SETUP wang_broken)
_wang_fail("wang tile with a missing tile" "tile_5.png: tile 5 listed in .*tiles.json is missing"
           wang tile --tiles ${_o}/missing --grid 2x2 --out ${_o}/bad.png)
_wang_fail("wang tile with a mismatched tile" "tile_2.png is 96 x 80 but .*tiles.json says tile_size 32"
           wang tile --tiles ${_o}/wrong --grid 2x2 --out ${_o}/bad.png)
set_tests_properties("cli: wang tile with a missing tile" "cli: wang tile with a mismatched tile" PROPERTIES FIXTURES_REQUIRED
                     wang_broken)

# --- three-axis sets and wang map (image Wang tiles on surfaces) ------------------------------------
set(_wsdata ${CMAKE_CURRENT_LIST_DIR}/../data/surface)
tessera_cli_test(NAME "cli: wang build three-axis with stats"
                 REGEX "^{\"command\":\"wang build\",\"tiles\":96,\"tile_size\":16,\"build_ms\":${_num},\"seam_ratio_mean\":${_num},\"seam_ratio_max\":${_num},\"atlas\":\"three_axis\",\"atlas_mip_levels\":2,\"shared_border\":[2-8]}\n$"
                 COMMAND wang build --exemplar cells --exemplar-size 64 --colors 2,2,2 --tile 16 --out ${_o}/axis_tiles
                         --threads 2 --stats)
set_tests_properties("cli: wang build three-axis with stats" PROPERTIES FIXTURES_SETUP wang_axis_tiles)
add_test(NAME "cli: wang build three-axis wrote version 2 tiles.json with faces"
         COMMAND ${CMAKE_COMMAND} -DFILE=${_o}/axis_tiles/tiles.json -P ${CMAKE_CURRENT_LIST_DIR}/wang_support/check_axis_tiles_json.cmake)
set_tests_properties("cli: wang build three-axis wrote version 2 tiles.json with faces" PROPERTIES FIXTURES_REQUIRED wang_axis_tiles)
tessera_cli_test(NAME "cli: wang map torus with stats"
                 REGEX "^{\"command\":\"wang map\",\"map_ms\":${_num},\"quads\":[1-9][0-9]*,\"tiles_used\":[1-9][0-9]*,\"vertices\":[1-9][0-9]*,\"faces\":[1-9][0-9]*,\"split_faces\":[1-9][0-9]*,\"refined\":false}\n$"
                 COMMAND wang map --tiles ${_o}/axis_tiles --mesh ${_wsdata}/torus.obj --out ${_o}/torus_wang.obj --tile 0.5
                         --seed 3 --threads 2 --stats)
set_tests_properties("cli: wang map torus with stats" PROPERTIES FIXTURES_REQUIRED wang_axis_tiles FIXTURES_SETUP wang_map)
_wang_png_size("wang map wrote the atlas beside the obj" ${_o}/torus_wang.png 240 160 wang_map)
add_test(NAME "cli: wang map wrote an mtl naming the atlas"
         COMMAND ${CMAKE_COMMAND} -DFILE=${_o}/torus_wang.mtl -DREGEX=map_Kd\ torus_wang\\.png
                 -P ${CMAKE_CURRENT_LIST_DIR}/wang_support/check_file_matches.cmake)
set_tests_properties("cli: wang map wrote an mtl naming the atlas" PROPERTIES FIXTURES_REQUIRED wang_map)
tessera_cli_test(NAME "cli: wang map from a polycube file" REGEX "wrote .*l_wang\\.obj, .*l_wang\\.mtl and .*l_wang\\.png"
                 COMMAND wang map --tiles ${_o}/axis_tiles --mesh ${_wsdata}/l_shape.off --polycube ${_wsdata}/l_shape.off
                         --out ${_o}/l_wang.obj --tile 0.5)
set_tests_properties("cli: wang map from a polycube file" PROPERTIES FIXTURES_REQUIRED wang_axis_tiles)
_wang_fail("wang map on an open mesh" "is not closed"
           wang map --tiles ${_o}/axis_tiles --mesh ${_wsdata}/open_cube.obj --out ${_o}/bad.obj --tile 0.5)
_wang_fail("wang map with a planar set" "a planar tile set, not a three-axis one"
           wang map --tiles ${_o}/tiles --mesh ${_wsdata}/torus.obj --out ${_o}/bad.obj --tile 0.5)
_wang_fail("wang map without --tile" "--tile W \\(the quad size in mesh units, > 0\\) is required"
           wang map --tiles ${_o}/axis_tiles --mesh ${_wsdata}/torus.obj --out ${_o}/bad.obj)
_wang_fail("wang map with a polycube of another mesh" "connectivity|differs|vertex count|faces"
           wang map --tiles ${_o}/axis_tiles --mesh ${_wsdata}/torus.obj --polycube ${_wsdata}/l_shape.off
                    --out ${_o}/bad.obj --tile 0.5)
_wang_fail("wang build three-axis with --subset" "--subset is for planar sets"
           wang build --exemplar cells --colors 2,2,2 --tile 16 --subset --out ${_o}/bad_tiles)
set_tests_properties("cli: wang map with a planar set" PROPERTIES FIXTURES_REQUIRED "wang_axis_tiles;wang_tiles")
foreach(_t "wang map on an open mesh" "wang map without --tile" "wang map with a polycube of another mesh")
  set_tests_properties("cli: ${_t}" PROPERTIES FIXTURES_REQUIRED wang_axis_tiles)
endforeach()
