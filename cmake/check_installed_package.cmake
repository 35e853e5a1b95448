# Installs the build tree BUILD_DIR into WORK_DIR/prefix, builds the examples in SOURCE_DIR as
# a separate project with find_package(roomscout) against it, and runs the program. Then
# compiles one file that includes every installed header against the installed targets, so a
# public header that includes an internal (uninstalled) one fails here.
# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -P check_installed_package.cmake
include(${CMAKE_CURRENT_LIST_DIR}/check_script_common.cmake)

run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/roomscout_explore_loop nearest_frontier)

file(GLOB_RECURSE headers RELATIVE ${WORK_DIR}/prefix/include ${WORK_DIR}/prefix/include/roomscout/*.hpp)
if(NOT headers)
  message(FATAL_ERROR "no header installed under ${WORK_DIR}/prefix/include/roomscout")
endif()
file(GLOB_RECURSE internal ${WORK_DIR}/prefix/include/roomscout/*/detail/*)
if(internal)
  message(FATAL_ERROR "internal headers were installed: ${internal}")
endif()
set(all_cpp "")
foreach(h IN LISTS headers)
  string(APPEND all_cpp "#include \"${h}\"\n")
endforeach()
file(WRITE ${WORK_DIR}/headers/all_headers.cpp "${all_cpp}int main() { return 0; }\n")
file(WRITE ${WORK_DIR}/headers/CMakeLists.txt [=[
cmake_minimum_required(VERSION 3.22)
project(roomscout_installed_headers LANGUAGES C CXX)
set(CMAKE_CXX_STANDARD 20)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
find_package(roomscout REQUIRED)
add_executable(all_headers all_headers.cpp)
target_link_libraries(all_headers PRIVATE roomscout::core)
foreach(t io slam sim plots)
  if(TARGET roomscout::${t})
    target_link_libraries(all_headers PRIVATE roomscout::${t})
  endif()
endforeach()
]=])
run(${CMAKE_COMMAND} -S ${WORK_DIR}/headers -B ${WORK_DIR}/headers/build -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/headers/build)
list(LENGTH headers header_count)
message("done: ${header_count} installed headers compile together")
