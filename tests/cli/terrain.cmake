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

# --anchor ground / --path / --frames-out (issue 18): a short fly-through, one --stats line per frame
file(WRITE ${_o}/terrain_path.txt "# ex ey ez tx ty tz fov\n0 -45 12 0 -15 0 55\n\n0 -44.6 12 0 -14.6 0 55\n0 -44.2 12 0 -14.2 0 55\n")
set(_frame_line "\\{\"frame\":[0-9]+,\"frame_ms\":[0-9.e-]+,\"visible\":[0-9]+,\"resynthesized\":[0-9]+,\"stable_faces\":[0-9.e-]+,\"continuous_edges\":[0-9.e-]+,\"max_level_jump\":[01]\\}")
# ground-anchored frames also print the texture stretch of the faces in view; its max stays within
# the default max_stretch (1.55; with the relaxation, on by default, within relaxed_max_stretch 1.3)
set(_ground_line "${_frame_line}")
string(REPLACE "\\}" ",\"stretch_median\":[0-9.e-]+,\"stretch_p95\":[0-9.e-]+,\"stretch_max\":1(\\.[0-4][0-9]*|\\.5[0-5][0-9]*)?\\}"
       _ground_line "${_ground_line}")
tessera_cli_test(NAME "cli: terrain ground-anchored fly-through"
  REGEX "^${_ground_line}\n${_ground_line}\n\\{\"frame\":2,[^\n]*\"stable_faces\":(0\\.9[5-9][0-9]*|1)[,}]"
  COMMAND terrain ${_small} --anchor ground --path ${_o}/terrain_path.txt --frames-out ${_o}/terrain_frames --stats
          --threads 2)
# --max-stretch bounds the stretch every face ends with (float export may add a few 1e-6); --relax 0
# turns the relaxation off
string(REPLACE "\"stretch_max\":1(\\.[0-4][0-9]*|\\.5[0-5][0-9]*)?" "\"stretch_max\":1(\\.0[0-9]*|\\.1[0-4][0-9]*|\\.15(00[0-9]*)?)?"
       _ground_115 "${_ground_line}")
tessera_cli_test(NAME "cli: terrain ground-anchored max-stretch" REGEX "^${_ground_115}\n?$"
  COMMAND terrain ${_small} --anchor ground --camera oblique --max-stretch 1.15 --out ${_o}/terrain_ground_115.png --stats)
tessera_cli_test(NAME "cli: terrain ground-anchored without relaxation" REGEX "^${_ground_115}\n?$"
  COMMAND terrain ${_small} --anchor ground --camera oblique --max-stretch 1.15 --relax 0
          --out ${_o}/terrain_ground_norelax.png --stats)
tessera_cli_test(NAME "cli: terrain max-stretch out of range" CODE 1 REGEX "--max-stretch expects a number in \\[1, 2\\]"
  COMMAND terrain ${_small} --anchor ground --max-stretch 3 --out ${_o}/terrain_bad.png)
tessera_cli_test(NAME "cli: terrain relax without ground anchoring" CODE 1 REGEX "apply to --anchor ground only"
  COMMAND terrain ${_small} --anchor screen --relax 2 --out ${_o}/terrain_bad.png)
tessera_cli_test(NAME "cli: terrain screen-space fly-through" REGEX "^${_frame_line}\n${_frame_line}\n${_frame_line}"
  COMMAND terrain ${_small} --anchor screen --path ${_o}/terrain_path.txt --frames-out ${_o}/terrain_frames_screen
          --stats)
tessera_cli_test(NAME "cli: terrain ground-anchored single frame" REGEX "^${_ground_line}\n?$"
  COMMAND terrain ${_small} --anchor ground --camera oblique --out ${_o}/terrain_ground.png --stats)
tessera_cli_test(NAME "cli: terrain ground-anchored empty view warns"
  REGEX "\"visible\":0,.*warning: terrain_session frame 0: no face is in view"
  COMMAND terrain ${_small} --anchor ground --eye 0,0,30 --target 0,0,60 --up 0,1,0 --out ${_o}/terrain_ground_empty.png
          --stats)
file(WRITE ${_o}/terrain_path_nan.txt "0 -45 12 0 -15 0 55\n0 nan 12 0 -15 0 55\n")
file(WRITE ${_o}/terrain_path_short.txt "0 -45 12 0 -15 0\n")
file(WRITE ${_o}/terrain_path_same.txt "0 -45 12 0 -15 0 55\n1 2 3 1 2 3 55\n")
file(WRITE ${_o}/terrain_path_fov.txt "0 -45 12 0 -15 0 0\n")
file(WRITE ${_o}/terrain_path_word.txt "0 -45 12 0 -15 zero 55\n")
file(WRITE ${_o}/terrain_path_empty.txt "# nothing\n")
foreach(_case
    "path with NaN|--path ${_o}/terrain_path_nan.txt|line 2: numbers must be finite"
    "path line too short|--path ${_o}/terrain_path_short.txt|line 1: expected 7 numbers .*got 6"
    "path eye equals target|--path ${_o}/terrain_path_same.txt|line 2: camera eye .* equals its target"
    "path fov zero|--path ${_o}/terrain_path_fov.txt|line 1: camera fov_y_degrees must be in"
    "path word|--path ${_o}/terrain_path_word.txt|line 1: 'zero' is not a number"
    "empty path|--path ${_o}/terrain_path_empty.txt|no camera in the file"
    "missing path|--path ${_o}/no_such_path.txt|no_such_path"
    "unknown anchor|--anchor sky|--anchor expects ground or screen, got 'sky'")
  string(REPLACE "|" ";" _parts "${_case}")
  list(GET _parts 0 _name)
  list(GET _parts 1 _args)
  list(GET _parts 2 _expect)
  separate_arguments(_args)
  tessera_cli_test(NAME "cli: terrain rejects ${_name}" CODE 1 REGEX "${_expect}"
    COMMAND terrain ${_small} ${_args} --frames-out ${_o}/terrain_bad_frames)
endforeach()
