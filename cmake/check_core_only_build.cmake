# Configures roomscout in SOURCE_DIR with ROOMSCOUT_BUILD_SIM=OFF into WORK_DIR, with every
# package past the core's made unfindable (PCL, VTK, yaml-cpp, nlohmann-json, CLI11, MRPT),
# builds the example robot loop on roomscout::core alone, runs it, and checks that the program
# links none of those libraries nor OpenCV's contrib modules.
# cmake -DSOURCE_DIR=... -DWORK_DIR=... -P check_core_only_build.cmake
foreach(v SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "${v} is not set")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})

function(run out_var)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "failed (${result}): ${ARGN}\n${out}\n${err}")
  endif()
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()

set(launcher "")
find_program(ccache ccache)
if(ccache)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${ccache})
endif()
run(out ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR} -DCMAKE_BUILD_TYPE=Release ${launcher}
    -DROOMSCOUT_BUILD_SIM=OFF -DROOMSCOUT_BUILD_TESTS=OFF -DROOMSCOUT_BUILD_BENCHMARKS=OFF
    -DCMAKE_DISABLE_FIND_PACKAGE_PCL=ON -DCMAKE_DISABLE_FIND_PACKAGE_VTK=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_yaml-cpp=ON -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON -DCMAKE_DISABLE_FIND_PACKAGE_mrpt-slam=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON)
run(out ${CMAKE_COMMAND} --build ${WORK_DIR} --parallel 2 --target roomscout_explore_loop)
set(program ${WORK_DIR}/examples/roomscout_explore_loop)
run(out ${program} nearest_frontier)
message("${out}")
run(libraries ldd ${program})
foreach(forbidden pcl vtk yaml-cpp mrpt opencv_ximgproc opencv_imgcodecs)
  if(libraries MATCHES "lib${forbidden}")
    message(FATAL_ERROR "the core-only program links lib${forbidden}:\n${libraries}")
  endif()
endforeach()
message("core alone: built and ran with Eigen and OpenCV core/imgproc only")
