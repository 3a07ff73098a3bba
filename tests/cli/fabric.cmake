# Command-line tests of `tessera fabric` and `tessera catmap` (paper 001).
set(_t $<TARGET_FILE:tessera_cli>)
set(_o ${TESSERA_CLI_OUT})

add_test(NAME "cli: fabric twill preset keeps 75/25 tones"
         COMMAND ${_t} fabric --preset twill --size 200 --out ${_o}/fabric_twill.png --stats --threads 2)
set_tests_properties("cli: fabric twill preset keeps 75/25 tones" PROPERTIES
  PASS_REGULAR_EXPRESSION "\"iterations\":31.*\"tone_shares\":\\[0.7500,0.2500\\]" FIXTURES_SETUP fabric_twill)

add_test(NAME "cli: fabric from a palette, tiled"
         COMMAND ${_t} fabric --palette "#202020:3,#c0a080:1" --layout cells --size 300x120 --tile 100
                 --iterations 60 --generations 2 --K 3 --N 6 --seed 7 --out ${_o}/fabric_palette.png --stats)
set_tests_properties("cli: fabric from a palette, tiled" PROPERTIES
  PASS_REGULAR_EXPRESSION "\"width\":300,\"height\":120,\"tile\":100,\"iterations\":60,\"generations\":2"
  FIXTURES_SETUP fabric_palette)

add_test(NAME "cli: fabric from a source image"
         COMMAND ${_t} fabric --source ${_o}/fabric_twill.png --iterations 80 --size 200 --out ${_o}/fabric_source.png)
set_tests_properties("cli: fabric from a source image" PROPERTIES FIXTURES_REQUIRED fabric_twill)

add_test(NAME "cli: catmap jumps and reports period and timing"
         COMMAND ${_t} catmap --in ${_o}/fabric_twill.png --iterations -31 --out ${_o}/catmap_back.png --stats --repeat 3)
set_tests_properties("cli: catmap jumps and reports period and timing" PROPERTIES
  FIXTURES_REQUIRED fabric_twill PASS_REGULAR_EXPRESSION "\"period\":150,\"catmap_ms\":[0-9.e+-]+,\"repeat\":3")

add_test(NAME "cli: catmap period of 400 is 300" COMMAND ${_t} catmap --period 400)
set_tests_properties("cli: catmap period of 400 is 300" PROPERTIES PASS_REGULAR_EXPRESSION "^300\n$")

add_test(NAME "cli: catmap period of 10^12" COMMAND ${_t} catmap --period 1000000000000 --stats)
set_tests_properties("cli: catmap period of 10^12" PROPERTIES PASS_REGULAR_EXPRESSION "\"period\":750000000000")

add_test(NAME "cli: catmap rejects N = 0" COMMAND ${_t} catmap --period 0)
set_tests_properties("cli: catmap rejects N = 0" PROPERTIES WILL_FAIL TRUE)

add_test(NAME "cli: catmap rejects a non-square image"
         COMMAND ${_t} catmap --in ${_o}/fabric_palette.png --iterations 3 --out ${_o}/never.png)
set_tests_properties("cli: catmap rejects a non-square image" PROPERTIES WILL_FAIL TRUE FIXTURES_REQUIRED fabric_palette)
add_test(NAME "cli: catmap maps square tiles of a non-square image"
         COMMAND ${_t} catmap --in ${_o}/fabric_palette.png --iterations 3 --non-square tiles --out ${_o}/catmap_tiles.png)
set_tests_properties("cli: catmap maps square tiles of a non-square image" PROPERTIES FIXTURES_REQUIRED fabric_palette)

add_test(NAME "cli: fabric rejects an empty palette" COMMAND ${_t} fabric --palette "" --out ${_o}/never.png)
set_tests_properties("cli: fabric rejects an empty palette" PROPERTIES WILL_FAIL TRUE)

add_test(NAME "cli: fabric rejects K out of range"
         COMMAND ${_t} fabric --preset tweed --K 9 --out ${_o}/never.png)
set_tests_properties("cli: fabric rejects K out of range" PROPERTIES WILL_FAIL TRUE)
