# CLI tests of the one vocabulary (docs/cli.md): the canonical spellings, the older spellings kept as
# aliases (same output file, byte for byte), the options the registry adds to every command, and
# refused values named as the user spelled them. Inputs are tiny: every run takes milliseconds.
set(_v ${TESSERA_CLI_OUT}/vocabulary)
file(MAKE_DIRECTORY ${_v})
set(_vdata ${PROJECT_SOURCE_DIR}/tests/data/surface)

# _same(NAME FILE_A FILE_B FIXTURES...): FILE_A and FILE_B are byte-identical
function(_same name a b)
  add_test(NAME "cli: vocabulary ${name}" COMMAND ${CMAKE_COMMAND} -E compare_files ${a} ${b})
  set_tests_properties("cli: vocabulary ${name}" PROPERTIES FIXTURES_REQUIRED "${ARGN}")
endfunction()
# _vocab(NAME FIXTURE ARGS...): `tessera ARGS` succeeds; it sets up FIXTURE (or none for "-")
function(_vocab name fixture)
  tessera_cli_test(NAME "cli: vocabulary ${name}" COMMAND ${ARGN})
  if(NOT fixture STREQUAL "-")
    set_tests_properties("cli: vocabulary ${name}" PROPERTIES FIXTURES_SETUP ${fixture})
  endif()
endfunction()
# _refused(NAME CODE REGEX ARGS...): `tessera ARGS` exits with CODE and prints REGEX
function(_refused name code regex)
  tessera_cli_test(NAME "cli: vocabulary ${name}" CODE ${code} REGEX "${regex}" COMMAND ${ARGN})
endfunction()

# --kind KIND, or KIND as the argument; --size N is NxN
_vocab("sample --kind" voc_kind sample --kind dots --size 16x12 --out ${_v}/kind_opt.png)
_vocab("sample KIND" voc_kind sample dots --size 16x12 --out ${_v}/kind_pos.png)
_same("sample KIND = --kind KIND" ${_v}/kind_opt.png ${_v}/kind_pos.png voc_kind)
_vocab("sample --size N" voc_square sample cells --size 16 --out ${_v}/square_n.png)
_vocab("sample --size NxN" voc_square sample cells --size 16x16 --out ${_v}/square_nxn.png)
_same("--size N = --size NxN" ${_v}/square_n.png ${_v}/square_nxn.png voc_square)
_refused("sample KIND and --kind" 2 "'dots' and --kind both give --kind: give one"
         sample dots --kind dots --out ${_v}/never.png)

# --in FILE, or FILE as the argument (info, tones, convert IN OUT = --in IN --out OUT)
tessera_cli_test(NAME "cli: vocabulary info --in" REGEX "size +16 x 12" COMMAND info --in ${_v}/kind_opt.png)
tessera_cli_test(NAME "cli: vocabulary tones --in" REGEX "#[0-9a-f]+" COMMAND tones --in ${_v}/kind_opt.png --max 2)
_vocab("convert --in --out" voc_convert convert --in ${_v}/kind_opt.png --out ${_v}/conv_opt.png --channels 1)
_vocab("convert IN OUT" voc_convert convert ${_v}/kind_opt.png ${_v}/conv_pos.png --channels 1)
set_tests_properties("cli: vocabulary info --in" "cli: vocabulary tones --in" "cli: vocabulary convert --in --out"
                     "cli: vocabulary convert IN OUT" PROPERTIES FIXTURES_REQUIRED voc_kind)
_same("convert IN OUT = --in IN --out OUT" ${_v}/conv_opt.png ${_v}/conv_pos.png voc_convert)
_refused("info FILE and --in" 2 "both give --in" info a.png --in b.png)
_refused("info takes one FILE" 2 "unexpected argument 'b.png'" info a.png b.png)
_refused("info has no --seed" 2 "unknown option --seed" info --seed 3 a.png)

# the registry adds --seed, --threads, --stats and --repeat to every command that does not opt out
tessera_cli_test(NAME "cli: vocabulary shared options in --help"
                 REGEX "--seed S.*--threads T.*--stats.*--repeat N" COMMAND mesh-quilt --help)
tessera_cli_test(NAME "cli: vocabulary a command restates a shared option"
                 REGEX "--seed S +random seed \\(default 1\\); same seed, same image" COMMAND sample --help)
_refused("a bad --threads is refused for every command" 2 "--threads expects an integer, got 'x'"
         render --in x.obj --out x.png --threads x)

# --size: quilt and synth read it with the shared parser, so a missing or bad size is worded as in
# every command (nothing after the option's name; the value checked before any file is read)
foreach(_c quilt synth)
  _refused("${_c} names a missing --size" 1 "tessera ${_c}: invalid_argument: missing required option --size[^ (]"
           ${_c} --exemplar sand --exemplar-size 32 --out ${_v}/never.png)
  _refused("${_c} refuses --size 0x4" 1 "tessera ${_c}: invalid_argument: --size expects positive integers WxH, got '0x4'"
           ${_c} --exemplar ${_v}/nowhere.png --size 0x4 --out ${_v}/never.png)
endforeach()
_refused("sample refuses --size 0x4" 1 "tessera sample: invalid_argument: --size expects positive integers WxH, got '0x4'"
         sample dots --size 0x4 --out ${_v}/never.png)

# meshes: exemplar --size L = LxL; render --tile/--size = --grid/--image-size; mesh-quilt WxH = X,Y;
# polycube --in = --mesh
_vocab("exemplar --size L" voc_ex exemplar rings --size 6.4 --segments 8 --out ${_v}/ex_l.obj)
_vocab("exemplar --size LxL" voc_ex exemplar --kind rings --size 6.4x6.4 --segments 8 --out ${_v}/ex_lxl.obj)
_same("exemplar --size L = LxL" ${_v}/ex_l.obj ${_v}/ex_lxl.obj voc_ex)
_refused("exemplar --size must be square" 1 "--size expects L or LxL with L in \\[0.5, 256\\], got '4x5'"
         exemplar rings --size 4x5 --out ${_v}/never.obj)
_vocab("render --tile --size" voc_render render --in ${_v}/ex_l.obj --out ${_v}/render_new.png --tile 1.5 --size 48x32)
_vocab("render --grid --image-size (aliases)" voc_render
       render ${_v}/ex_l.obj --out ${_v}/render_old.png --grid 1.5 --image-size 48x32)
set_tests_properties("cli: vocabulary render --tile --size" "cli: vocabulary render --grid --image-size (aliases)"
                     PROPERTIES FIXTURES_REQUIRED voc_ex)
_same("render --tile = --grid" ${_v}/render_new.png ${_v}/render_old.png voc_render)
_refused("render names the alias it was given" 1 "--grid expects a finite number, got 'nan'"
         render x.obj --out ${_v}/never.png --grid nan)
_refused("render names the option it was given" 1 "--tile expects a finite number, got 'nan'"
         render x.obj --out ${_v}/never.png --tile nan)
_refused("an option and its alias together" 2 "--tile and --grid are the same option: give one"
         render x.obj --out ${_v}/never.png --tile 1 --grid 1)
_vocab("mesh-quilt --size WxH" voc_mq mesh-quilt --exemplar ${_v}/ex_l.obj --size 6x5 --out ${_v}/mq_new.obj)
_vocab("mesh-quilt --size X,Y (alias)" voc_mq mesh-quilt --exemplar ${_v}/ex_l.obj --size 6,5 --out ${_v}/mq_old.obj)
set_tests_properties("cli: vocabulary mesh-quilt --size WxH" "cli: vocabulary mesh-quilt --size X,Y (alias)"
                     PROPERTIES FIXTURES_REQUIRED voc_ex)
_same("mesh-quilt --size WxH = X,Y" ${_v}/mq_new.obj ${_v}/mq_old.obj voc_mq)
_refused("mesh-quilt --size refuses a negative extent" 1 "--size expects positive numbers WxH, at most 1e\\+06 each, got '-6x5'"
         mesh-quilt --exemplar x.obj --size -6x5 --out ${_v}/never.obj)
_vocab("polycube --in" voc_pc polycube --in ${_vdata}/l_shape.off --tile 0.5 --out ${_v}/pc_new.obj)
_vocab("polycube --mesh (alias)" voc_pc polycube --mesh ${_vdata}/l_shape.off --tile 0.5 --out ${_v}/pc_old.obj)
_same("polycube --in = --mesh" ${_v}/pc_new.obj ${_v}/pc_old.obj voc_pc)

# --colors: the same rule for both Wang commands (0 is refused by both; both also take three counts)
_refused("wang build refuses zero colours" 1 "--colors expects two integers NH,NV or three NX,NY,NZ in \\[1, 4096\\], got '0,2'"
         wang build --exemplar grass --colors 0,2 --out ${_v}/never)
_refused("geo-wang build refuses zero colours" 1 "--colors expects two integers NH,NV or three NX,NY,NZ in \\[1, 4096\\], got '0,2'"
         geo-wang build --exemplar x.obj --colors 0,2 --tile 4 --out ${_v}/never)
_refused("geo-wang build refuses one colour count" 1 "--colors expects two integers NH,NV or three NX,NY,NZ in \\[1, 4096\\], got '2'"
         geo-wang build --exemplar x.obj --colors 2 --tile 4 --out ${_v}/never)

# --coloring: hash by default in both tile commands; the same choices (hash, scanline, periodic)
_vocab("wang build 1,1" voc_wt wang build --exemplar grass --exemplar-size 32 --colors 1,1 --tile 16 --out ${_v}/wt)
tessera_cli_test(NAME "cli: vocabulary wang tile colours by hash by default" REGEX "\"coloring\":\"hash\""
                 COMMAND wang tile --tiles ${_v}/wt --grid 3x2 --seed 5 --out ${_v}/wt_default.png --stats)
tessera_cli_test(NAME "cli: vocabulary wang tile --coloring hash"
                 COMMAND wang tile --tiles ${_v}/wt --grid 3x2 --seed 5 --coloring hash --out ${_v}/wt_hash.png)
set_tests_properties("cli: vocabulary wang tile colours by hash by default" "cli: vocabulary wang tile --coloring hash"
                     PROPERTIES FIXTURES_REQUIRED voc_wt FIXTURES_SETUP voc_wt_tiled)
_same("wang tile default = --coloring hash" ${_v}/wt_default.png ${_v}/wt_hash.png voc_wt_tiled)
_refused("wang tile names the colourings" 1 "--coloring expects hash, scanline or periodic, got 'spiral'"
         wang tile --tiles ${_v}/wt --grid 2x2 --coloring spiral --out ${_v}/never.png)
_refused("geo-wang tile names the colourings" 1 "--coloring expects hash, scanline or periodic, got 'spiral'"
         geo-wang tile --tiles ${_v}/nowhere --grid 2x2 --coloring spiral --out ${_v}/never.obj)
_vocab("geo-wang build 1,1" voc_gt geo-wang build --exemplar ${_v}/ex_l.obj --colors 1,1 --tile 4.8 --out ${_v}/gt)
set_tests_properties("cli: vocabulary geo-wang build 1,1" PROPERTIES FIXTURES_REQUIRED voc_ex)
foreach(_c default hash periodic)
  set(_arg --coloring ${_c})
  if(_c STREQUAL "default")
    set(_arg "")
  endif()
  tessera_cli_test(NAME "cli: vocabulary geo-wang tile ${_c}" REGEX "wrote .*gt_${_c}\\.obj \\(2 x 2 tiles"
                   COMMAND geo-wang tile --tiles ${_v}/gt --grid 2x2 --seed 5 ${_arg} --out ${_v}/gt_${_c}.obj)
  set_tests_properties("cli: vocabulary geo-wang tile ${_c}" PROPERTIES FIXTURES_REQUIRED voc_gt FIXTURES_SETUP voc_gt_tiled)
endforeach()
_same("geo-wang tile default = --coloring hash" ${_v}/gt_default.obj ${_v}/gt_hash.obj voc_gt_tiled)

# --help names an option's older spellings
tessera_cli_test(NAME "cli: vocabulary --help lists the aliases"
                 REGEX "--size WxH .*\\(also --image-size\\).*--tile W .*\\(also --grid\\)" COMMAND render --help)
