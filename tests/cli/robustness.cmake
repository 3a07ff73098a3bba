# The numeric-option matrix (issue 21): every numeric option of every command, run with -1, 0, huge,
# nan, inf, empty and malformed values (tests/cli/support/robust_option.cmake lists them per kind).
# Each run must end cleanly: exit 0, 1 or 2 with a message, never a signal, an abort or a hang; the
# values no option accepts (nan, inf, empty, malformed) must be refused naming the option. One ctest
# test per option; the base arguments keep every accepted run tiny. Add a row for every new numeric
# option.
set(_rb ${TESSERA_CLI_OUT}/robust)
file(MAKE_DIRECTORY ${_rb})
set(_robust_script ${CMAKE_CURRENT_LIST_DIR}/support/robust_option.cmake)

# _robust(COMMAND_LABEL OPTION KIND FIXTURE ARGS...): one row; ARGS are the base arguments of tessera
function(_robust label option kind fixture)
  set(_name "cli: robust ${label} ${option}")
  add_test(NAME "${_name}" COMMAND ${CMAKE_COMMAND} -DOPTION=${option} -DKIND=${kind} -P ${_robust_script} --
           $<TARGET_FILE:tessera_cli> ${ARGN})
  set_tests_properties("${_name}" PROPERTIES TIMEOUT 300)
  if(NOT fixture STREQUAL "-")
    set_tests_properties("${_name}" PROPERTIES FIXTURES_REQUIRED ${fixture})
  endif()
endfunction()

# inputs: a PNG, a mesh, an image tile directory and a geometric one
tessera_cli_test(NAME "cli: robust setup png" COMMAND sample bricks --size 32x32 --out ${_rb}/in.png)
set_tests_properties("cli: robust setup png" PROPERTIES FIXTURES_SETUP robust_png)
tessera_cli_test(NAME "cli: robust setup mesh" COMMAND exemplar rings --size 6.4 --segments 8 --out ${_rb}/rings.obj)
set_tests_properties("cli: robust setup mesh" PROPERTIES FIXTURES_SETUP robust_mesh)
tessera_cli_test(NAME "cli: robust setup tiles"
                 COMMAND wang build --exemplar grass --exemplar-size 48 --colors 1,1 --tile 16 --out ${_rb}/tiles)
set_tests_properties("cli: robust setup tiles" PROPERTIES FIXTURES_SETUP robust_tiles)
tessera_cli_test(NAME "cli: robust setup geometric tiles"
                 COMMAND geo-wang build --exemplar ${_rb}/rings.obj --colors 1,1 --tile 4.8 --out ${_rb}/geo)
set_tests_properties("cli: robust setup geometric tiles" PROPERTIES FIXTURES_REQUIRED robust_mesh
                                                                      FIXTURES_SETUP robust_geo)

# options every command shares (main checks them before any command runs)
foreach(_o --seed --threads --repeat)
  _robust("common" ${_o} int - sample bricks --size 8x8 --out ${_rb}/common.png)
endforeach()

set(_catmap catmap --in ${_rb}/in.png --out ${_rb}/catmap.png)
_robust("catmap" --iterations int robust_png ${_catmap})
_robust("catmap" --tile int robust_png ${_catmap})
_robust("catmap" --family list2 robust_png ${_catmap})
_robust("catmap" --period int - catmap)

set(_convert convert ${_rb}/in.png ${_rb}/converted.png)
_robust("convert" --channels int robust_png ${_convert})
_robust("convert" --depth int robust_png ${_convert})

set(_exemplar exemplar rings --out ${_rb}/exemplar.obj)
_robust("exemplar" --size number - ${_exemplar})
_robust("exemplar" --density number - ${_exemplar})
_robust("exemplar" --segments int - ${_exemplar})

set(_fabric fabric --preset twill --size 24 --out ${_rb}/fabric.png)
foreach(_o --feature --tile --iterations --generations --K --N)
  _robust("fabric" ${_o} int - ${_fabric})
endforeach()
_robust("fabric" --size size - fabric --preset twill --out ${_rb}/fabric.png)
_robust("fabric" --family list2 - ${_fabric})

set(_gwb geo-wang build --exemplar ${_rb}/rings.obj --colors 1,1 --tile 4.8 --out ${_rb}/geo_build)
_robust("geo-wang build" --colors list2 robust_mesh geo-wang build --exemplar ${_rb}/rings.obj --tile 4.8
        --out ${_rb}/geo_build)
_robust("geo-wang build" --tile number robust_mesh geo-wang build --exemplar ${_rb}/rings.obj --colors 1,1
        --out ${_rb}/geo_build)
_robust("geo-wang build" --edge-height number robust_mesh ${_gwb})
_robust("geo-wang tile" --grid size robust_geo geo-wang tile --tiles ${_rb}/geo --out ${_rb}/geo_plane.obj)

set(_mq mesh-quilt --exemplar ${_rb}/rings.obj --out ${_rb}/mesh_quilt.obj)
_robust("mesh-quilt" --size extent robust_mesh ${_mq})
_robust("mesh-quilt" --lambda number robust_mesh ${_mq} --size 10,10)

set(_quilt quilt --exemplar sand --exemplar-size 32 --size 24x24 --out ${_rb}/quilt.png)
foreach(_o --exemplar-size --patch --overlap)
  _robust("quilt" ${_o} int - ${_quilt})
endforeach()
_robust("quilt" --tolerance number - ${_quilt})
_robust("quilt" --size size - quilt --exemplar sand --exemplar-size 32 --out ${_rb}/quilt.png)

set(_render render ${_rb}/rings.obj --out ${_rb}/render.png --image-size 32x24)
foreach(_o --azimuth --elevation --grid)
  _robust("render" ${_o} number robust_mesh ${_render})
endforeach()
_robust("render" --image-size size robust_mesh render ${_rb}/rings.obj --out ${_rb}/render.png)

_robust("sample" --size size - sample bricks --out ${_rb}/sample.png)

set(_synth synth --exemplar sand --exemplar-size 32 --size 24x24 --out ${_rb}/synth.png)
_robust("synth" --exemplar-size int - ${_synth})
_robust("synth" --overlap int - ${_synth})
_robust("synth" --patch size - ${_synth})
_robust("synth" --size size - synth --exemplar sand --exemplar-size 32 --out ${_rb}/synth.png)
_robust("synth" --window list4 - synth --exemplar sand --exemplar-size 32 --out ${_rb}/synth.png)
_robust("synth" --candidates int - ${_synth})
set(_metrics metrics --exemplar sand --exemplar-size 32 --in ${_rb}/in.png)
foreach(_o --window --levels --step --min-offset --exemplar-size)
  _robust("metrics" ${_o} int robust_png ${_metrics})
endforeach()

set(_terrain terrain --exemplar sand --exemplar-size 32 --grid 4 --viewport 32x24 --out ${_rb}/terrain.png)
foreach(_o --levels --exemplar-size)
  _robust("terrain" ${_o} int - ${_terrain})
endforeach()
_robust("terrain" --grid int - terrain --exemplar sand --exemplar-size 32 --viewport 32x24 --out ${_rb}/terrain.png)
foreach(_o --height --fov --min-scale --feather)
  _robust("terrain" ${_o} number - ${_terrain})
endforeach()
foreach(_o --eye --target --up --sun)
  _robust("terrain" ${_o} list3 - ${_terrain})
endforeach()
_robust("terrain" --viewport size - terrain --exemplar sand --exemplar-size 32 --grid 4 --out ${_rb}/terrain.png)

_robust("tones" --max int robust_png tones ${_rb}/in.png)

set(_wb wang build --exemplar grass --exemplar-size 48 --colors 1,1 --tile 16 --out ${_rb}/wang_build)
foreach(_o --exemplar-size --overlap --patch --mip-levels --border)
  _robust("wang build" ${_o} int - ${_wb})
endforeach()
_robust("wang build" --tile int - wang build --exemplar grass --exemplar-size 48 --colors 1,1 --out ${_rb}/wang_build)
_robust("wang build" --tolerance number - ${_wb})
_robust("wang build" --colors list2 - wang build --exemplar grass --exemplar-size 48 --tile 16 --out ${_rb}/wang_build)
_robust("wang tile" --grid size robust_tiles wang tile --tiles ${_rb}/tiles --out ${_rb}/wang_tile.png)
_robust("wang tile" --period int robust_tiles wang tile --tiles ${_rb}/tiles --grid 3x2 --coloring periodic
        --out ${_rb}/wang_tile.png)

# grids at the option caps are refused before anything large is allocated (geo-wang tile once stored
# 2^28 cells, 4 GB, before its vertex-count check)
tessera_cli_test(NAME "cli: robust geo-wang tile refuses a 65536 x 4096 grid quickly" CODE 1 REGEX "--grid"
                 COMMAND geo-wang tile --tiles ${_rb}/geo --grid 65536x4096 --out ${_rb}/geo_huge.obj)
set_tests_properties("cli: robust geo-wang tile refuses a 65536 x 4096 grid quickly" PROPERTIES
                     FIXTURES_REQUIRED robust_geo TIMEOUT 20)
tessera_cli_test(NAME "cli: robust wang tile refuses a 65536 x 4096 grid quickly" CODE 1
                 COMMAND wang tile --tiles ${_rb}/tiles --grid 65536x4096 --out ${_rb}/wang_huge.png)
set_tests_properties("cli: robust wang tile refuses a 65536 x 4096 grid quickly" PROPERTIES
                     FIXTURES_REQUIRED robust_tiles TIMEOUT 20)
# --exemplar-size 600000 aborted with std::bad_alloc in quilt, wang build, terrain and synth
foreach(_c "quilt --size 8x8 --out ${_rb}/x.png" "wang build --out ${_rb}/x_tiles" "terrain --grid 2 --out ${_rb}/x.png"
           "synth --size 8x8 --out ${_rb}/x.png")
  separate_arguments(_args UNIX_COMMAND "${_c}")
  list(GET _args 0 _first)
  tessera_cli_test(NAME "cli: robust ${_first} refuses --exemplar-size 600000" CODE 1
                   REGEX "--exemplar-size expects an integer in \\[8, 4096\\], got '600000'"
                   COMMAND ${_args} --exemplar sand --exemplar-size 600000)
endforeach()

# the PNG decoding limit: named in the message with the way to raise it
add_test(NAME "cli: robust png decoding limit from TESSERA_MAX_PIXELS"
         COMMAND ${CMAKE_COMMAND} -E env TESSERA_MAX_PIXELS=100 ${CMAKE_COMMAND} -DCODE=1
                 "-DREGEX=32 x 32 = 1024 pixels.*limit of 100 pixels.*TESSERA_MAX_PIXELS"
                 -P ${CMAKE_CURRENT_LIST_DIR}/support/expect_exit.cmake -- $<TARGET_FILE:tessera_cli>
                 convert ${_rb}/in.png ${_rb}/limited.png)
add_test(NAME "cli: robust png decoding limit raised"
         COMMAND ${CMAKE_COMMAND} -E env TESSERA_MAX_PIXELS=1024 ${CMAKE_COMMAND} -DCODE=0
                 -P ${CMAKE_CURRENT_LIST_DIR}/support/expect_exit.cmake -- $<TARGET_FILE:tessera_cli>
                 convert ${_rb}/in.png ${_rb}/limited.png)
add_test(NAME "cli: robust malformed TESSERA_MAX_PIXELS"
         COMMAND ${CMAKE_COMMAND} -E env TESSERA_MAX_PIXELS=lots ${CMAKE_COMMAND} -DCODE=1
                 "-DREGEX=TESSERA_MAX_PIXELS expects an integer"
                 -P ${CMAKE_CURRENT_LIST_DIR}/support/expect_exit.cmake -- $<TARGET_FILE:tessera_cli>
                 convert ${_rb}/in.png ${_rb}/limited.png)
set_tests_properties("cli: robust png decoding limit from TESSERA_MAX_PIXELS" "cli: robust png decoding limit raised"
                     "cli: robust malformed TESSERA_MAX_PIXELS" PROPERTIES FIXTURES_REQUIRED robust_png)
