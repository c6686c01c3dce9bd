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
message(STATUS "snell CLI: arguments and renders OK")
