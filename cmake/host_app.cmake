# The CTest test_host_app_out_of_tree (c_tests/CMakeLists.txt):
#
#   cmake -DCOP_DIR=<cop> -DWORK=<folder> -P cmake/host_app.cmake
#
# builds the application of README "Your own application on the host" the
# way that section says: the sources of c_tests/host_app are copied into
# WORK/my_app (a project that cop is not a subfolder of), its
# CMakeLists.txt is the first cmake block of that README section, written
# out as it stands; then configure with -DCOP_DIR, build, run. The program
# exits with 0 when its two nodes worked as described.
cmake_minimum_required(VERSION 3.20)
foreach(var COP_DIR WORK)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "host_app.cmake: -D${var}=... missing")
    endif()
endforeach()

file(READ "${COP_DIR}/README.md" readme)
set(heading "## Your own application on the host")
string(FIND "${readme}" "${heading}" at)
if(at EQUAL -1)
    message(FATAL_ERROR "README.md has no section \"${heading}\"")
endif()
string(SUBSTRING "${readme}" ${at} -1 section)
set(open "```cmake\n")
string(FIND "${section}" "${open}" start)
if(start EQUAL -1)
    message(FATAL_ERROR "the README section has no cmake block")
endif()
string(LENGTH "${open}" open_len)
math(EXPR start "${start} + ${open_len}")
string(SUBSTRING "${section}" ${start} -1 block)
string(FIND "${block}" "```" end)
string(SUBSTRING "${block}" 0 ${end} block)

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/my_app")
file(GLOB sources "${COP_DIR}/c_tests/host_app/*")
file(COPY ${sources} DESTINATION "${WORK}/my_app")
file(WRITE "${WORK}/my_app/CMakeLists.txt" "${block}")

function(step what)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
    endif()
    message(STATUS "${what}: ok")
    set(step_output "${out}" PARENT_SCOPE)
endfunction()

step("configure" "${CMAKE_COMMAND}" -S "${WORK}/my_app" -B "${WORK}/build" "-DCOP_DIR=${COP_DIR}")
step("build" "${CMAKE_COMMAND}" --build "${WORK}/build" -j2)
step("run" "${WORK}/build/my_app")
message("${step_output}")
if(NOT step_output MATCHES "ok: the actuator saw the GFC once")
    message(FATAL_ERROR "my_app did not report the GFC")
endif()
