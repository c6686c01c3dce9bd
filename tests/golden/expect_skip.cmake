# Runs one golden test with every Vulkan driver hidden (VK_DRIVER_FILES / VK_ICD_FILENAMES name a
# file that does not exist, so lavapipe is absent): it must succeed, print the SNELL_SKIP reason
# (which CTest turns into "skipped") and never reach REQUIRE(ctx).
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env VK_DRIVER_FILES=/nonexistent/snell-no-driver.json
          VK_ICD_FILENAMES=/nonexistent/snell-no-driver.json SNELL_VALIDATION=1
          "${GOLDEN}" "--test-case=golden: pool"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${out}${err}" "SNELL_SKIP: golden images need Mesa lavapipe" skip)
string(FIND "${out}${err}" "lavapipe" named)
if(NOT rc EQUAL 0 OR skip EQUAL -1)
  message(FATAL_ERROR "golden test without lavapipe: exit ${rc}, expected 0 with a SNELL_SKIP "
                      "reason:\n${out}\n${err}")
endif()
message(STATUS "golden tests skip without lavapipe:\n${out}")
