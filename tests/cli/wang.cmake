# tessera quilt / wang build / wang tile: outputs, --stats keys, and the documented bad inputs.
set(_t $<TARGET_FILE:tessera_cli>)
set(_o ${TESSERA_CLI_OUT}/wang)
file(MAKE_DIRECTORY ${_o})

# tessera_wang_cli_bad(NAME EXPECT ARGS...): the command exits with 1 and prints EXPECT
function(tessera_wang_cli_bad name expect)
  add_test(NAME "cli: ${name} fails" COMMAND ${_t} ${ARGN})
  set_tests_properties("cli: ${name} fails" PROPERTIES WILL_FAIL TRUE)
  add_test(NAME "cli: ${name} explains" COMMAND ${_t} ${ARGN})
  set_tests_properties("cli: ${name} explains" PROPERTIES PASS_REGULAR_EXPRESSION "${expect}")
endfunction()
set(_num "[0-9.e+-]+")

# --- quilt -----------------------------------------------------------------------------------------
add_test(NAME "cli: quilt with stats"
         COMMAND ${_t} quilt --exemplar cells --exemplar-size 64 --size 96x80 --patch 16 --out ${_o}/quilt.png --stats --threads 2)
set_tests_properties("cli: quilt with stats" PROPERTIES PASS_REGULAR_EXPRESSION
  "^\\{\"command\":\"quilt\",\"mode\":\"quilt\",\"width\":96,\"height\":80,\"quilt_ms\":${_num}\\}")
add_test(NAME "cli: quilt seamless with options"
         COMMAND ${_t} quilt --exemplar sand --exemplar-size 64 --size 64x64 --patch 20 --overlap 5 --tolerance 0.2 --seamless
                 --out ${_o}/quilt_seamless.png --stats --repeat 2)
set_tests_properties("cli: quilt seamless with options" PROPERTIES PASS_REGULAR_EXPRESSION "\"mode\":\"seamless\",\"width\":64,\"height\":64")
add_test(NAME "cli: quilt help" COMMAND ${_t} quilt --help)
set_tests_properties("cli: quilt help" PROPERTIES PASS_REGULAR_EXPRESSION "--seamless")
tessera_wang_cli_bad("quilt without --size" "missing required option --size" quilt --exemplar sand --out ${_o}/bad.png)
tessera_wang_cli_bad("quilt with a patch larger than the exemplar" "patch_size 80 does not fit the 64 x 64 exemplar"
                     quilt --exemplar sand --exemplar-size 64 --size 32x32 --patch 80 --out ${_o}/bad.png)
tessera_wang_cli_bad("quilt with a too wide overlap" "overlap 9 must be in" quilt --exemplar sand --exemplar-size 64 --size 32x32
                     --patch 16 --overlap 9 --out ${_o}/bad.png)
tessera_wang_cli_bad("quilt with an unknown exemplar" "neither a readable file" quilt --exemplar nosuch --size 32x32 --out ${_o}/bad.png)
tessera_wang_cli_bad("quilt with --mask but no --in" "--mask and --in go together" quilt --mask ${_o}/quilt.png --out ${_o}/bad.png)
tessera_wang_cli_bad("quilt with a missing mask file" "cannot open" quilt --in sand --mask ${_o}/no_such.png --out ${_o}/bad.png)

# --- wang build ------------------------------------------------------------------------------------
add_test(NAME "cli: wang build with stats"
         COMMAND ${_t} wang build --exemplar bricks --exemplar-size 96 --colors 2,2 --tile 32 --out ${_o}/tiles --stats --threads 2)
set_tests_properties("cli: wang build with stats" PROPERTIES FIXTURES_SETUP wang_tiles PASS_REGULAR_EXPRESSION
  "^\\{\"command\":\"wang build\",\"tiles\":16,\"tile_size\":32,\"build_ms\":${_num},\"seam_ratio_mean\":${_num},\"seam_ratio_max\":${_num},\"atlas\":\"edge_ordered\"\\}")
add_test(NAME "cli: wang build a Cohen subset"
         COMMAND ${_t} wang build --exemplar grass --exemplar-size 64 --colors 2,2 --tile 24 --subset --out ${_o}/subset --stats)
set_tests_properties("cli: wang build a Cohen subset" PROPERTIES FIXTURES_SETUP wang_subset PASS_REGULAR_EXPRESSION
  "\"tiles\":8,.*\"atlas\":\"padded\"")
add_test(NAME "cli: wang build help" COMMAND ${_t} wang build --help)
set_tests_properties("cli: wang build help" PROPERTIES PASS_REGULAR_EXPRESSION "--colors NH,NV")
tessera_wang_cli_bad("wang build with tiles larger than the exemplar" "tile_size 64 is larger than the 48 x 48 exemplar"
                     wang build --exemplar sand --exemplar-size 48 --tile 64 --out ${_o}/bad)
tessera_wang_cli_bad("wang build with zero colours" "horizontal \\(north/south\\) colours must be in \\[1, 4096\\], got 0"
                     wang build --exemplar sand --exemplar-size 48 --colors 0,2 --tile 16 --out ${_o}/bad)
tessera_wang_cli_bad("wang build with one number for --colors" "--colors expects 2 comma-separated numbers"
                     wang build --exemplar sand --colors 3 --tile 16 --out ${_o}/bad)
tessera_wang_cli_bad("wang build a subset of odd colour counts" "modulus 2 must be >= 1 and divide"
                     wang build --exemplar sand --exemplar-size 48 --colors 3,3 --subset --tile 16 --out ${_o}/bad)

# --- wang tile -------------------------------------------------------------------------------------
foreach(_coloring scanline hash periodic)
  add_test(NAME "cli: wang tile ${_coloring}"
           COMMAND ${_t} wang tile --tiles ${_o}/tiles --grid 5x4 --coloring ${_coloring} --out ${_o}/tiled_${_coloring}.png
                   --stats --repeat 3)
  set_tests_properties("cli: wang tile ${_coloring}" PROPERTIES FIXTURES_REQUIRED wang_tiles PASS_REGULAR_EXPRESSION
    "^\\{\"command\":\"wang tile\",\"coloring\":\"${_coloring}\",\"width\":160,\"height\":128,\"tiling_ms\":${_num},\"mpixels_per_s\":${_num}\\}")
endforeach()
add_test(NAME "cli: wang tile a subset with the hash colouring"
         COMMAND ${_t} wang tile --tiles ${_o}/subset --grid 4x4 --coloring hash --out ${_o}/tiled_subset.png --stats)
set_tests_properties("cli: wang tile a subset with the hash colouring" PROPERTIES FIXTURES_REQUIRED wang_subset
  PASS_REGULAR_EXPRESSION "\"width\":96,\"height\":96")
# the same grass tiling with outlines: the red tile borders make a mask for the inpainting test below
add_test(NAME "cli: wang tile outlined" COMMAND ${_t} wang tile --tiles ${_o}/subset --grid 4x4 --seed 4 --outline --out ${_o}/outlined.png)
add_test(NAME "cli: wang tile plain" COMMAND ${_t} wang tile --tiles ${_o}/subset --grid 4x4 --seed 4 --out ${_o}/plain.png)
set_tests_properties("cli: wang tile outlined" "cli: wang tile plain" PROPERTIES FIXTURES_REQUIRED wang_subset FIXTURES_SETUP wang_plain)
add_test(NAME "cli: quilt fills a mask"
         COMMAND ${_t} quilt --in ${_o}/plain.png --mask ${_o}/outlined.png --patch 12 --out ${_o}/filled.png --stats)
set_tests_properties("cli: quilt fills a mask" PROPERTIES FIXTURES_REQUIRED wang_plain PASS_REGULAR_EXPRESSION
  "\"mode\":\"inpaint\",\"width\":96,\"height\":96")
tessera_wang_cli_bad("quilt with a mask of another size" "mask is 160 x 128 but image is 96 x 96"
                     quilt --in ${_o}/plain.png --mask ${_o}/tiled_hash.png --out ${_o}/bad.png)
set_tests_properties("cli: quilt with a mask of another size fails" "cli: quilt with a mask of another size explains"
                     PROPERTIES FIXTURES_REQUIRED "wang_plain;wang_tiles;wang_subset")

tessera_wang_cli_bad("wang tile without a tile directory" "tiles.json: cannot open" wang tile --tiles ${_o}/no_such --grid 2x2 --out ${_o}/bad.png)
tessera_wang_cli_bad("wang tile with an unknown colouring" "--coloring expects scanline, hash or periodic"
                     wang tile --tiles ${_o}/tiles --grid 2x2 --coloring spiral --out ${_o}/bad.png)
tessera_wang_cli_bad("wang tile with a bad grid" "--grid expects" wang tile --tiles ${_o}/tiles --grid 0x2 --out ${_o}/bad.png)
# a directory with a missing tile and one with a tile of the wrong size
add_test(NAME "cli: wang tile prepare broken directories"
         COMMAND ${CMAKE_COMMAND} -E chdir ${_o} sh -c
                 "rm -rf missing wrong && cp -r tiles missing && cp -r tiles wrong && rm missing/tile_5.png && cp quilt.png wrong/tile_2.png")
set_tests_properties("cli: wang tile prepare broken directories" PROPERTIES FIXTURES_REQUIRED wang_tiles FIXTURES_SETUP wang_broken
                     DEPENDS "cli: quilt with stats")
tessera_wang_cli_bad("wang tile with a missing tile" "tile_5.png: tile 5 listed in .*tiles.json is missing"
                     wang tile --tiles ${_o}/missing --grid 2x2 --out ${_o}/bad.png)
tessera_wang_cli_bad("wang tile with a mismatched tile" "tile_2.png is 96 x 80 but .*tiles.json says tile_size 32"
                     wang tile --tiles ${_o}/wrong --grid 2x2 --out ${_o}/bad.png)
foreach(_n "missing tile" "mismatched tile")
  set_tests_properties("cli: wang tile with a ${_n} fails" "cli: wang tile with a ${_n} explains" PROPERTIES FIXTURES_REQUIRED wang_broken)
endforeach()
