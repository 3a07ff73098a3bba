# CLI tests of the foundation commands: tessera sample, info and convert (success and failure).
set(_t $<TARGET_FILE:tessera_cli>)
set(_o ${TESSERA_CLI_OUT}/foundation)
file(MAKE_DIRECTORY ${_o})
set(_expect_script ${CMAKE_CURRENT_LIST_DIR}/support/expect_exit.cmake)

# A small OBJ written at configure time: a uv-mapped quad plus a separate triangle (2 components).
file(WRITE ${_o}/two_parts.obj
  "# two components\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 5 5 5\nv 6 5 5\nv 5 6 6\n"
  "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\nf 5/1 6/2 7/3\n")

# success: sample -> info -> convert -> info
add_test(NAME "cli: sample bricks" COMMAND ${_t} sample bricks --size 96x64 --seed 3 --out ${_o}/bricks.png)
set_tests_properties("cli: sample bricks" PROPERTIES FIXTURES_SETUP foundation_png
                     PASS_REGULAR_EXPRESSION "wrote .*bricks.png \\(bricks, 96 x 64, seed 3\\)")
foreach(_kind grass sand rock cells weave dots)
  add_test(NAME "cli: sample ${_kind} --stats" COMMAND ${_t} sample ${_kind} --size 32 --out ${_o}/${_kind}.png --stats)
  set_tests_properties("cli: sample ${_kind} --stats" PROPERTIES
                       PASS_REGULAR_EXPRESSION "^{\"kind\":\"${_kind}\",\"width\":32,\"height\":32,\"seed\":1,[^\n]*}\n$")
endforeach()
add_test(NAME "cli: info png" COMMAND ${_t} info ${_o}/bricks.png)
set_tests_properties("cli: info png" PROPERTIES FIXTURES_REQUIRED foundation_png
                     PASS_REGULAR_EXPRESSION "size +96 x 64\n +channels +3 \\(RGB\\)\n +bit depth +8")
add_test(NAME "cli: info png --stats" COMMAND ${_t} info ${_o}/bricks.png --stats)
set_tests_properties("cli: info png --stats" PROPERTIES FIXTURES_REQUIRED foundation_png
                     PASS_REGULAR_EXPRESSION "^{[^\n]*\"width\":96,\"height\":64,\"channels\":3,\"bit_depth\":8,[^\n]*}\n$")
add_test(NAME "cli: convert png to 16-bit grey" COMMAND ${_t} convert ${_o}/bricks.png ${_o}/bricks16.png --channels 1 --depth 16)
set_tests_properties("cli: convert png to 16-bit grey" PROPERTIES FIXTURES_REQUIRED foundation_png
                     FIXTURES_SETUP foundation_png16 PASS_REGULAR_EXPRESSION "1 channel, 16-bit")
add_test(NAME "cli: info converted png" COMMAND ${_t} info ${_o}/bricks16.png --stats)
set_tests_properties("cli: info converted png" PROPERTIES FIXTURES_REQUIRED foundation_png16
                     PASS_REGULAR_EXPRESSION "\"channels\":1,\"bit_depth\":16")
add_test(NAME "cli: info obj" COMMAND ${_t} info ${_o}/two_parts.obj)
set_tests_properties("cli: info obj" PROPERTIES PASS_REGULAR_EXPRESSION
                     "vertices +7\n +faces +3 triangles\n +components +2\n +boundary edges +7\n +non-manifold edges +0\n +bounding box +\\(0, 0, 0\\) - \\(6, 6, 6\\)\n +uvs +yes")
add_test(NAME "cli: convert obj to binary ply" COMMAND ${_t} convert ${_o}/two_parts.obj ${_o}/two_parts.ply --binary)
set_tests_properties("cli: convert obj to binary ply" PROPERTIES FIXTURES_SETUP foundation_ply
                     PASS_REGULAR_EXPRESSION "7 vertices, 3 triangles, with uvs")
add_test(NAME "cli: info ply --stats" COMMAND ${_t} info ${_o}/two_parts.ply --stats)
set_tests_properties("cli: info ply --stats" PROPERTIES FIXTURES_REQUIRED foundation_ply PASS_REGULAR_EXPRESSION
                     "^{\"file\":\"[^\"]*two_parts.ply\",\"kind\":\"mesh\",\"format\":\"ply\",\"vertices\":7,\"faces\":3,\"components\":2,\"boundary_edges\":7,\"nonmanifold_edges\":0,\"bbox_min\":\\[0,0,0\\],\"bbox_max\":\\[6,6,6\\],\"has_uvs\":true,[^\n]*}\n$")
add_test(NAME "cli: convert ply to off" COMMAND ${_t} convert ${_o}/two_parts.ply ${_o}/two_parts.off)
set_tests_properties("cli: convert ply to off" PROPERTIES FIXTURES_REQUIRED foundation_ply
                     PASS_REGULAR_EXPRESSION "OFF cannot hold the uvs")
add_test(NAME "cli: info --help" COMMAND ${_t} info --help)
set_tests_properties("cli: info --help" PROPERTIES PASS_REGULAR_EXPRESSION "usage: tessera info FILE")

# failures: exit code 1 with a message naming the problem (2 for unknown options)
function(_foundation_fail name code regex)
  add_test(NAME "cli: ${name}" COMMAND ${CMAKE_COMMAND} -DCODE=${code} "-DREGEX=${regex}" -P ${_expect_script} -- ${_t} ${ARGN})
endfunction()
_foundation_fail("info missing file" 1 "io_error: .*missing.png: cannot open" info ${_o}/missing.png)
_foundation_fail("info unknown extension" 1 "unknown file type" info ${_o}/two_parts.stl)
_foundation_fail("info without a file" 1 "expects exactly one FILE" info)
_foundation_fail("info unknown option" 2 "unknown option --bogus" info --bogus ${_o}/bricks.png)
_foundation_fail("convert image to mesh" 1 "cannot convert between an image and a mesh" convert ${_o}/bricks.png ${_o}/x.obj)
_foundation_fail("convert bad channels" 1 "--channels must be 1, 2, 3 or 4, got 7" convert ${_o}/bricks.png ${_o}/x.png --channels 7)
_foundation_fail("convert bad depth" 1 "--depth must be 8 or 16, got 12" convert ${_o}/bricks.png ${_o}/x.png --depth 12)
_foundation_fail("convert depth on a mesh" 1 "apply to PNG images only" convert ${_o}/two_parts.obj ${_o}/x.ply --depth 8)
_foundation_fail("convert binary to obj" 1 "--binary applies to .ply output only" convert ${_o}/two_parts.obj ${_o}/x.obj --binary)
_foundation_fail("convert unknown output" 1 "x.stl: unknown" convert ${_o}/two_parts.obj ${_o}/x.stl)
_foundation_fail("convert missing input" 1 "io_error" convert ${_o}/missing.obj ${_o}/x.ply)
_foundation_fail("sample unknown kind" 1 "unknown exemplar kind 'plaid'" sample plaid --out ${_o}/x.png)
_foundation_fail("sample without --out" 1 "missing required option --out" sample grass)
_foundation_fail("sample bad size" 1 "--size expects positive integers WxH, got '0x4'" sample grass --size 0x4 --out ${_o}/x.png)
_foundation_fail("sample huge size" 1 "limited to 16384" sample grass --size 99999x4 --out ${_o}/x.png)
_foundation_fail("sample bad seed" 1 "--seed expects an integer" sample grass --seed abc --out ${_o}/x.png)
_foundation_fail("sample not png" 1 "must name a .png file" sample grass --out ${_o}/x.jpg)
set_tests_properties("cli: info unknown option" "cli: convert image to mesh" "cli: convert bad channels"
                     "cli: convert bad depth" PROPERTIES FIXTURES_REQUIRED foundation_png)

# a file that is not a PNG is a parse error naming the file and byte, not a crash
file(WRITE ${_o}/not_a.png "P3 2 2 255\n")
_foundation_fail("info not a png" 1 "parse_error: .*not_a.png, byte 0: not a PNG file" info ${_o}/not_a.png)
