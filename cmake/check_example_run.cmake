# Runs the explore-loop example (PROGRAM, with METHOD) and fails unless it ends by itself with
# exit code 0 and a map that knows at least MIN_PERCENT of its floor plan: an Explorer that
# said "done" at once, or never, fails.
foreach(v PROGRAM METHOD MIN_PERCENT)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "${v} is not set")
  endif()
endforeach()
execute_process(COMMAND ${PROGRAM} ${METHOD} RESULT_VARIABLE result OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
message("${out}${err}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} ${METHOD} exited with ${result}")
endif()
if(NOT out MATCHES "done: ([0-9.]+) % of the floor plan known")
  message(FATAL_ERROR "no \"done: N % of the floor plan known\" line")
endif()
if(CMAKE_MATCH_1 LESS MIN_PERCENT)
  message(FATAL_ERROR "only ${CMAKE_MATCH_1} % of the floor plan known, below ${MIN_PERCENT} %")
endif()
message("explored ${CMAKE_MATCH_1} % of the floor plan")
