# Drives the snell CLI: bad arguments exit 2 with one line naming the argument; each built-in
# scene renders to a PNG of the requested size with validation on and no validation error.
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

# Rendering: each built-in scene, with validation, to the requested size.
foreach(scene pool window spheres)
  set(png "${WORK_DIR}/${scene}.png")
  expect_exit(0 render --scene ${scene} --size 160x90 --out ${png} --validation --debug-targets)
  file(READ "${png}" header LIMIT 24 HEX)
  # PNG signature, then the IHDR chunk: width and height as big-endian 32-bit at offset 16.
  string(SUBSTRING "${header}" 0 16 signature)
  string(SUBSTRING "${header}" 32 8 width)
  string(SUBSTRING "${header}" 40 8 height)
  if(NOT signature STREQUAL "89504e470d0a1a0a" OR NOT width STREQUAL "000000a0"
     OR NOT height STREQUAL "0000005a")
    message(FATAL_ERROR "${png}: not a 160x90 PNG (header ${header})")
  endif()
endforeach()
# The sample glTF asset (hierarchy, negative scale, generated normals, camera, light) renders.
expect_exit(0 render --scene "${ASSET_DIR}/courtyard.gltf" --size 160x90
            --out "${WORK_DIR}/courtyard.png" --validation)
if(NOT EXISTS "${WORK_DIR}/courtyard.png")
  message(FATAL_ERROR "courtyard.gltf rendered no PNG")
endif()
# A missing glTF file is an error naming it (exit 1: a failure, not a usage error).
expect_exit(1 render --scene "${WORK_DIR}/missing.gltf" --out "${WORK_DIR}/m.png")
string(FIND "${last_err}" "missing.gltf" found)
if(found EQUAL -1)
  message(FATAL_ERROR "missing glTF: message does not name the file:\n${last_err}")
endif()
message(STATUS "snell CLI: arguments and renders OK")
