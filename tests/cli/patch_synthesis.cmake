# tessera synth: outputs, --stats keys, windows, source maps, seam cuts and the documented bad inputs.
# Every test checks the exit code and the output (tessera_cli_test, tests/CMakeLists.txt).
set(_o ${TESSERA_CLI_OUT}/synth)
file(MAKE_DIRECTORY ${_o})
set(_num "[0-9.e+-]+")

tessera_cli_test(NAME "cli: synth with stats"
  REGEX "^\\{\"command\":\"synth\",\"width\":96,\"height\":80,[^\n]*\"patch\":[0-9]+,[^\n]*\"overlap\":[0-9]+,[^\n]*\"preprocess_ms\":${_num},\"synthesis_ms\":${_num},[^\n]*\"empty_intersections\":[0-9]+,[^\n]*\"neighborhood_energy\":${_num}[^\n]*\\}\n$"
  COMMAND synth --exemplar sand --exemplar-size 64 --size 96x80 --out ${_o}/sand.png --stats --repeat 3 --threads 2)
tessera_cli_test(NAME "cli: synth a window with a source map and seam cuts"
  REGEX "wrote .*bricks_window.png \\(90 x 60, patch 16 x 16, overlap 4"
  COMMAND synth --exemplar bricks --exemplar-size 64 --window -70,1000000,90,60 --patch 16 --overlap 4 --seams cut
          --source-map ${_o}/bricks_source.png --out ${_o}/bricks_window.png --seed 9)
set_tests_properties("cli: synth a window with a source map and seam cuts" PROPERTIES FIXTURES_SETUP synth_window)
tessera_cli_test(NAME "cli: synth reads its own PNG output as an exemplar"
  REGEX "\"exemplar_width\":90,\"exemplar_height\":60,\"patch\":12,\"patch_height\":10,\"overlap\":3"
  COMMAND synth --exemplar ${_o}/bricks_window.png --size 40x30 --patch 12x10 --overlap 3 --out ${_o}/again.png --stats)
set_tests_properties("cli: synth reads its own PNG output as an exemplar" PROPERTIES FIXTURES_REQUIRED synth_window)
tessera_cli_test(NAME "cli: synth a window at the edge of the texture plane"
  REGEX "wrote .*edge.png \\(8 x 8,"
  COMMAND synth --exemplar sand --exemplar-size 48 --window 4503599627370488,-4503599627370496,8,8 --out ${_o}/edge.png)
tessera_cli_test(NAME "cli: synth help" REGEX "--window X,Y,W,H" COMMAND synth --help)

# bad input: exit code 1 and a message naming the option or parameter and the value
tessera_cli_test(NAME "cli: synth without --size fails" CODE 1 REGEX "tessera synth: .*missing required option --size"
  COMMAND synth --exemplar sand --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with an empty size fails" CODE 1 REGEX "--size expects positive integers WxH, got '0x10'"
  COMMAND synth --exemplar sand --size 0x10 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with an oversized output fails" CODE 1 REGEX "--size expects at most 32768 per side"
  COMMAND synth --exemplar sand --size 40000x8 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with an unknown exemplar fails" CODE 1 REGEX "neither a readable file"
  COMMAND synth --exemplar nosuch --size 8x8 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with patches too large for the exemplar fails" CODE 1 REGEX "do not fit the 48 x 48 exemplar"
  COMMAND synth --exemplar sand --exemplar-size 48 --patch 40 --overlap 10 --size 8x8 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with an overlap wider than the patch fails" CODE 1 REGEX "overlap 9 is invalid \\(patch sides >= 2, 1 <= overlap <= patch side\\)"
  COMMAND synth --exemplar sand --exemplar-size 48 --patch 8 --overlap 9 --size 8x8 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with a negative overlap fails" CODE 1 REGEX "--overlap expects an integer in \\[0, 32768\\], got '-2'"
  COMMAND synth --exemplar sand --exemplar-size 48 --overlap -2 --size 8x8 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with a bad exemplar size fails" CODE 1 REGEX "--exemplar-size expects an integer in \\[8, 4096\\], got '5'"
  COMMAND synth --exemplar sand --exemplar-size 5 --size 8x8 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with a window off the texture plane fails" CODE 1
  REGEX "window at origin \\(4503599627370490, 0\\) of 8 x 8 leaves the supported texture plane"
  COMMAND synth --exemplar sand --exemplar-size 48 --window 4503599627370490,0,8,8 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with a window beyond the index range fails" CODE 1
  REGEX "--window expects integers X,Y,W,H with \\|X\\| and \\|Y\\| at most 2\\^52 \\(the texture plane\\), got '1e300,0,8,8'"
  COMMAND synth --exemplar sand --window 1e300,0,8,8 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with a window origin past 2^63 fails" CODE 1 REGEX "--window expects integers X,Y,W,H with \\|X\\| and \\|Y\\|"
  COMMAND synth --exemplar sand --window 0,-9300000000000000000,8,8 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with a huge window size fails" CODE 1
  REGEX "--window expects integers X,Y,W,H with W and H in \\[1, 32768\\] and W x H at most 2\\^28, got '0,0,1e12,8'"
  COMMAND synth --exemplar sand --window 0,0,1e12,8 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with a window too many pixels fails" CODE 1 REGEX "W x H at most 2\\^28, got '0,0,32768,32768'"
  COMMAND synth --exemplar sand --window 0,0,32768,32768 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with a fractional window fails" CODE 1 REGEX "--window expects integers X,Y,W,H with no fractions, got '0.5,0,8,8'"
  COMMAND synth --exemplar sand --window 0.5,0,8,8 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with an empty window fails" CODE 1 REGEX "W and H in \\[1, 32768\\]"
  COMMAND synth --exemplar sand --window 3,4,0,8 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with a non-finite window fails" CODE 1 REGEX "--window expects 4 comma-separated numbers, got 'nan,0,8,8'"
  COMMAND synth --exemplar sand --window nan,0,8,8 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with a bad window fails" CODE 1 REGEX "--window expects 4 comma-separated numbers, got '1,2,3'"
  COMMAND synth --exemplar sand --window 1,2,3 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with an unknown seam mode fails" CODE 1 REGEX "--seams expects feather or cut, got 'zigzag'"
  COMMAND synth --exemplar sand --size 8x8 --seams zigzag --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with a bad seed fails" CODE 2 REGEX "--seed expects an integer in \\[0, 2\\^64 - 1\\], got '-3'"
  COMMAND synth --exemplar sand --size 8x8 --seed -3 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with an unknown fallback fails" CODE 1 REGEX "--fallback expects estimate, sets or overlap, got 'random'"
  COMMAND synth --exemplar sand --size 8x8 --fallback random --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth with a negative feather band fails" CODE 1 REGEX "--feather expects an integer in \\[0, 32768\\], got '-1'"
  COMMAND synth --exemplar sand --size 8x8 --feather -1 --out ${_o}/bad.png)
tessera_cli_test(NAME "cli: synth --stats reports the feather band, clamped to the overlap"
  REGEX "\"overlap\":4,\"seams\":\"feather\",\"feather_width\":4,"
  COMMAND synth --exemplar sand --exemplar-size 48 --size 64x64 --patch 12 --overlap 4 --feather 9 --stats --out ${_o}/band.png)
tessera_cli_test(NAME "cli: synth --stats reports the fallback rate and the structure check"
  REGEX "\"fallback_rate\":[0-9.e-]+.*\"fill_overlap_rms\":[0-9.e-]+.*\"pitch_alignment\":[0-9.e-]+.*\"structure_warning\":"
  COMMAND synth --exemplar bricks --exemplar-size 64 --size 96x96 --fallback sets --candidates 4 --stats --out ${_o}/fallback.png)
tessera_cli_test(NAME "cli: metrics of an image against its exemplar"
  REGEX "\"energy_1x\":[0-9.e-]+,\"energy_2x\":[0-9.e-]+,\"histogram_distance\":[0-9.e-]+,\"repetition\":"
  COMMAND metrics --exemplar sand --exemplar-size 48 --in sand --window 5 --levels 2 --step 4)
tessera_cli_test(NAME "cli: synth --stats reports the seam steps and a grid warning"
  REGEX "\"seam_gradient_ratio\":[0-9.e-]+,\"seam_step_ratio\":[0-9.e-]+,\"seam_warning\":\""
  COMMAND synth --exemplar rock --exemplar-size 64 --size 128x128 --stats --out ${_o}/steps.png)
tessera_cli_test(NAME "cli: metrics --patch measures the seams of a patch grid"
  REGEX "\"repetition\":[0-9.e-]+,\"seam_gradient_ratio\":[0-9.e-]+,\"seam_step_ratio\":[0-9.e-]+,\"metrics_ms\""
  COMMAND metrics --exemplar sand --exemplar-size 48 --in sand --window 5 --levels 1 --step 4 --patch 16 --overlap 4)
tessera_cli_test(NAME "cli: metrics with an overlap wider than the patch fails" CODE 1
  REGEX "--overlap expects an integer in \\[0, 16\\], got '20'"
  COMMAND metrics --exemplar sand --exemplar-size 48 --in sand --patch 16 --overlap 20)
