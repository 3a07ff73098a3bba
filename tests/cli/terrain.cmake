# tessera terrain: a small frame with every output, --stats keys, and the documented bad inputs.
set(_t $<TARGET_FILE:tessera_cli>)
set(_o ${TESSERA_CLI_OUT})
set(_small --exemplar grass --exemplar-size 64 --grid 24 --viewport 160x90)

add_test(NAME "cli: terrain frame with stats"
         COMMAND ${_t} terrain ${_small} --sun 1,-1,2 --out ${_o}/terrain.png --scale-out ${_o}/terrain_scale.png
                 --tiled-out ${_o}/terrain_tiled.png --uv-out ${_o}/terrain_uv.bin --stats --threads 2)
set_tests_properties("cli: terrain frame with stats" PROPERTIES PASS_REGULAR_EXPRESSION
  "^\\{\"triangles\":1152,\"visible\":[0-9]+,\"levels\":[0-9]+,\"max_level_jump\":[01],\"restarts\":[0-9]+,\"continuous_edges\":[0-9.e-]+,\"scale_field_ms\":[0-9.e-]+,\"synthesis_ms\":[0-9.e-]+,\"render_ms\":[0-9.e-]+\\}")
add_test(NAME "cli: terrain continuous mode, uniform placement, explicit camera"
         COMMAND ${_t} terrain ${_small} --mode continuous --placement uniform --eye 0,-60,20 --target 0,0,0 --fov 50
                 --shading regions --out ${_o}/terrain_regions.png --stats)
set_tests_properties("cli: terrain continuous mode, uniform placement, explicit camera" PROPERTIES
  PASS_REGULAR_EXPRESSION "\"max_level_jump\":[01],")
add_test(NAME "cli: terrain help" COMMAND ${_t} terrain --help)
set_tests_properties("cli: terrain help" PROPERTIES PASS_REGULAR_EXPRESSION "--min-scale")

# documented behaviour: nothing visible is a warning, not an error
add_test(NAME "cli: terrain fully culled" COMMAND ${_t} terrain ${_small} --eye 0,0,30 --target 0,0,60 --up 0,1,0
                                                  --out ${_o}/terrain_empty.png --stats)
set_tests_properties("cli: terrain fully culled" PROPERTIES PASS_REGULAR_EXPRESSION "\"visible\":0,")
add_test(NAME "cli: terrain exemplar too small warns" COMMAND ${_t} terrain --exemplar grass --exemplar-size 8 --grid 4
                                                               --viewport 160x90 --out ${_o}/terrain_small.png)
set_tests_properties("cli: terrain exemplar too small warns" PROPERTIES PASS_REGULAR_EXPRESSION "warning: the exemplar")

# bad inputs: exit code 1 and a message naming the problem
foreach(_case
    "eye equals target|--eye 1,2,3 --target 1,2,3|equals its target"
    "fov zero|--fov 0|fov_y_degrees"
    "fov too wide|--fov 180|fov_y_degrees"
    "min scale zero|--min-scale 0|min-scale"
    "min scale above one|--min-scale 1.5|min-scale"
    "unknown exemplar|--exemplar nosuch|neither a readable file"
    "missing mesh file|--mesh ${_o}/no_such.obj|cannot open"
    "bad viewport|--viewport 0x5|viewport")
  string(REPLACE "|" ";" _parts "${_case}")
  list(GET _parts 0 _name)
  list(GET _parts 1 _args)
  list(GET _parts 2 _expect)
  separate_arguments(_args)
  if(_name STREQUAL "unknown exemplar" OR _name STREQUAL "missing mesh file")
    set(_base --viewport 160x90)
    if(_name STREQUAL "missing mesh file")
      list(APPEND _base --exemplar grass)
    endif()
  else()
    set(_base ${_small})
  endif()
  add_test(NAME "cli: terrain rejects ${_name}" COMMAND ${_t} terrain ${_base} ${_args} --out ${_o}/terrain_bad.png)
  set_tests_properties("cli: terrain rejects ${_name}" PROPERTIES WILL_FAIL TRUE)
  add_test(NAME "cli: terrain explains ${_name}" COMMAND ${_t} terrain ${_base} ${_args} --out ${_o}/terrain_bad.png)
  set_tests_properties("cli: terrain explains ${_name}" PROPERTIES PASS_REGULAR_EXPRESSION "${_expect}")
endforeach()

# an OBJ mesh with quads and v/t/n face syntax
add_test(NAME "cli: terrain from an OBJ mesh"
         COMMAND ${_t} terrain --exemplar sand --exemplar-size 64 --mesh ${CMAKE_CURRENT_SOURCE_DIR}/data/terrain/quad_plane.obj
                 --viewport 160x90 --camera oblique --out ${_o}/terrain_obj.png --stats)
set_tests_properties("cli: terrain from an OBJ mesh" PROPERTIES PASS_REGULAR_EXPRESSION "\"triangles\":72,\"visible\":72,")
