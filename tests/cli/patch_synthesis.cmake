# tessera synth: outputs, --stats keys, windows, source maps, seam cuts and the documented bad inputs.
set(_t $<TARGET_FILE:tessera_cli>)
set(_o ${TESSERA_CLI_OUT}/synth)
file(MAKE_DIRECTORY ${_o})
set(_num "[0-9.e+-]+")

# tessera_synth_cli_bad(NAME EXPECT ARGS...): the command exits with 1 and prints EXPECT
function(tessera_synth_cli_bad name expect)
  add_test(NAME "cli: ${name} fails" COMMAND ${_t} ${ARGN})
  set_tests_properties("cli: ${name} fails" PROPERTIES WILL_FAIL TRUE)
  add_test(NAME "cli: ${name} explains" COMMAND ${_t} ${ARGN})
  set_tests_properties("cli: ${name} explains" PROPERTIES PASS_REGULAR_EXPRESSION "${expect}")
endfunction()

add_test(NAME "cli: synth with stats"
         COMMAND ${_t} synth --exemplar sand --exemplar-size 64 --size 96x80 --out ${_o}/sand.png --stats --repeat 3 --threads 2)
set_tests_properties("cli: synth with stats" PROPERTIES PASS_REGULAR_EXPRESSION
  "^\\{\"command\":\"synth\",\"width\":96,\"height\":80,.*\"patch\":[0-9]+,.*\"overlap\":[0-9]+,.*\"preprocess_ms\":${_num},\"synthesis_ms\":${_num},.*\"empty_intersections\":[0-9]+,.*\"neighborhood_energy\":${_num}")
add_test(NAME "cli: synth a window with a source map and seam cuts"
         COMMAND ${_t} synth --exemplar bricks --exemplar-size 64 --window -70,1000000,90,60 --patch 16 --overlap 4 --seams cut
                 --source-map ${_o}/bricks_source.png --out ${_o}/bricks_window.png --seed 9)
set_tests_properties("cli: synth a window with a source map and seam cuts" PROPERTIES FIXTURES_SETUP synth_window
  PASS_REGULAR_EXPRESSION "wrote .*bricks_window.png \\(90 x 60, patch 16 x 16, overlap 4")
add_test(NAME "cli: synth reads its own PNG output as an exemplar"
         COMMAND ${_t} synth --exemplar ${_o}/bricks_window.png --size 40x30 --patch 12x10 --overlap 3 --out ${_o}/again.png --stats)
set_tests_properties("cli: synth reads its own PNG output as an exemplar" PROPERTIES FIXTURES_REQUIRED synth_window
  PASS_REGULAR_EXPRESSION "\"exemplar_width\":90,\"exemplar_height\":60,\"patch\":12,\"patch_height\":10,\"overlap\":3")
add_test(NAME "cli: synth help" COMMAND ${_t} synth --help)
set_tests_properties("cli: synth help" PROPERTIES PASS_REGULAR_EXPRESSION "--window X,Y,W,H")

tessera_synth_cli_bad("synth without --size" "missing required option --size" synth --exemplar sand --out ${_o}/bad.png)
tessera_synth_cli_bad("synth with an empty size" "--size expects" synth --exemplar sand --size 0x10 --out ${_o}/bad.png)
tessera_synth_cli_bad("synth with an unknown exemplar" "neither a readable file" synth --exemplar nosuch --size 8x8 --out ${_o}/bad.png)
tessera_synth_cli_bad("synth with patches too large for the exemplar" "do not fit the 48 x 48 exemplar"
                      synth --exemplar sand --exemplar-size 48 --patch 40 --overlap 10 --size 8x8 --out ${_o}/bad.png)
tessera_synth_cli_bad("synth with an overlap wider than the patch" "1 <= overlap <= patch side"
                      synth --exemplar sand --exemplar-size 48 --patch 8 --overlap 9 --size 8x8 --out ${_o}/bad.png)
tessera_synth_cli_bad("synth with a window off the texture plane" "leaves the supported texture plane"
                      synth --exemplar sand --exemplar-size 48 --window 4503599627370490,0,8,8 --out ${_o}/bad.png)
tessera_synth_cli_bad("synth with an unknown seam mode" "--seams expects feather or cut" synth --exemplar sand --size 8x8 --seams zigzag
                      --out ${_o}/bad.png)
tessera_synth_cli_bad("synth with a bad window" "--window expects 4 comma-separated numbers" synth --exemplar sand --window 1,2,3
                      --out ${_o}/bad.png)
