# tessera terrain: a small frame with every output, --stats keys, and the documented bad inputs.
# Every test checks the exit code and the output (tessera_cli_test, tests/cli/README.md).
set(_o ${TESSERA_CLI_OUT})
set(_small --exemplar grass --exemplar-size 64 --grid 24 --viewport 160x90)

tessera_cli_test(NAME "cli: terrain frame with stats"
  REGEX "^\\{\"triangles\":1152,\"visible\":[0-9]+,\"levels\":[0-9]+,\"max_level_jump\":[01],\"restarts\":[0-9]+,\"continuous_edges\":[0-9.e-]+,\"scale_field_ms\":[0-9.e-]+,\"synthesis_ms\":[0-9.e-]+,\"render_ms\":[0-9.e-]+\\}"
  COMMAND terrain ${_small} --sun 1,-1,2 --out ${_o}/terrain.png --scale-out ${_o}/terrain_scale.png
          --tiled-out ${_o}/terrain_tiled.png --uv-out ${_o}/terrain_uv.bin --stats --threads 2)
tessera_cli_test(NAME "cli: terrain continuous mode, uniform placement, explicit camera"
  REGEX "\"max_level_jump\":[01],"
  COMMAND terrain ${_small} --mode continuous --placement uniform --eye 0,-60,20 --target 0,0,0 --fov 50
          --shading regions --out ${_o}/terrain_regions.png --stats)
tessera_cli_test(NAME "cli: terrain help" REGEX "--min-scale" COMMAND terrain --help)

# documented behaviour: nothing visible is a warning, not an error (exit 0, background frame)
tessera_cli_test(NAME "cli: terrain fully culled"
  REGEX "\"visible\":0,\"levels\":0,.*warning: no triangle is visible"
  COMMAND terrain ${_small} --eye 0,0,30 --target 0,0,60 --up 0,1,0 --out ${_o}/terrain_empty.png --stats)
tessera_cli_test(NAME "cli: terrain exemplar too small warns"
  REGEX "warning: the exemplar \\(8 x 8\\) is only [0-9.e-]+ times the screen area"
  COMMAND terrain --exemplar grass --exemplar-size 8 --grid 4 --viewport 160x90 --out ${_o}/terrain_small.png)

# bad inputs: exit code 1 and a message naming the problem
foreach(_case
    "eye equals target|--eye 1,2,3 --target 1,2,3|equals its target"
    "fov zero|--fov 0|fov_y_degrees must be in \\(0, 180\\), got 0"
    "fov too wide|--fov 180|fov_y_degrees must be in \\(0, 180\\), got 180"
    "min scale zero|--min-scale 0|--min-scale must be in \\(0, 1., got 0"
    "min scale above one|--min-scale 1.5|--min-scale must be in \\(0, 1., got 1.5"
    "unknown exemplar|--exemplar nosuch|neither a readable file"
    "missing mesh file|--mesh ${_o}/no_such.obj|cannot open"
    "bad viewport|--viewport 0x5|--viewport"
    "viewport too large|--viewport 20000x10|--viewport.*at most 16384 per side"
    "grid too large|--grid 16384|--grid.*an integer in \\[1, 4096\\]"
    "grid zero|--grid 0|--grid.*an integer in \\[1, 4096\\]"
    "feather out of range|--feather 100|--feather.*a number in \\[0, 64\\]"
    "non-finite height|--height nan|--height.*a finite number"
    "unknown shading|--shading foo|--shading expects texture, scale or regions")
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
  tessera_cli_test(NAME "cli: terrain rejects ${_name}" CODE 1 REGEX "${_expect}"
    COMMAND terrain ${_base} ${_args} --out ${_o}/terrain_bad.png)
endforeach()

# an OBJ mesh with quads and v/t/n face syntax
tessera_cli_test(NAME "cli: terrain from an OBJ mesh" REGEX "\"triangles\":72,\"visible\":72,"
  COMMAND terrain --exemplar sand --exemplar-size 64 --mesh ${CMAKE_CURRENT_SOURCE_DIR}/data/terrain/quad_plane.obj
          --viewport 160x90 --camera oblique --out ${_o}/terrain_obj.png --stats)

# the paper's literal rules (first neighbour, uniform placement, immediate restarts) still run
tessera_cli_test(NAME "cli: terrain with the paper's literal synthesis rules" REGEX "\"max_level_jump\":[01],\"restarts\":[1-9]"
  COMMAND terrain ${_small} --continuation first --placement uniform --restart immediate --keep-axis no
          --out ${_o}/terrain_literal.png --stats)
tessera_cli_test(NAME "cli: terrain rejects an unknown restart rule" CODE 1 REGEX "--restart expects wait or immediate, got 'later'"
  COMMAND terrain ${_small} --restart later --out ${_o}/terrain_bad.png)
