# CLI tests of the foundation commands: tessera sample, info and convert (success and failure).
set(_o ${TESSERA_CLI_OUT}/foundation)
file(MAKE_DIRECTORY ${_o})

# A small OBJ written at configure time: a uv-mapped quad plus a separate triangle (2 components).
file(WRITE ${_o}/two_parts.obj
  "# two components\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 5 5 5\nv 6 5 5\nv 5 6 6\n"
  "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\nf 5/1 6/2 7/3\n")

# success: sample -> info -> convert -> info
tessera_cli_test(NAME "cli: sample bricks" REGEX "wrote .*bricks.png \\(bricks, 96 x 64, seed 3\\)"
                 COMMAND sample bricks --size 96x64 --seed 3 --out ${_o}/bricks.png)
set_tests_properties("cli: sample bricks" PROPERTIES FIXTURES_SETUP foundation_png)
foreach(_kind grass sand rock cells weave dots)
  tessera_cli_test(NAME "cli: sample ${_kind} --stats"
                   REGEX "^{\"kind\":\"${_kind}\",\"width\":32,\"height\":32,\"seed\":1,[^\n]*}\n$"
                   COMMAND sample ${_kind} --size 32 --out ${_o}/${_kind}.png --stats)
endforeach()
tessera_cli_test(NAME "cli: info png" REGEX "size +96 x 64\n +channels +3 \\(RGB\\)\n +bit depth +8"
                 COMMAND info ${_o}/bricks.png)
set_tests_properties("cli: info png" PROPERTIES FIXTURES_REQUIRED foundation_png)
tessera_cli_test(NAME "cli: info png --stats" REGEX "^{[^\n]*\"width\":96,\"height\":64,\"channels\":3,\"bit_depth\":8,[^\n]*}\n$"
                 COMMAND info ${_o}/bricks.png --stats)
set_tests_properties("cli: info png --stats" PROPERTIES FIXTURES_REQUIRED foundation_png)
tessera_cli_test(NAME "cli: convert png to 16-bit grey" REGEX "1 channel, 16-bit"
                 COMMAND convert ${_o}/bricks.png ${_o}/bricks16.png --channels 1 --depth 16)
set_tests_properties("cli: convert png to 16-bit grey" PROPERTIES FIXTURES_REQUIRED foundation_png
                     FIXTURES_SETUP foundation_png16)
tessera_cli_test(NAME "cli: info converted png" REGEX "\"channels\":1,\"bit_depth\":16"
                 COMMAND info ${_o}/bricks16.png --stats)
set_tests_properties("cli: info converted png" PROPERTIES FIXTURES_REQUIRED foundation_png16)
tessera_cli_test(NAME "cli: info obj" REGEX "vertices +7\n +faces +3 triangles\n +components +2\n +boundary edges +7\n +non-manifold edges +0\n +bounding box +\\(0, 0, 0\\) - \\(6, 6, 6\\)\n +uvs +yes"
                 COMMAND info ${_o}/two_parts.obj)
tessera_cli_test(NAME "cli: convert obj to binary ply" REGEX "7 vertices, 3 triangles, with uvs"
                 COMMAND convert ${_o}/two_parts.obj ${_o}/two_parts.ply --binary)
set_tests_properties("cli: convert obj to binary ply" PROPERTIES FIXTURES_SETUP foundation_ply)
tessera_cli_test(NAME "cli: info ply --stats" REGEX "^{\"file\":\"[^\"]*two_parts.ply\",\"kind\":\"mesh\",\"format\":\"ply\",\"vertices\":7,\"faces\":3,\"components\":2,\"boundary_edges\":7,\"nonmanifold_edges\":0,\"bbox_min\":\\[0,0,0\\],\"bbox_max\":\\[6,6,6\\],\"has_uvs\":true,[^\n]*}\n$"
                 COMMAND info ${_o}/two_parts.ply --stats)
set_tests_properties("cli: info ply --stats" PROPERTIES FIXTURES_REQUIRED foundation_ply)
tessera_cli_test(NAME "cli: convert ply to off" REGEX "OFF cannot hold the uvs"
                 COMMAND convert ${_o}/two_parts.ply ${_o}/two_parts.off)
set_tests_properties("cli: convert ply to off" PROPERTIES FIXTURES_REQUIRED foundation_ply)
# every command answers --help with its usage line (exit 0)
foreach(_cmd info convert sample synth quilt "wang build" "wang tile" fabric catmap terrain exemplar mesh-quilt
        "geo-wang build" "geo-wang tile" render remesh)
  separate_arguments(_words UNIX_COMMAND "${_cmd}")
  tessera_cli_test(NAME "cli: ${_cmd} --help" REGEX "usage: tessera ${_cmd}" COMMAND ${_words} --help)
endforeach()
tessera_cli_test(NAME "cli: overview lists every command" REGEX "catmap.*convert.*exemplar.*fabric.*geo-wang build.*info.*mesh-quilt.*quilt.*render.*sample.*synth.*terrain.*wang build"
                 COMMAND --help)

# failures: exit code 1 with a message naming the problem (2 for unknown options)
function(_foundation_fail name code regex)
  tessera_cli_test(NAME "cli: ${name}" CODE ${code} REGEX "${regex}" COMMAND ${ARGN})
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
_foundation_fail("sample huge size" 1 "--size expects at most 16384 per side" sample grass --size 99999x4 --out ${_o}/x.png)
_foundation_fail("sample bad seed" 2 "--seed expects an integer in \\[0, 2\\^64 - 1\\], got 'abc'" sample grass --seed abc --out ${_o}/x.png)
_foundation_fail("negative seed" 2 "--seed expects an integer" sample grass --seed -3 --out ${_o}/x.png)
_foundation_fail("bad threads" 2 "--threads expects an integer in \\[0, 1024\\], got '5000'" synth --exemplar sand --size 8 --threads 5000 --out ${_o}/x.png)
_foundation_fail("threads not a number" 2 "--threads expects an integer, got 'abc'" synth --exemplar sand --size 8 --threads abc --out ${_o}/x.png)
_foundation_fail("bad repeat" 2 "--repeat expects an integer in \\[1, 100000\\], got '0'" sample grass --repeat 0 --out ${_o}/x.png)
_foundation_fail("size not finite" 1 "--size expects WxH, got 'nanx4'" sample grass --size nanx4 --out ${_o}/x.png)
_foundation_fail("sample not png" 1 "must name a .png file" sample grass --out ${_o}/x.jpg)
set_tests_properties("cli: info unknown option" "cli: convert image to mesh" "cli: convert bad channels"
                     "cli: convert bad depth" PROPERTIES FIXTURES_REQUIRED foundation_png)

# a file that is not a PNG is a parse error naming the file and byte, not a crash
file(WRITE ${_o}/not_a.png "P3 2 2 255\n")
_foundation_fail("info not a png" 1 "parse_error: .*not_a.png, byte 0: not a PNG file" info ${_o}/not_a.png)
