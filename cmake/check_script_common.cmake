# Shared by the cmake -P check scripts: each needs BUILD_DIR, SOURCE_DIR and WORK_DIR, starts
# from an empty WORK_DIR, and runs commands that must succeed.
foreach(v BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "${v} is not set")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})

# Runs a command, prints its output and stops the script when it fails; sets run_output to
# what it printed.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "failed (${result}): ${ARGN}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()
