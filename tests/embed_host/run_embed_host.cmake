# Drives snell-embed-host: bad arguments exit 2 with one line on stderr; a render with
# validation and --check (the water changes the pixel where its centre projects, the sky stays
# unchanged, the chrome ball shows the colour its probe's capture predicts) exits 0 and writes a
# PNG of the requested size.
include("${CMAKE_CURRENT_LIST_DIR}/../cmake/expect_png.cmake")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function(expect_exit code)
  execute_process(COMMAND "${EMBED_HOST}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL code)
    message(FATAL_ERROR
            "snell-embed-host ${ARGN}: exit ${rc}, expected ${code}\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  set(last_out "${out}" PARENT_SCOPE)
  set(last_err "${err}" PARENT_SCOPE)
endfunction()

# Bad arguments: exit 2, exactly one line on stderr naming the culprit, no GPU work.
foreach(case
    "--size;320x0;--out;x.png|--size"
    "--size;wide;--out;x.png|--size"
    "--frames;0;--out;x.png|--frames"
    "--size;320x180|--out"
    "--out;x.png;--bogus|--bogus")
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts -1 needle)
  list(REMOVE_AT parts -1)
  expect_exit(2 ${parts})
  string(STRIP "${last_err}" err)
  string(FIND "${err}" "\n" newline)
  string(FIND "${err}" "${needle}" found)
  if(NOT newline EQUAL -1 OR found EQUAL -1)
    message(FATAL_ERROR "${parts}: expected one line naming '${needle}', got:\n${last_err}")
  endif()
endforeach()

# Render two frames (the second reuses the effects' targets and the chrome material's descriptor
# set) with validation and the check.
set(png "${WORK_DIR}/embed.png")
expect_exit(0 --out "${png}" --size 320x180 --frames 2 --validation --check)
message(STATUS "snell-embed-host:\n${last_out}")
string(FIND "${last_out}" "check: passed" passed)
if(passed EQUAL -1)
  message(FATAL_ERROR "--check did not report 'check: passed':\n${last_out}")
endif()
expect_png("${png}" 320 180)
message(STATUS "snell-embed-host: arguments, render, check and PNG OK")
