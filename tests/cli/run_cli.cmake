# Drives the snell CLI: bad arguments exit 2 with one line naming the argument; each built-in
# scene renders to a PNG of the requested size with validation on and no validation error.
include("${CMAKE_CURRENT_LIST_DIR}/../cmake/expect_png.cmake")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function(expect_exit code)
  execute_process(COMMAND "${SNELL}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL code)
    message(FATAL_ERROR "snell ${ARGN}: exit ${rc}, expected ${code}\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  set(last_out "${out}" PARENT_SCOPE)
  set(last_err "${err}" PARENT_SCOPE)
endfunction()

expect_exit(0 --help)
string(FIND "${last_out}" "usage:" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "--help prints no usage")
endif()

# Bad arguments: exit code 2 and exactly one line on stderr that names the culprit.
foreach(case
    "--size;0x10;--out;x.png|--size width"
    "--size;12;--out;x.png|--size"
    "--eye;1,2;--out;x.png|--eye"
    "--fov;200;--out;x.png|--fov"
    "--near;5;--far;1;--out;x.png|--near"
    "--frames;0;--out;x.png|--frames"
    "--time;nan;--out;x.png|--time"
    "--bogus;1|--bogus"
    "--scene;nope;--out;x.png|nope")
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts -1 needle)
  list(REMOVE_AT parts -1)
  expect_exit(2 render ${parts})
  string(STRIP "${last_err}" err)
  string(FIND "${err}" "\n" newline)
  string(FIND "${err}" "${needle}" found)
  if(NOT newline EQUAL -1 OR found EQUAL -1)
    message(FATAL_ERROR "render ${parts}: expected one line naming '${needle}', got:\n${last_err}")
  endif()
endforeach()
expect_exit(2 frobnicate)
# Effect arguments: unknown effect, unknown key (lists the valid keys), bad value (names the
# range), --set for an effect that is not enabled.
expect_exit(2 render --effect lava --out x.png)
string(FIND "${last_err}" "water" found)
if(found EQUAL -1)
  message(FATAL_ERROR "unknown effect: registered effects not listed:\n${last_err}")
endif()
expect_exit(2 render --effect water --set water.wave_hieght=1 --out x.png)
string(FIND "${last_err}" "wave_height" found)
if(found EQUAL -1)
  message(FATAL_ERROR "unknown key: valid keys not listed:\n${last_err}")
endif()
expect_exit(2 render --effect water --set water.ior=9 --out x.png)
string(FIND "${last_err}" "[1, 3]" found)
if(found EQUAL -1)
  message(FATAL_ERROR "out-of-range value: range not named:\n${last_err}")
endif()
expect_exit(2 render --set water.ior=1.2 --out x.png)
expect_exit(2 render --effect water --set water.center=1 --out x.png)

# snell list prints every parameter of every effect.
expect_exit(0 list)
foreach(key preset height center size resolution_scale refraction_source clip_mode clip_offset wave_length
        wave_height distortion wind_direction wind_force fresnel ior reflectance water_color color_blend
        specular_power specular_intensity absorption shore_softness reflection_layers
        refraction_layers debug_view normal_map)
  string(FIND "${last_out}" "  ${key} " found)
  if(found EQUAL -1)
    message(FATAL_ERROR "snell list lacks water.${key}:\n${last_out}")
  endif()
endforeach()

# Rendering: each built-in scene, with validation, to the requested size.
foreach(scene pool window spheres)
  set(png "${WORK_DIR}/${scene}.png")
  expect_exit(0 render --scene ${scene} --size 160x90 --out ${png} --validation --debug-targets)
  expect_png("${png}" 160 90)
endforeach()
# The sample glTF asset (hierarchy, negative scale, generated normals, camera, light) renders.
expect_exit(0 render --scene "${ASSET_DIR}/courtyard.gltf" --size 160x90
            --out "${WORK_DIR}/courtyard.png" --validation)
expect_png("${WORK_DIR}/courtyard.png" 160 90)
# Water on a glTF scene, placed with --set; and the bench JSON.
expect_exit(0 render --scene "${ASSET_DIR}/courtyard.gltf" --effect water --set water.height=0.05
            --set water.center=0,0 --set water.size=6,6 --size 160x90
            --out "${WORK_DIR}/courtyard_water.png" --validation)
expect_exit(0 bench --scene pool --effect water --size 96x54 --frames 3
            --json "${WORK_DIR}/bench.json" --validation)
file(READ "${WORK_DIR}/bench.json" bench)
# The frame phases and water's one extra scene pass (refraction comes from the snapshot).
foreach(field plain_ms effect_ms ratio passes device opaque snapshot surfaces water.reflection)
  string(FIND "${bench}" "\"${field}\"" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "bench JSON lacks '${field}':\n${bench}")
  endif()
endforeach()
# A missing glTF file is an error naming it (exit 1: a failure, not a usage error).
expect_exit(1 render --scene "${WORK_DIR}/missing.gltf" --out "${WORK_DIR}/m.png")
string(FIND "${last_err}" "missing.gltf" found)
if(found EQUAL -1)
  message(FATAL_ERROR "missing glTF: message does not name the file:\n${last_err}")
endif()

# --- Refusals say what, where and why (issue 10) ------------------------------------------------
# expect_refusal(<exit code> NEEDLES <text>... ARGS <argument>...): exactly one line on stderr,
# containing every needle; nothing on stdout (refused before any work is reported).
function(expect_refusal code)
  cmake_parse_arguments(R "" "" "NEEDLES;ARGS" ${ARGN})
  expect_exit(${code} ${R_ARGS})
  string(STRIP "${last_err}" err)
  string(FIND "${err}" "\n" newline)
  if(NOT newline EQUAL -1)
    message(FATAL_ERROR "snell ${R_ARGS}: more than one line on stderr:\n${last_err}")
  endif()
  foreach(needle IN LISTS R_NEEDLES)
    string(FIND "${err}" "${needle}" found)
    if(found EQUAL -1)
      message(FATAL_ERROR "snell ${R_ARGS}: stderr does not name '${needle}':\n${last_err}")
    endif()
  endforeach()
  if(NOT last_out STREQUAL "")
    message(FATAL_ERROR "snell ${R_ARGS}: refused, yet printed on stdout:\n${last_out}")
  endif()
endfunction()

file(MAKE_DIRECTORY "${WORK_DIR}/a_folder" "${WORK_DIR}/folder.gltf")
# A folder where a file is expected: output, texture, scene.
expect_refusal(1 NEEDLES "${WORK_DIR}/a_folder" "is a folder"
               ARGS render --size 32x32 --out "${WORK_DIR}/a_folder")
expect_refusal(1 NEEDLES "${WORK_DIR}/missing_folder" "does not exist"
               ARGS render --size 32x32 --out "${WORK_DIR}/missing_folder/x.png")
expect_refusal(1 NEEDLES "--json" "is a folder" "${WORK_DIR}/a_folder"
               ARGS bench --size 32x32 --frames 3 --json "${WORK_DIR}/a_folder")
expect_refusal(2 NEEDLES "water.normal_map" "${WORK_DIR}/a_folder" "is a folder"
               ARGS render --size 32x32 --effect water --set "water.normal_map=${WORK_DIR}/a_folder"
                    --out "${WORK_DIR}/t.png")
expect_refusal(2 NEEDLES "glass.color_texture" "is a folder"
               ARGS render --size 32x32 --effect glass
                    --set "glass.color_texture=${WORK_DIR}/a_folder" --out "${WORK_DIR}/t.png")
expect_refusal(1 NEEDLES "--scene" "folder.gltf" "is a folder"
               ARGS render --size 32x32 --scene "${WORK_DIR}/folder.gltf" --out "${WORK_DIR}/t.png")
expect_refusal(1 NEEDLES "--scene" "is a folder" "pool, window, spheres"
               ARGS render --size 32x32 --scene "${WORK_DIR}/a_folder" --out "${WORK_DIR}/t.png")
# A PNG whose header claims 60000x60000 (tests/cli/huge_header.png: 69 bytes): the size and the
# limit, not stb_image's "unknown image type".
expect_refusal(2 NEEDLES "water.normal_map" "huge_header.png" "60000x60000" "1..16384"
               ARGS render --size 32x32 --effect water
                    --set "water.normal_map=${CLI_DIR}/huge_header.png" --out "${WORK_DIR}/t.png")
# Values named: what, which flag, the valid range.
expect_refusal(2 NEEDLES "--near 5" "--far 1" ARGS render --near 5 --far 1 --out x.png)
expect_refusal(2 NEEDLES "--eye and --target" "1,2,3" ARGS render --eye 1,2,3 --target 1,2,3 --out x.png)
expect_refusal(2 NEEDLES "--frames 2" "3..100000" ARGS bench --frames 2)
expect_refusal(2 NEEDLES "--json" "bench" ARGS render --json x.json --out x.png)
expect_refusal(2 NEEDLES "--scene" "nope" "pool, window, spheres" ".gltf/.glb"
               ARGS render --scene nope --out x.png)

# --- Output files are never half-written and never falsely reported -----------------------------
if(EXISTS /dev/full)
  expect_refusal(1 NEEDLES "/dev/full" "No space left on device"
                 ARGS render --size 64x64 --out /dev/full)
  expect_exit(1 bench --size 32x32 --frames 3 --json /dev/full)
  foreach(needle "/dev/full" "No space left on device")
    string(FIND "${last_err}" "${needle}" found)
    if(found EQUAL -1)
      message(FATAL_ERROR "bench --json /dev/full: stderr does not name '${needle}':\n${last_err}")
    endif()
  endforeach()
  string(FIND "${last_out}" "wrote" found)
  if(NOT found EQUAL -1)
    message(FATAL_ERROR "bench --json /dev/full: reported as written:\n${last_out}")
  endif()
endif()
# An existing output survives a failed run: a bad parameter, a failed load, a failed write.
set(keep "${WORK_DIR}/keep.png")
file(COPY_FILE "${WORK_DIR}/pool.png" "${keep}")
file(SHA256 "${keep}" keep_hash)
expect_exit(2 render --effect water --set water.ior=9 --out "${keep}")
expect_exit(1 render --scene "${WORK_DIR}/missing.gltf" --out "${keep}")
# A write that fails part-way: a file-size limit of 8 KiB (SIGXFSZ ignored, so write() fails
# with EFBIG, "File too large"); the 320x180 image is larger.
find_program(BASH bash)
if(BASH)
  execute_process(COMMAND "${BASH}" -c "trap '' XFSZ; ulimit -f 8; exec \"$0\" \"$@\"" "${SNELL}"
                          render --size 320x180 --out "${keep}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${err}" "keep.png" named)
  string(FIND "${err}" "File too large" why)
  if(NOT rc EQUAL 1 OR named EQUAL -1 OR why EQUAL -1)
    message(FATAL_ERROR "a failed write: exit ${rc} (expected 1), stderr:\n${err}\nstdout:\n${out}")
  endif()
endif()
file(SHA256 "${keep}" after_hash)
if(NOT after_hash STREQUAL keep_hash)
  message(FATAL_ERROR "${keep} changed although every run that targeted it failed")
endif()
# Nothing beside the outputs: no temporary file left by a successful or a failed write.
file(GLOB entries LIST_DIRECTORIES true RELATIVE "${WORK_DIR}" "${WORK_DIR}/*" "${WORK_DIR}/.*")
foreach(entry IN LISTS entries)
  if(entry MATCHES "snell-tmp" OR entry MATCHES "^\\.")
    message(FATAL_ERROR "stray file left in ${WORK_DIR}: ${entry}\n(all: ${entries})")
  endif()
endforeach()

# --- Progress: one updating line on a terminal, nothing when piped ------------------------------
# A render of about 3 to 5 s on lavapipe (over the 2 s after which progress shows).
set(long_render render --size 1280x720 --effect water --frames 60 --out "${WORK_DIR}/long.png")
expect_exit(0 ${long_render})
if(NOT last_err STREQUAL "")
  message(FATAL_ERROR "a piped render printed on stderr (progress must stay off):\n${last_err}")
endif()
# On a terminal (a pseudo-terminal from util-linux `script`; TERM set, as TERM=dumb turns it
# off): "snell: frame i/60" lines redrawn with a carriage return, erased before the report.
find_program(SCRIPT script)
if(SCRIPT)
  string(REPLACE ";" " " long_line "${long_render}")
  execute_process(COMMAND "${CMAKE_COMMAND}" -E env TERM=xterm "${SCRIPT}" -qefc "'${SNELL}' ${long_line}" /dev/null
                  INPUT_FILE /dev/null RESULT_VARIABLE rc OUTPUT_VARIABLE tty_out
                  ERROR_VARIABLE tty_err)
  string(FIND "${tty_out}" "\rsnell: frame " progress)
  string(FIND "${tty_out}" "/60" total)
  string(ASCII 27 esc)
  string(FIND "${tty_out}" "\r${esc}[Kscene pool" erased)
  if(NOT rc EQUAL 0 OR progress EQUAL -1 OR total EQUAL -1 OR erased EQUAL -1)
    message(FATAL_ERROR "no progress line on a terminal (exit ${rc}):\n${tty_out}\n${tty_err}")
  endif()
else()
  message(STATUS "util-linux script not found: progress on a terminal not checked")
endif()

message(STATUS "snell CLI: arguments and renders OK")

# --- The mirror from a glTF node (issue 13) ------------------------------------------------------
# samples/assets/mirror_hall.gltf (scripts/make_mirror_hall.py): "Mirror" is a flat quad, "Bent"
# two quads at 30 degrees. The first renders; the second is refused naming the node and how far
# it is off its plane; an unknown node is refused naming it.
expect_exit(0 render --scene "${ASSET_DIR}/mirror_hall.gltf" --effect mirror
            --set mirror.node=Mirror --size 160x90 --out "${WORK_DIR}/mirror_hall.png" --validation)
expect_png("${WORK_DIR}/mirror_hall.png" 160 90)
expect_refusal(2 NEEDLES "mirror.node" "'Bent'" "not planar" "off its best plane"
               ARGS render --scene "${ASSET_DIR}/mirror_hall.gltf" --effect mirror
                    --set mirror.node=Bent --size 32x32 --out "${WORK_DIR}/t.png")
expect_refusal(2 NEEDLES "mirror.node" "'Nowhere'"
               ARGS render --scene "${ASSET_DIR}/mirror_hall.gltf" --effect mirror
                    --set mirror.node=Nowhere --size 32x32 --out "${WORK_DIR}/t.png")
