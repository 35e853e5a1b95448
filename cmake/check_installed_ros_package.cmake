# Installs the build tree BUILD_DIR into a prefix under WORK_DIR, then configures and builds the ROS
# nodes in SOURCE_DIR (ros/) as a separate project with find_package(roomscout) against it,
# so a node that needs an uninstalled header or library fails here, and installs them. Both
# installs must write into their prefix only.
# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... [-DPYTHON_EXECUTABLE=...]
#       [-DC_COMPILER=... -DCXX_COMPILER=...] -P check_installed_ros_package.cmake
include(${CMAKE_CURRENT_LIST_DIR}/check_script_common.cmake)

# Installs build tree `build` under WORK_DIR/dest with prefix /`name`, and sets `name`_prefix
# to where it went. DESTDIR keeps a file installed to an absolute path inside WORK_DIR too;
# every file must go under the prefix.
function(install_into build name)
  set(dest ${WORK_DIR}/dest)
  run(${CMAKE_COMMAND} -E env DESTDIR=${dest} ${CMAKE_COMMAND} --install ${build} --prefix /${name})
  string(REGEX MATCHALL "-- (Installing|Up-to-date): [^\n]*" lines "${run_output}")
  if(NOT lines)
    message(FATAL_ERROR "nothing installed from ${build}")
  endif()
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^-- [A-Za-z-]+: " "" path "${line}")
    string(FIND "${path}" "${dest}/${name}/" at)
    if(NOT at EQUAL 0)
      message(FATAL_ERROR "installing ${build} into prefix /${name} wrote ${path}")
    endif()
  endforeach()
  set(${name}_prefix ${dest}/${name} PARENT_SCOPE)
endfunction()

install_into(${BUILD_DIR} roomscout)
set(prefix ${roomscout_prefix})
set(options -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix})
if(PYTHON_EXECUTABLE)
  list(APPEND options -DPYTHON_EXECUTABLE=${PYTHON_EXECUTABLE})
endif()
if(C_COMPILER AND CXX_COMPILER)
  list(APPEND options -DCMAKE_C_COMPILER=${C_COMPILER} -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build ${options})

# The nodes must have found the installed package, not another roomscout on the machine.
file(STRINGS ${WORK_DIR}/build/CMakeCache.txt found REGEX "^roomscout_DIR:")
string(FIND "${found}" "roomscout_DIR:PATH=${prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "the nodes were configured against another roomscout: ${found}")
endif()
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
install_into(${WORK_DIR}/build ros)
foreach(f lib/roomscout/roomscout_explore_node lib/roomscout/roomscout_sim_node
          share/roomscout/package.xml share/roomscout/launch/sim_explore.launch)
  if(NOT EXISTS ${ros_prefix}/${f})
    message(FATAL_ERROR "not installed: ${ros_prefix}/${f}")
  endif()
endforeach()
message("done: the ROS nodes built and installed against the installed roomscout")
