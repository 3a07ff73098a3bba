# Command-line tests of `tessera fabric`, `tessera catmap` and `tessera tones` (paper 001). Each
# checks the exit code and the output (tessera_cli_test, see README.md here); failures check the
# message names the problem.
set(_o ${TESSERA_CLI_OUT}/fabric)
file(MAKE_DIRECTORY ${_o})

# --- tessera fabric ------------------------------------------------------------------------------
tessera_cli_test(NAME "cli: fabric twill preset keeps 75/25 tones"
                 REGEX "^{\"command\":\"fabric\",\"width\":200,\"height\":200,\"tile\":0,\"iterations\":31,[^\n]*\"tone_shares\":\\[0.7500,0.2500\\]}\n$"
                 COMMAND fabric --preset twill --size 200 --out ${_o}/twill.png --stats --threads 2)
set_tests_properties("cli: fabric twill preset keeps 75/25 tones" PROPERTIES FIXTURES_SETUP fabric_twill)
tessera_cli_test(NAME "cli: fabric from a palette, tiled"
                 REGEX "\"width\":300,\"height\":120,\"tile\":100,\"iterations\":60,\"generations\":2,"
                 COMMAND fabric --palette "#202020:3,#c0a080:1" --layout cells --size 300x120 --tile 100
                         --iterations 60 --generations 2 --K 3 --N 6 --seed 7 --out ${_o}/palette.png --stats)
set_tests_properties("cli: fabric from a palette, tiled" PROPERTIES FIXTURES_SETUP fabric_palette)
# a source image: the output takes its size, and its tones (a permutation of the twill's) keep their shares
tessera_cli_test(NAME "cli: fabric from a source image"
                 REGEX "\"width\":200,\"height\":200,\"tile\":0,\"iterations\":80,\"generations\":0,[^\n]*\"tone_shares\":\\[0.7500,0.2500\\]"
                 COMMAND fabric --source ${_o}/twill.png --iterations 80 --out ${_o}/source.png --stats)
set_tests_properties("cli: fabric from a source image" PROPERTIES FIXTURES_REQUIRED fabric_twill)
tessera_cli_test(NAME "cli: fabric from a non-square source with --fit center"
                 REGEX "wrote .*source_center.png \\(90 x 70\\)"
                 COMMAND fabric --source ${_o}/palette.png --fit center --size 90x70 --iterations 9
                         --out ${_o}/source_center.png)
set_tests_properties("cli: fabric from a non-square source with --fit center" PROPERTIES FIXTURES_REQUIRED fabric_palette)

function(_fabric_fail name regex)
  tessera_cli_test(NAME "cli: fabric rejects ${name}" CODE 1 REGEX "${regex}" COMMAND fabric ${ARGN})
endfunction()
_fabric_fail("an empty palette" "palette entry '': missing ':weight'" --palette= --out ${_o}/never.png)
_fabric_fail("weights whose sum overflows" "proportions sum to inf" --palette "#000000:1e308,#ffffff:1e308"
             --out ${_o}/never.png)
_fabric_fail("K out of range" "--K expects an integer in \\[0, 8\\], got '9'" --preset tweed --K 9 --out ${_o}/never.png)
_fabric_fail("N out of range" "--N expects an integer in \\[1, 8\\], got '0'" --preset tweed --N 0 --out ${_o}/never.png)
_fabric_fail("negative generations" "--generations expects an integer in \\[0, 10000\\], got '-1'" --preset tweed
             --generations -1 --out ${_o}/never.png)
_fabric_fail("a huge tile" "--tile expects an integer in \\[0, 8192\\], got '9000'" --preset twill --tile 9000
             --out ${_o}/never.png)
_fabric_fail("a negative feature size" "--feature expects an integer in \\[0, 8192\\], got '-4'" --palette "#000000:1"
             --feature -4 --out ${_o}/never.png)
_fabric_fail("non-integer iterations" "--iterations expects an integer, got '2.5'" --preset twill --iterations 2.5
             --out ${_o}/never.png)
_fabric_fail("a family that is not integers" "--family expects two integers a,b with \\|a\\|, \\|b\\| <= 2\\^53, got '1e300,1'"
             --preset twill --family 1e300,1 --out ${_o}/never.png)
_fabric_fail("a huge size" "--size expects at most 16384 per side and 67108864 in all, got '1000000'" --preset twill
             --size 1000000 --out ${_o}/never.png)
_fabric_fail("a size whose square is too large" "generated at 16384 x 16384 .*give --tile T <= 8192" --preset twill
             --size 16384x2 --out ${_o}/never.png)
_fabric_fail("an unknown --fit" "--fit expects reject, center or crop, got 'stretch'" --preset twill --fit stretch
             --out ${_o}/never.png)
_fabric_fail("a non-square source by default" "the source is 300 x 120 but the fabric square is 300 x 300.*options.fit"
             --source ${_o}/palette.png --out ${_o}/never.png)
set_tests_properties("cli: fabric rejects a non-square source by default" PROPERTIES FIXTURES_REQUIRED fabric_palette)

# --- tessera catmap ------------------------------------------------------------------------------
tessera_cli_test(NAME "cli: catmap jumps and reports period and timing"
                 REGEX "\"side\":200,\"period\":150,\"catmap_ms\":[0-9.e+-]+,\"repeat\":3"
                 COMMAND catmap --in ${_o}/twill.png --iterations -31 --out ${_o}/catmap_back.png --stats --repeat 3)
set_tests_properties("cli: catmap jumps and reports period and timing" PROPERTIES FIXTURES_REQUIRED fabric_twill)
tessera_cli_test(NAME "cli: catmap period of 400 is 300" REGEX "^300\n$" COMMAND catmap --period 400)
tessera_cli_test(NAME "cli: catmap period of 10^12" REGEX "\"N\":1000000000000,\"period\":750000000000,"
                 COMMAND catmap --period 1000000000000 --stats)
# --non-square: the period reported is that of the squares mapped (tiles: gcd(300, 120) = 60, or --tile)
tessera_cli_test(NAME "cli: catmap maps square tiles of a non-square image"
                 REGEX "\"width\":300,\"height\":120,\"iterations\":3,\"side\":60,\"period\":60,"
                 COMMAND catmap --in ${_o}/palette.png --iterations 3 --non-square tiles --out ${_o}/catmap_tiles.png --stats)
tessera_cli_test(NAME "cli: catmap period of --tile squares"
                 REGEX "\"side\":40,\"period\":30,"
                 COMMAND catmap --in ${_o}/palette.png --iterations 3 --non-square tiles --tile 40
                         --out ${_o}/catmap_tiles40.png --stats)
tessera_cli_test(NAME "cli: catmap period of the centred square"
                 REGEX "on 120 x 120 squares. period 60\\)"
                 COMMAND catmap --in ${_o}/palette.png --iterations 3 --non-square center --out ${_o}/catmap_center.png)
set_tests_properties("cli: catmap maps square tiles of a non-square image" "cli: catmap period of --tile squares"
                     "cli: catmap period of the centred square" PROPERTIES FIXTURES_REQUIRED fabric_palette)

function(_catmap_fail name regex)
  tessera_cli_test(NAME "cli: catmap rejects ${name}" CODE 1 REGEX "${regex}" COMMAND catmap ${ARGN})
endfunction()
_catmap_fail("N = 0" "--period expects an integer in \\[1, 4611686018427387904\\], got '0'" --period 0)
_catmap_fail("a family that is not integers" "--family expects two integers" --period 10 --family 1.5,2)
_catmap_fail("a non-square image" "the image is 300 x 120 but the cat map needs a square image"
             --in ${_o}/palette.png --iterations 3 --out ${_o}/never.png)
_catmap_fail("a negative tile" "--tile expects an integer in \\[0, 16384\\], got '-1'" --in ${_o}/palette.png
             --non-square tiles --tile -1 --out ${_o}/never.png)
_catmap_fail("a tile larger than the image" "options.tile_size must be 0 \\(gcd of the sides\\) or in \\[1, 120\\].*got 200"
             --in ${_o}/palette.png --non-square tiles --tile 200 --out ${_o}/never.png)
set_tests_properties("cli: catmap rejects a non-square image" "cli: catmap rejects a negative tile"
                     "cli: catmap rejects a tile larger than the image" PROPERTIES FIXTURES_REQUIRED fabric_palette)

# --- tessera tones -------------------------------------------------------------------------------
tessera_cli_test(NAME "cli: tones of the twill"
                 REGEX "twill.png: 200 x 200, dominant tones \\(k-means\\)\n  #000000   75.00 %\n  #ffffff   25.00 %\n--palette \"#000000:0.7500,#ffffff:0.2500\"\n$"
                 COMMAND tones ${_o}/twill.png)
tessera_cli_test(NAME "cli: tones --stats"
                 REGEX "^{\"command\":\"tones\",[^\n]*\"width\":200,\"height\":200,\"method\":\"dominant\",\"tones\":\\[{\"color\":\"#000000\",\"share\":0.7500},{\"color\":\"#ffffff\",\"share\":0.2500}\\],\"palette\":\"#000000:0.7500,#ffffff:0.2500\",\"tones_ms\":[0-9.e+-]+}\n$"
                 COMMAND tones ${_o}/twill.png --stats --max 6)
tessera_cli_test(NAME "cli: tones against a given palette"
                 REGEX "nearest to each tone\n  #202020   75.00 %\n  #e0e0e0   25.00 %\n"
                 COMMAND tones ${_o}/twill.png --palette "#202020:1,#e0e0e0:1")
tessera_cli_test(NAME "cli: tones of a perturbed cloth"  # 4 tones found, shares that sum to 1
                 REGEX "palette.png: 300 x 120, dominant tones[^\n]*\n(  #[0-9a-f]+ +[0-9.]+ %\n)(  #[0-9a-f]+ +[0-9.]+ %\n)(  #[0-9a-f]+ +[0-9.]+ %\n)(  #[0-9a-f]+ +[0-9.]+ %\n)--palette"
                 COMMAND tones ${_o}/palette.png)
set_tests_properties("cli: tones of the twill" "cli: tones --stats" "cli: tones against a given palette"
                     PROPERTIES FIXTURES_REQUIRED fabric_twill)
set_tests_properties("cli: tones of a perturbed cloth" PROPERTIES FIXTURES_REQUIRED fabric_palette)
tessera_cli_test(NAME "cli: tones --help" REGEX "usage: tessera tones --in IN.png" COMMAND tones --help)
tessera_cli_test(NAME "cli: tones rejects no image" CODE 1 REGEX "expects exactly one image IN.png" COMMAND tones)
tessera_cli_test(NAME "cli: tones rejects --max 0" CODE 1 REGEX "--max expects an integer in \\[1, 64\\], got '0'"
                 COMMAND tones ${_o}/twill.png --max 0)
tessera_cli_test(NAME "cli: tones rejects a missing file" CODE 1 REGEX "missing.png" COMMAND tones ${_o}/missing.png)
tessera_cli_test(NAME "cli: tones rejects a bad palette" CODE 1 REGEX "palette entry '#12345:1'"
                 COMMAND tones ${_o}/twill.png --palette "#12345:1")
