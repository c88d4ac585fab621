# SPDX-License-Identifier: MIT
# The C++ host header (performance/performance.hpp) brings no stage, ECS or scene internals, and
# no glm, into a host's code: the headers a translation unit including only it reads, listed by
# the compiler (-M), name none of them.
#   cmake -DCXX=compiler -DINCLUDE_ROOT=dir -P host_header_check.cmake
execute_process(
  COMMAND ${CXX} -std=c++20 -M -I${INCLUDE_ROOT} -x c++ ${INCLUDE_ROOT}/tutti/performance/performance.hpp
  OUTPUT_VARIABLE deps ERROR_VARIABLE errors RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "performance.hpp does not compile alone: ${errors}")
endif()
string(REGEX MATCHALL "[^ \\\\\n]+\\.(hpp|h|inl)" headers "${deps}")
set(internal "")
foreach(header IN LISTS headers)
  if(header MATCHES "/tutti/(stage|ecs|scene|components|render|model|humanoid|runtime)/" OR
     header MATCHES "/glm/")
    list(APPEND internal ${header})
  endif()
endforeach()
list(LENGTH headers count)
if(internal)
  list(JOIN internal "\n  " listed)
  message(FATAL_ERROR "performance.hpp pulls in internals:\n  ${listed}")
endif()
message(STATUS "performance.hpp reads ${count} headers, none of stage, ECS, scene or glm")
